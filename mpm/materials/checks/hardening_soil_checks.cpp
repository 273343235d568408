// Hardening soil small: the small-strain secant curve, E50 and the Mohr-Coulomb failure
// deviator in drained triaxial compression (issue 5, verification 2).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "mpm/materials/checks/element_test_checks.hpp"

namespace pilempm::mpm {


namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// The HS stiffness factor ((c cos phi + sigma'_3 sin phi) / (c cos phi + p_ref sin phi))^m
// with the model's floor (sigma'_3 + c cot phi >= min_pressure).
double stiffness_factor(const MaterialParameters& m, double sigma3) {
    const double a = m.cohesion / std::tan(m.friction_angle * kDeg);
    return std::pow(std::max(sigma3 + a, m.min_pressure) / (m.reference_pressure + a), m.stiffness_exponent);
}

// A drained triaxial test whose legs go one way (monotonic) or turn back after the first.
const TestResult& drained_test(const ElementTestContext& ctx, bool reversing, const std::string& check) {
    for (const auto& r : ctx.results) {
        if (r.input->type != "triaxial_drained") continue;
        const auto& legs = r.input->legs;
        const bool turns = legs.size() >= 2 && legs[1].axial_target < legs[0].axial_target && legs[0].axial_target > 0.0;
        if (reversing ? turns : (legs.size() == 1 && legs[0].axial_target > 0.0)) return r;
    }
    throw std::invalid_argument(check + (reversing ? " needs a triaxial_drained test that loads then unloads (path: [e1, e2 < e1])"
                                                   : " needs a triaxial_drained test with one compression leg"));
}

}  // namespace

// Unloading after primary loading is elastic. From the reversal, with Benz's shear strain
// gamma = (3/2) eps_q = eps_a - eps_r and the secant G_s = dq / (2 gamma):
//   G_s / G0 = 1 / (1 + 0.385 gamma / gamma_0.7) while the tangent exceeds G_ur, then the
// tangent stays at G_ur = E_ur / (2 (1 + nu_ur)). G0 is taken at sigma'_3 of the reversal.
std::vector<VerificationCheck> small_strain_stiffness_decay(const ElementTestContext& ctx) {
    ctx.require_model("hardening_soil_small", "small_strain_stiffness_decay");
    const auto& m = ctx.c.material;
    const auto& r = drained_test(ctx, true, "small_strain_stiffness_decay");
    const std::size_t rev = static_cast<std::size_t>(r.input->legs[0].steps);
    const auto& p0 = r.path[rev];
    const double w = stiffness_factor(m, p0.lateral_stress);
    const double G0 = m.g0_ref * w, Gur = m.eur_ref / (2.0 * (1.0 + m.poisson_ratio)) * w, g07 = m.gamma_07;
    const double gc = g07 / 0.385 * (std::sqrt(G0 / Gur) - 1.0);  // tangent = G_ur here
    auto gamma = [](const ElementRecord& x) { return 1.5 * x.axial_strain - 0.5 * x.volumetric_strain; };
    double worst_curve = 0.0, worst_floor = 0.0, reached = 0.0;
    const std::size_t end = rev + static_cast<std::size_t>(r.input->legs[1].steps);
    for (std::size_t k = rev + 1; k <= end && k < r.path.size(); ++k) {
        const double g = gamma(p0) - gamma(r.path[k]);
        if (!(g > 0.0)) continue;
        const double Gs = (p0.q - r.path[k].q) / (2.0 * g);
        reached = std::max(reached, g);
        if (g <= gc) {
            worst_curve = std::max(worst_curve, std::abs(Gs / (G0 / (1.0 + 0.385 * g / g07)) - 1.0));
        } else {
            const double ref = (G0 * gc / (1.0 + 0.385 * gc / g07) + Gur * (g - gc)) / g;
            worst_floor = std::max(worst_floor, std::abs(Gs / ref - 1.0));
        }
    }
    VerificationCheck cover = make_check("unloading_reaches_G_ur_shear_strain", reached, gc, 0.0, true,
                                         "the unloading branch reaches gamma where G_t = G_ur");
    cover.at_least = true;
    cover.passed = reached >= gc;
    return {make_check("secant_G_over_G0_max_error_relative", worst_curve, 0.0, 0.02, false,
                       "max |G_s / (G0 / (1 + 0.385 gamma / gamma_0.7)) - 1| for gamma up to G_t = G_ur"),
            make_check("secant_G_beyond_floor_max_error_relative", worst_floor, 0.0, 0.02, false,
                       "max |G_s / G_s,ref - 1| past gamma_c, tangent G_ur"),
            cover};
}

// Drained compression at constant sigma'_3: failure at the Mohr-Coulomb deviator of
// triaxial compression, q_f = 2 sin phi / (1 - sin phi) (sigma'_3 + c cot phi), and the
// secant at q_f / 2 equals E50 = E50_ref ((c cos phi + sigma'_3 sin phi) / (c cos phi + p_ref sin phi))^m.
std::vector<VerificationCheck> e50_and_failure(const ElementTestContext& ctx) {
    ctx.require_model("hardening_soil_small", "e50_and_failure");
    const auto& m = ctx.c.material;
    const auto& r = drained_test(ctx, false, "e50_and_failure");
    const double s3 = ctx.c.lateral_stress, sphi = std::sin(m.friction_angle * kDeg);
    const double qf = 2.0 * sphi / (1.0 - sphi) * (s3 + m.cohesion / std::tan(m.friction_angle * kDeg));
    double qmax = 0.0;
    for (const auto& x : r.path) qmax = std::max(qmax, x.q - r.path.front().q);
    double e50 = 0.0;
    for (std::size_t k = 1; k < r.path.size(); ++k) {
        const double qa = r.path[k - 1].q - r.path.front().q, qb = r.path[k].q - r.path.front().q;
        if (qb >= 0.5 * qmax) {
            const double ea = r.path[k - 1].axial_strain, eb = r.path[k].axial_strain;
            const double eps = ea + (0.5 * qmax - qa) / (qb - qa) * (eb - ea) - r.path.front().axial_strain;
            e50 = 0.5 * qmax / eps;
            break;
        }
    }
    return {make_check("failure_deviator_Pa", qmax, qf, 0.01, true, "q_f = 2 sin phi / (1 - sin phi) (sigma'_3 + c cot phi)"),
            make_check("E50_Pa", e50, m.e50_ref * stiffness_factor(m, s3), 0.02, true,
                       "secant q / eps_a at q_f / 2 = E50_ref (sigma'_3 factor)^m")};
}

}  // namespace pilempm::mpm
