#include "mpm/materials/modified_cam_clay.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mpm/materials/substepping.hpp"

#include "mpm/materials/critical_state_common.hpp"

namespace pilempm::mpm {

using critical_state::deviator_q;
using critical_state::mean_pressure;
using critical_state::norm6;

ModifiedCamClay::ModifiedCamClay(const CamClayParameters& p) : par_(p) {
    if (!(p.lambda > p.kappa) || !(p.kappa > 0.0))
        throw std::invalid_argument("modified Cam clay: 0 < kappa < lambda");
    if (!(p.M > 0.0)) throw std::invalid_argument("modified Cam clay: M > 0");
    if (!(p.poisson_ratio > -1.0 && p.poisson_ratio < 0.5))
        throw std::invalid_argument("modified Cam clay: -1 < nu < 0.5");
    if (!(p.void_ratio > 0.0) || !(p.ocr >= 1.0) || !(p.p_min > 0.0) || !(p.tolerance > 0.0))
        throw std::invalid_argument("modified Cam clay: e > 0, OCR >= 1, p_min > 0, tolerance > 0");
    if (!(p.peak_friction_angle >= 0.0 && p.peak_friction_angle < 89.0))
        throw std::invalid_argument("modified Cam clay: peak friction angle 0 (none) or below 89 deg");
    g_over_k_ = critical_state::shear_to_bulk(p.poisson_ratio);
    if (p.peak_friction_angle > 0.0) peak_ = FrictionCone::of_angle(p.peak_friction_angle, false);
}

double ModifiedCamClay::yield_function(const double* s, double pc) const {
    const double p = mean_pressure(s), q = deviator_q(s, p);
    return q * q / (par_.M * par_.M) + p * (p - pc);
}

double ModifiedCamClay::bulk(double p, double v) const { return critical_state::bulk_modulus(p, v, par_.kappa, par_.p_min); }

void ModifiedCamClay::initialise_state(const double* stress, double* state) const {
    const double p = std::max(mean_pressure(stress), par_.p_min), q = deviator_q(stress, mean_pressure(stress));
    state[0] = std::max(par_.ocr * (p + q * q / (par_.M * par_.M * p)), par_.p_min);
    state[1] = par_.void_ratio;
}

double ModifiedCamClay::p_wave_modulus() const {
    const double K = bulk(p_ref_, 1.0 + par_.void_ratio);
    return K + 4.0 / 3.0 * g_over_k_ * K;
}
double ModifiedCamClay::shear_modulus() const { return g_over_k_ * bulk(p_ref_, 1.0 + par_.void_ratio); }

double ModifiedCamClay::p_wave_modulus_at(const double* stress, const double* state) const {
    const double K = bulk(mean_pressure(stress), 1.0 + state[1]);
    return K * (1.0 + 4.0 / 3.0 * g_over_k_);
}

// Hypoelastic step (critical_state_common.hpp); the hardening variable is unchanged.
void ModifiedCamClay::elastic_step(const Point& in, const double* de, Point& out) const {
    critical_state::hypoelastic_step(in.s, in.v, de, par_.kappa, par_.p_min, g_over_k_, out.s);
    out.pc = in.pc;
    out.v = in.v;
}

// What the plastic corrector needs at a stress: n = df/dsigma = -(2p - p_c)/3 I + 3/M^2
// dev(sigma) (no 1/q: smooth at q = 0), in engineering form so that n . dsigma is the
// contraction; De n; n . De n; and dp_c / dl.
struct ModifiedCamClay::Gradient {
    double n[6], Dn[6], nDn, hard, p, K, G;
};

ModifiedCamClay::Gradient ModifiedCamClay::gradient(const Point& pt) const {
    Gradient g;
    g.p = mean_pressure(pt.s);
    g.K = bulk(g.p, pt.v);
    g.G = g_over_k_ * g.K;
    const double c = 3.0 / (par_.M * par_.M);
    for (int i = 0; i < 3; ++i) g.n[i] = -(2.0 * g.p - pt.pc) / 3.0 + c * (pt.s[i] + g.p);
    for (int i = 3; i < 6; ++i) g.n[i] = 2.0 * c * pt.s[i];
    critical_state::elastic_tangent(g.K, g.G, g.n, g.Dn);
    g.nDn = 0.0;
    for (int i = 0; i < 6; ++i) g.nDn += g.n[i] * g.Dn[i];
    g.hard = pt.pc * pt.v * (2.0 * g.p - pt.pc) / (par_.lambda - par_.kappa);
    return g;
}

// Continuum tangent on the yield surface: dsigma = De (de - dl n), with the multiplier from
// consistency; unloading (dl < 0) is elastic.
void ModifiedCamClay::plastic_rate(const Point& pt, const double* de, double* ds, double& dpc) const {
    const Gradient g = gradient(pt);
    double Dde[6];
    critical_state::elastic_tangent(g.K, g.G, de, Dde);
    double nDde = 0.0;
    for (int i = 0; i < 6; ++i) nDde += g.n[i] * Dde[i];
    const double dl = std::max(0.0, nDde / (g.nDn + g.p * g.hard));
    for (int i = 0; i < 6; ++i) ds[i] = Dde[i] - dl * g.Dn[i];
    dpc = dl * g.hard;
}

// Pulls a stress that drifted off the surface back onto it along De n (Potts & Gens 1985).
void ModifiedCamClay::correct_drift(Point& pt) const {
    for (int it = 0; it < 5; ++it) {
        const double fv = f(pt);
        if (std::abs(fv) <= par_.tolerance * pt.pc * pt.pc) return;
        const Gradient g = gradient(pt);
        const double dl = fv / (g.nDn + g.p * g.hard);
        for (int i = 0; i < 6; ++i) pt.s[i] -= dl * g.Dn[i];
        pt.pc = std::max(pt.pc + dl * g.hard, par_.p_min);
    }
}

void ModifiedCamClay::update_point(const double* de, Point& pt) const {
    const double tol = par_.tolerance;
    if (f(pt) > tol * pt.pc * pt.pc) correct_drift(pt);  // e.g. a set-up a hair outside
    Point trial;
    elastic_step(pt, de, trial);
    const double f0 = f(pt), f1 = f(trial);
    double alpha = 0.0;  // elastic share of the increment
    if (f1 <= tol * trial.pc * trial.pc) {
        pt = trial;
        return;
    }
    if (f0 < -tol * pt.pc * pt.pc) {
        // The elastic share of the increment: where the elastic path meets the surface.
        alpha = pegasus_root(f0, f1, tol * pt.pc * pt.pc, [&](double a) {
            double part[6];
            for (int i = 0; i < 6; ++i) part[i] = a * de[i];
            elastic_step(pt, part, trial);
            return f(trial);
        });
        pt = trial;
    }
    // Plastic part: modified Euler with local error control (Sloan et al. 2001).
    double rest[6];
    for (int i = 0; i < 6; ++i) rest[i] = (1.0 - alpha) * de[i];
    SubstepClock clock(tol, 100000, 1e-12);
    while (clock.unfinished()) {
        if (clock.exhausted()) throw std::runtime_error("modified Cam clay: substepping did not converge");
        double d[6], ds1[6], ds2[6], dpc1, dpc2;
        for (int i = 0; i < 6; ++i) d[i] = clock.fraction() * rest[i];
        plastic_rate(pt, d, ds1, dpc1);
        Point mid = pt;
        for (int i = 0; i < 6; ++i) mid.s[i] += ds1[i];
        mid.pc = std::max(mid.pc + dpc1, par_.p_min);
        plastic_rate(mid, d, ds2, dpc2);
        Point next = pt;
        double diff[6];
        for (int i = 0; i < 6; ++i) {
            next.s[i] += 0.5 * (ds1[i] + ds2[i]);
            diff[i] = 0.5 * (ds2[i] - ds1[i]);
        }
        next.pc = std::max(next.pc + 0.5 * (dpc1 + dpc2), par_.p_min);
        const double scale = std::max(norm6(next.s), par_.p_min);
        if (!clock.accept(std::max(norm6(diff) / scale, 0.5 * std::abs(dpc2 - dpc1) / next.pc))) continue;
        correct_drift(next);
        pt = next;
    }
}

void ModifiedCamClay::update(int count, const int* points, const double* de, double* stress, double* state,
                             int stride) const {
    for (int k = 0; k < count; ++k) {
        const int idx = points[k];
        const double* e = de + 6 * idx;
        double* s = stress + 6 * idx;
        double* st = state + static_cast<std::size_t>(stride) * idx;
        Point pt;
        std::copy(s, s + 6, pt.s);
        pt.pc = std::max(st[0], par_.p_min);
        pt.v = 1.0 + st[1];
        update_point(e, pt);
        if (peak_.exists()) peak_.return_to(pt.s);  // inside the ellipse: p_c stays
        std::copy(pt.s, pt.s + 6, s);
        st[0] = pt.pc;
        st[1] = pt.v * std::exp(e[0] + e[1] + e[2]) - 1.0;  // v follows the volume
    }
}

}  // namespace pilempm::mpm
