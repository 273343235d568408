#include "mpm/materials/element_test.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pilempm::mpm {

ElementTest::ElementTest(const ConstitutiveModel& model, const double* stress0, const std::vector<double>& state0)
    : model_(model), state_(state0) {
    std::copy(stress0, stress0 + 6, stress_);
    if (static_cast<int>(state_.size()) < model.num_state()) state_.resize(model.num_state(), 0.0);
}

void ElementTest::step(const double* de, double* stress, std::vector<double>& state) const {
    const int point = 0;
    model_.update(1, &point, de, stress, state.data(), static_cast<int>(state.size()));
}

ElementRecord ElementTest::record() const {
    ElementRecord r;
    r.axial_strain = -strain_[2];
    r.volumetric_strain = -(strain_[0] + strain_[1] + strain_[2]);
    r.axial_stress = -stress_[2];
    r.lateral_stress = -0.5 * (stress_[0] + stress_[1]);
    r.p = (r.axial_stress + 2.0 * r.lateral_stress) / 3.0;
    r.q = r.axial_stress - r.lateral_stress;
    r.state = state_;
    return r;
}

// Unknowns: the axial and lateral strain increments (tension positive). Each leg fixes one
// equation per direction; the stress-controlled ones are solved with a secant-free Newton
// iteration on the model's response from the state at the start of the step.
void ElementTest::run(const ElementLeg& leg, std::vector<ElementRecord>& out) {
    if (leg.steps < 1) throw std::invalid_argument("an element-test leg needs at least one step");
    const double r0 = -0.5 * (stress_[0] + stress_[1]);
    const double a0 = leg.axial == ElementLeg::AxialStrain   ? -strain_[2]
                      : leg.axial == ElementLeg::AxialStress ? -stress_[2]
                                                             : -stress_[2] - r0;
    const double scale = std::max({std::abs(stress_[0]), std::abs(stress_[1]), std::abs(stress_[2]), 1e3});
    double guess[2] = {0.0, 0.0};  // last step's strain increments: the next step's start
    for (int n = 1; n <= leg.steps; ++n) {
        const double target = a0 + (leg.axial_target - a0) * n / leg.steps;  // compression +
        auto residual = [&](const double* x, double* r, double* s_out, std::vector<double>& st_out) {
            double de[6] = {x[1], x[1], x[0], 0, 0, 0};
            double s[6];
            std::copy(stress_, stress_ + 6, s);
            st_out = state_;
            step(de, s, st_out);
            const double axial = -s[2], lateral = -0.5 * (s[0] + s[1]);
            switch (leg.axial) {
                case ElementLeg::AxialStrain: r[0] = (-(strain_[2] + x[0]) - target) / 1e-3; break;
                case ElementLeg::AxialStress: r[0] = (axial - target) / scale; break;
                case ElementLeg::Deviator: r[0] = (axial - lateral - target) / scale; break;
            }
            switch (leg.lateral) {
                case ElementLeg::LateralStress: r[1] = (lateral - r0) / scale; break;
                case ElementLeg::LateralStrainZero: r[1] = x[1] / 1e-3; break;
                case ElementLeg::Undrained: r[1] = (x[1] + 0.5 * x[0]) / 1e-3; break;
                case ElementLeg::LateralStressEqualsAxial: r[1] = (lateral - axial) / scale; break;
            }
            if (s_out) std::copy(s, s + 6, s_out);
        };
        double x[2] = {guess[0], guess[1]}, r[2] = {0.0, 0.0}, s[6];
        std::vector<double> st;
        // Substepped models answer with a noise of about their integration tolerance, so
        // Newton may stall a little above 1e-10: the best iterate below 1e-7 is accepted.
        bool converged = false;
        double best = HUGE_VAL, best_x[2] = {x[0], x[1]};
        for (int it = 0; it < 30; ++it) {
            residual(x, r, s, st);
            const double size = std::max(std::abs(r[0]), std::abs(r[1]));
            if (size < best) {
                best = size;
                best_x[0] = x[0];
                best_x[1] = x[1];
            }
            if (size < 1e-10) {
                converged = true;
                break;
            }
            // Central-difference Jacobian: the model is a black box here, and central
            // differences average a kink at the solution (e.g. a shear surface that is a
            // cone about the current isotropic stress) instead of taking one side of it.
            double J[2][2], rp[2] = {0.0, 0.0}, rm[2] = {0.0, 0.0};
            std::vector<double> scratch;
            for (int j = 0; j < 2; ++j) {
                double xp[2] = {x[0], x[1]}, xm[2] = {x[0], x[1]};
                const double h = 1e-8 + 1e-6 * std::abs(x[j]);
                xp[j] += h;
                xm[j] -= h;
                residual(xp, rp, nullptr, scratch);
                residual(xm, rm, nullptr, scratch);
                J[0][j] = (rp[0] - rm[0]) / (2.0 * h);
                J[1][j] = (rp[1] - rm[1]) / (2.0 * h);
            }
            const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
            if (!(std::abs(det) > 0.0)) break;
            const double dx[2] = {(J[1][1] * r[0] - J[0][1] * r[1]) / det, (-J[1][0] * r[0] + J[0][0] * r[1]) / det};
            // Backtracking: a model whose response has a vertex at the solution (a cone-shaped
            // yield surface about the current stress) can make full steps jump across it.
            const double r_norm = std::max(std::abs(r[0]), std::abs(r[1]));
            double step = 1.0;
            for (int ls = 0; ls < 12; ++ls) {
                const double xt[2] = {x[0] - step * dx[0], x[1] - step * dx[1]};
                double rt[2] = {0.0, 0.0};
                residual(xt, rt, nullptr, scratch);
                if (std::max(std::abs(rt[0]), std::abs(rt[1])) < r_norm) break;
                step *= 0.5;
            }
            x[0] -= step * dx[0];
            x[1] -= step * dx[1];
        }
        if (!converged && best < 1e-7) {
            x[0] = best_x[0];
            x[1] = best_x[1];
            residual(x, r, s, st);
            converged = true;
        }
        if (!converged) throw std::runtime_error("element test: the mixed-control step " + std::to_string(n) +
                                                 " did not converge (the material cannot follow this path)");
        std::copy(s, s + 6, stress_);
        state_ = st;
        strain_[0] += x[1];
        strain_[1] += x[1];
        strain_[2] += x[0];
        guess[0] = x[0];
        guess[1] = x[1];
        out.push_back(record());
    }
}

}  // namespace pilempm::mpm
