#include "mpm/materials/subloading_cam_clay.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mpm/materials/substepping.hpp"

#include "mpm/materials/critical_state_common.hpp"

namespace pilempm::mpm {

using critical_state::deviator_q;
using critical_state::mean_pressure;
using critical_state::norm6;

namespace {

// Deviator s of a Voigt stress (tensor shear), det s and dev(s s), for the Lode angle.
struct Deviator {
    double s[6], J3, dev_ss[6];
};

Deviator deviator(const double* st, double p) {
    Deviator d;
    for (int i = 0; i < 3; ++i) d.s[i] = st[i] + p;
    for (int i = 3; i < 6; ++i) d.s[i] = st[i];
    const double *s = d.s;
    const double xx = s[0], yy = s[1], zz = s[2], xy = s[3], yz = s[4], zx = s[5];
    d.J3 = xx * (yy * zz - yz * yz) - xy * (xy * zz - yz * zx) + zx * (xy * yz - yy * zx);
    double ss[6] = {xx * xx + xy * xy + zx * zx, xy * xy + yy * yy + yz * yz, zx * zx + yz * yz + zz * zz,
                    xx * xy + xy * yy + zx * yz, xy * zx + yy * yz + yz * zz, xx * zx + xy * yz + zx * zz};
    const double tr = (ss[0] + ss[1] + ss[2]) / 3.0;
    for (int i = 0; i < 3; ++i) d.dev_ss[i] = ss[i] - tr;
    for (int i = 3; i < 6; ++i) d.dev_ss[i] = ss[i];
    return d;
}

}  // namespace

SubloadingCamClay::SubloadingCamClay(const SubloadingCamClayParameters& p) : par_(p) {
    if (!(p.lambda > p.kappa) || !(p.kappa > 0.0))
        throw std::invalid_argument("subloading Cam clay: 0 < kappa < lambda");
    if (!(p.friction_angle > 0.0 && p.friction_angle < 89.0))
        throw std::invalid_argument("subloading Cam clay: 0 < friction angle < 89 deg");
    if (!(p.poisson_ratio > -1.0 && p.poisson_ratio < 0.5))
        throw std::invalid_argument("subloading Cam clay: -1 < nu < 0.5");
    if (!(p.void_ratio > 0.0) || !(p.ocr >= 1.0) || !(p.p_min > 0.0) || !(p.tolerance > 0.0))
        throw std::invalid_argument("subloading Cam clay: e > 0, OCR >= 1, p_min > 0, tolerance > 0");
    if (!(p.a > 0.0)) throw std::invalid_argument("subloading Cam clay: subloading parameter a > 0");
    if (!(p.peak_friction_angle == 0.0 || (p.peak_friction_angle >= p.friction_angle && p.peak_friction_angle < 89.0)))
        throw std::invalid_argument("subloading Cam clay: peak friction angle 0 (none) or from the friction angle to 89 deg");
    g_over_k_ = critical_state::shear_to_bulk(p.poisson_ratio);
    const bool circular = p.surface == CriticalStateSurface::DruckerPrager;
    critical_ = FrictionCone::of_angle(p.friction_angle, circular);
    if (p.peak_friction_angle > 0.0) peak_ = FrictionCone::of_angle(p.peak_friction_angle, false);  // no tension
    M_c_ = critical_.M_c;
    k_mn_ = critical_.k;
    p_floor_ = 1e-3 * p.p_min;
}

const char* SubloadingCamClay::state_name(int k) const {
    static const char* names[] = {"preconsolidation_pressure", "void_ratio", "subloading_rho", "plastic_strain"};
    return k >= 0 && k < 4 ? names[k] : "";
}

double SubloadingCamClay::critical_state_ratio_at(double c) const { return critical_.ratio_at(c); }

// M and what its Lode dependence adds to df/dsigma: q^2 d(M^-2)/dsigma = -2 M'/M^3 q^2
// dc/dsigma, with c = -27 J3 / (2 q^3) (tension-positive deviator: compression gives c = 1)
// and q^2 dc/dsigma = -27/(2q) dev(s s) + 243 J3 / (4 q^3) s, which vanishes like q.
struct SubloadingCamClay::Lode {
    double M, w[6];  // w = q^2 d(M^-2)/dsigma, tensor components
};

SubloadingCamClay::Lode SubloadingCamClay::lode(const double* st, double p, double q) const {
    Lode L;
    std::fill(L.w, L.w + 6, 0.0);
    if (par_.surface == CriticalStateSurface::DruckerPrager || !(q > 1e-10 * std::max(std::abs(p), par_.p_min))) {
        L.M = par_.surface == CriticalStateSurface::DruckerPrager ? M_c_ : critical_state_ratio_at(0.0);
        return L;
    }
    const Deviator d = deviator(st, p);
    const double q3 = q * q * q;
    const double c = std::clamp(-13.5 * d.J3 / q3, -1.0, 1.0);
    const double M = critical_state_ratio_at(c);
    L.M = M;
    if (std::abs(c) >= 1.0) return L;  // the triaxial meridians: M is stationary in theta there
    // dM/dc from g(eta, c) = 0.
    const double A = 2.0 * k_mn_ * c / 27.0, B = 1.0 - k_mn_ / 3.0;
    const double dMdc = -(2.0 * k_mn_ / 27.0) * M * M * M / (M * (2.0 * B + 3.0 * A * M));
    const double factor = -2.0 * dMdc / (M * M * M);
    for (int i = 0; i < 6; ++i) L.w[i] = factor * (-13.5 / q * d.dev_ss[i] + 60.75 * d.J3 / q3 * d.s[i]);
    return L;
}

double SubloadingCamClay::critical_state_ratio(const double* stress) const {
    const double p = mean_pressure(stress);
    return lode(stress, p, deviator_q(stress, p)).M;
}

double SubloadingCamClay::subloading_size(const double* stress) const {
    const double p = mean_pressure(stress);
    if (!(p > 0.0)) return 0.0;
    const double q = deviator_q(stress, p), M = lode(stress, p, q).M;
    return p + q * q / (M * M * p);
}

double SubloadingCamClay::yield_function(const double* s, double pc, double rho) const {
    const double p = mean_pressure(s), q = deviator_q(s, p), M = lode(s, p, q).M;
    return q * q / (M * M) + p * (p - pc * std::exp(-rho / (par_.lambda - par_.kappa)));
}

double SubloadingCamClay::ps_of(const Point& pt) const { return pt.pc * std::exp(-pt.rho / (par_.lambda - par_.kappa)); }

double SubloadingCamClay::rho_of_stress(const double* s, double pc) const {
    return (par_.lambda - par_.kappa) * std::log(pc / std::max(subloading_size(s), p_floor_));
}

double SubloadingCamClay::bulk(double p, double v) const { return critical_state::bulk_modulus(p, v, par_.kappa, par_.p_min); }

void SubloadingCamClay::initialise_state(const double* stress, double* state) const {
    const double ps = std::max(subloading_size(stress), par_.p_min);
    state[0] = std::max(par_.ocr * ps, par_.p_min);
    state[1] = par_.void_ratio;
    state[2] = rho_of_stress(stress, state[0]);
    state[3] = 0.0;
}

double SubloadingCamClay::p_wave_modulus() const {
    const double K = bulk(p_ref_, 1.0 + par_.void_ratio);
    return K * (1.0 + 4.0 / 3.0 * g_over_k_);
}
double SubloadingCamClay::shear_modulus() const { return g_over_k_ * bulk(p_ref_, 1.0 + par_.void_ratio); }

double SubloadingCamClay::p_wave_modulus_at(const double* stress, const double* state) const {
    return bulk(mean_pressure(stress), 1.0 + state[1]) * (1.0 + 4.0 / 3.0 * g_over_k_);
}

// n = df/dsigma in engineering form (so that n . dsigma is the contraction), De n, n De n,
// and per unit multiplier: p dp_s (the hardening modulus), dp_c, drho and |deps^p|.
struct SubloadingCamClay::Gradient {
    double n[6], Dn[6], nDn, hard, dpc, drho, deps, p, ps;
};

SubloadingCamClay::Gradient SubloadingCamClay::gradient(const Point& pt) const {
    Gradient g;
    g.p = mean_pressure(pt.s);
    g.ps = ps_of(pt);
    const double q = deviator_q(pt.s, g.p);
    const Lode L = lode(pt.s, g.p, q);
    const double K = bulk(g.p, pt.v), G = g_over_k_ * K;
    const double c = 3.0 / (L.M * L.M);
    double nt[6];  // tensor components
    for (int i = 0; i < 3; ++i) nt[i] = -(2.0 * g.p - g.ps) / 3.0 + c * (pt.s[i] + g.p) + L.w[i];
    for (int i = 3; i < 6; ++i) nt[i] = c * pt.s[i] + L.w[i];
    for (int i = 0; i < 3; ++i) g.n[i] = nt[i];
    for (int i = 3; i < 6; ++i) g.n[i] = 2.0 * nt[i];
    critical_state::elastic_tangent(K, G, g.n, g.Dn);
    g.nDn = 0.0;
    for (int i = 0; i < 6; ++i) g.nDn += g.n[i] * g.Dn[i];
    const double lk = par_.lambda - par_.kappa, Grho = G_of(pt.rho);
    g.dpc = pt.pc * pt.v * (2.0 * g.p - g.ps) / lk;
    g.drho = -pt.v * Grho * g.ps;
    g.hard = g.p * g.ps * pt.v / lk * ((2.0 * g.p - g.ps) + Grho * g.ps);
    g.deps = norm6(nt);
    return g;
}

void SubloadingCamClay::flow_direction(const double* stress, const double* state, double* n) const {
    Point pt;
    std::copy(stress, stress + 6, pt.s);
    pt.pc = state[0];
    pt.v = 1.0 + state[1];
    pt.rho = state[2];
    pt.eps_p = state[3];
    const Gradient g = gradient(pt);
    std::copy(g.n, g.n + 6, n);
}

double SubloadingCamClay::drift_tolerance(const Point& pt) const {
    const double ps = std::max(ps_of(pt), par_.p_min);
    return par_.tolerance * ps * ps;
}

// Continuum tangent on the subloading surface: dsigma = De (de - dl n); unloading (dl < 0)
// is elastic. Returns dl.
double SubloadingCamClay::plastic_rate(const Point& pt, const double* de, double* ds, double& dpc, double& drho,
                                       double& deps) const {
    const Gradient g = gradient(pt);
    const double K = bulk(g.p, pt.v);
    double Dde[6];
    critical_state::elastic_tangent(K, g_over_k_ * K, de, Dde);
    double nDde = 0.0;
    for (int i = 0; i < 6; ++i) nDde += g.n[i] * Dde[i];
    const double den = g.nDn + g.hard;
    const double dl = den > 0.0 ? std::max(0.0, nDde / den) : 0.0;
    for (int i = 0; i < 6; ++i) ds[i] = Dde[i] - dl * g.Dn[i];
    dpc = dl * g.dpc;
    drho = dl * g.drho;
    deps = dl * g.deps;
    return dl;
}

// Pulls a stress that drifted off the subloading surface back onto it along De n (Potts &
// Gens 1985), with p_c and rho moving as for a plastic multiplier.
void SubloadingCamClay::correct_drift(Point& pt) const {
    for (int it = 0; it < 5; ++it) {
        const double fv = f(pt);
        if (std::abs(fv) <= drift_tolerance(pt)) return;
        const Gradient g = gradient(pt);
        const double den = g.nDn + g.hard;
        if (!(den > 0.0)) return;
        const double dl = fv / den;
        for (int i = 0; i < 6; ++i) pt.s[i] -= dl * g.Dn[i];
        pt.pc = std::max(pt.pc + dl * g.dpc, par_.p_min);
        pt.rho += dl * g.drho;
    }
}

void SubloadingCamClay::update_point(const double* de, Point& pt) const {
    const double tol = par_.tolerance;
    // Outside the normal surface (a set-up a hair outside, a point pulled into tension):
    // back onto it, as modified Cam clay does; then the subloading surface through the stress.
    {
        const double p = mean_pressure(pt.s), q = deviator_q(pt.s, p), M = lode(pt.s, p, q).M;
        pt.rho = 0.0;
        if (q * q / (M * M) + p * (p - pt.pc) > drift_tolerance(pt)) {
            correct_drift(pt);
            pt.rho = rho_of_stress(pt.s, pt.pc);
        } else {
            const double ps = p > 0.0 ? p + q * q / (M * M * p) : 0.0;
            pt.rho = (par_.lambda - par_.kappa) * std::log(pt.pc / std::max(ps, p_floor_));
        }
    }
    // Unloading from the surface: exact hypoelastic step, the surface shrinks to the stress.
    // On loading the rate at the start is the first stage of the first substep.
    double ds0[6], dpc0, drho0, deps0;
    const double dl0 = plastic_rate(pt, de, ds0, dpc0, drho0, deps0);
    if (dl0 <= 0.0) {
        double s[6];
        critical_state::hypoelastic_step(pt.s, pt.v, de, par_.kappa, par_.p_min, g_over_k_, s);
        std::copy(s, s + 6, pt.s);
        pt.rho = rho_of_stress(pt.s, pt.pc);
        return;
    }
    // Modified Euler with local error control (Sloan et al. 2001), as modified Cam clay.
    SubstepClock clock(tol, 100000, 1e-12);
    while (clock.unfinished()) {
        if (clock.exhausted()) throw std::runtime_error("subloading Cam clay: substepping did not converge");
        const double dT = clock.fraction();
        double d[6], ds1[6], ds2[6], dpc1, dpc2, drho1, drho2, deps1, deps2;
        for (int i = 0; i < 6; ++i) d[i] = dT * de[i];
        double dl1;
        if (clock.first()) {  // the rate is homogeneous of degree 1 in the increment
            dl1 = dT * dl0;
            for (int i = 0; i < 6; ++i) ds1[i] = dT * ds0[i];
            dpc1 = dT * dpc0;
            drho1 = dT * drho0;
            deps1 = dT * deps0;
        } else {
            dl1 = plastic_rate(pt, d, ds1, dpc1, drho1, deps1);
        }
        Point mid = pt;
        for (int i = 0; i < 6; ++i) mid.s[i] += ds1[i];
        mid.pc = std::max(mid.pc + dpc1, par_.p_min);
        mid.rho += drho1;
        const double dl2 = plastic_rate(mid, d, ds2, dpc2, drho2, deps2);
        Point next = pt;
        double diff[6];
        for (int i = 0; i < 6; ++i) {
            next.s[i] += 0.5 * (ds1[i] + ds2[i]);
            diff[i] = 0.5 * (ds2[i] - ds1[i]);
        }
        next.pc = std::max(next.pc + 0.5 * (dpc1 + dpc2), par_.p_min);
        next.rho += 0.5 * (drho1 + drho2);
        next.eps_p += 0.5 * (deps1 + deps2);
        const double scale = std::max(norm6(next.s), par_.p_min);
        const double err = std::max({norm6(diff) / scale, 0.5 * std::abs(dpc2 - dpc1) / next.pc,
                                     0.5 * std::abs(drho2 - drho1) / (par_.lambda - par_.kappa)});
        if (!clock.accept(err)) continue;
        // On loading keep the stress on the subloading surface; an elastic substep moved it
        // inside, and the surface follows it there.
        if (dl1 > 0.0 || dl2 > 0.0) correct_drift(next);
        else next.rho = rho_of_stress(next.s, next.pc);
        pt = next;
    }
}

// Back onto the bounding cone (FrictionCone::return_to); its plastic strain is the
// deviator's drop over 2G.
void SubloadingCamClay::bound_by_peak_cone(Point& pt) const {
    if (!peak_.exists()) return;
    const double p = mean_pressure(pt.s);
    const double removed = peak_.return_to(pt.s);
    if (removed == 0.0) return;
    pt.eps_p += removed / (2.0 * g_over_k_ * bulk(p, pt.v));
    pt.rho = rho_of_stress(pt.s, pt.pc);
}

void SubloadingCamClay::update(int count, const int* points, const double* de, double* stress, double* state,
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
        pt.rho = st[2];
        pt.eps_p = st[3];
        update_point(e, pt);
        bound_by_peak_cone(pt);
        std::copy(pt.s, pt.s + 6, s);
        st[0] = pt.pc;
        st[1] = pt.v * std::exp(e[0] + e[1] + e[2]) - 1.0;  // v follows the volume
        st[2] = pt.rho;
        st[3] = pt.eps_p;
    }
}

}  // namespace pilempm::mpm
