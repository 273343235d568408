#include "mpm/materials/hypoplastic.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mpm/materials/substepping.hpp"

namespace pilempm::mpm {

namespace {

// Symmetric tensors in Voigt order with tensor shear.
double ddot(const double* a, const double* b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + 2.0 * (a[3] * b[3] + a[4] * b[4] + a[5] * b[5]);
}
double norm(const double* a) { return std::sqrt(ddot(a, a)); }

// tr(A^3) of a symmetric tensor.
double trace_cube(const double* a) {
    return a[0] * a[0] * a[0] + a[1] * a[1] * a[1] + a[2] * a[2] * a[2] +
           3.0 * (a[3] * a[3] * (a[0] + a[1]) + a[4] * a[4] * (a[1] + a[2]) + a[5] * a[5] * (a[2] + a[0])) +
           6.0 * a[3] * a[4] * a[5];
}

// x^y with the exponents calibrations use (1, 1/2, 1/4, small integers) done without pow,
// which dominated the profile of the update.
double power(double x, double y) {
    if (y == 1.0) return x;
    if (y == 0.5) return std::sqrt(x);
    if (y == 0.25) return std::sqrt(std::sqrt(x));
    if (y == 0.0) return 1.0;
    const int k = static_cast<int>(y);
    if (k == y && k > 0 && k <= 8) {
        double r = x;
        for (int i = 1; i < k; ++i) r *= x;
        return r;
    }
    return std::pow(x, y);
}

double shifted_mean_pressure(const double* T, double p_t) { return -(T[0] + T[1] + T[2]) / 3.0 + p_t; }

}  // namespace

Hypoplastic::Hypoplastic(const HypoplasticParameters& p) : par_(p), igs_(p.intergranular_strain) {
    if (!(p.phi_c > 0.0 && p.phi_c < 60.0)) throw std::invalid_argument("hypoplastic: 0 < phi_c < 60 deg");
    if (!(p.h_s > 0.0) || !(p.n > 0.0 && p.n < 1.0)) throw std::invalid_argument("hypoplastic: h_s > 0, 0 < n < 1");
    if (!(p.e_d0 > 0.0 && p.e_d0 < p.e_c0 && p.e_c0 < p.e_i0))
        throw std::invalid_argument("hypoplastic: 0 < e_d0 < e_c0 < e_i0");
    if (!(p.alpha >= 0.0) || !(p.beta >= 0.0) || !(p.p_t >= 0.0) || !(p.p_min > 0.0) || !(p.tolerance > 0.0))
        throw std::invalid_argument("hypoplastic: alpha, beta, p_t >= 0; p_min, tolerance > 0");
    if (!(p.void_ratio > 0.0)) throw std::invalid_argument("hypoplastic: void ratio > 0");
    if (igs_ && !(p.m_R >= p.m_T && p.m_T >= 1.0 && p.R_max > 0.0 && p.beta_r > 0.0 && p.chi > 0.0))
        throw std::invalid_argument("hypoplastic: intergranular strain needs m_R >= m_T >= 1, R_max, beta_r, chi > 0");
    const double s = std::sin(p.phi_c * M_PI / 180.0);
    a_ = std::sqrt(3.0) * (3.0 - s) / (2.0 * std::sqrt(2.0) * s);
    const double loosest = std::pow((p.e_i0 - p.e_d0) / (p.e_c0 - p.e_d0), p.alpha);
    // Bauer's compression law e_i(p) is a solution of isotropic compression from e_i0.
    fb_factor_ = p.h_s / p.n * std::pow(p.e_i0 / p.e_c0, p.beta) / (3.0 + a_ * a_ - std::sqrt(3.0) * a_ * loosest);
}

const char* Hypoplastic::state_name(int k) const {
    static const char* names[] = {"intergranular_strain_xx", "intergranular_strain_yy", "intergranular_strain_zz",
                                  "intergranular_strain_xy", "intergranular_strain_yz", "intergranular_strain_zx"};
    if (igs_ && k < 6) return names[k];
    return "void_ratio";
}

double Hypoplastic::e_i(double p) const { return par_.e_i0 * std::exp(-std::pow(3.0 * p / par_.h_s, par_.n)); }
double Hypoplastic::e_c(double p) const { return par_.e_c0 * std::exp(-std::pow(3.0 * p / par_.h_s, par_.n)); }
double Hypoplastic::e_d(double p) const { return par_.e_d0 * std::exp(-std::pow(3.0 * p / par_.h_s, par_.n)); }

void Hypoplastic::initialise_state(const double* stress, double* state) const {
    for (int k = 0; k < num_state() - 1; ++k) state[k] = 0.0;
    state[num_state() - 1] = par_.void_ratio;
    if (!igs_ || !par_.delta_along_stress) return;
    double Ts[6];
    for (int i = 0; i < 6; ++i) Ts[i] = stress[i] - (i < 3 ? par_.p_t : 0.0);
    const double n = norm(Ts);
    if (n > 0.0)
        for (int i = 0; i < 6; ++i) state[i] = par_.R_max * Ts[i] / n;
}

// Everything the rate needs at one state: T^, the factor f_b f_e / tr(T^^2), F and f_d.
struct Hypoplastic::Stiffness {
    double That[6], fs, F, fd;
};

Hypoplastic::Stiffness Hypoplastic::stiffness(const Point& pt) const {
    Stiffness k;
    const double ps = std::max(shifted_mean_pressure(pt.T, par_.p_t), par_.p_min);
    const double tr = -3.0 * ps;
    for (int i = 0; i < 6; ++i) k.That[i] = (pt.T[i] - (i < 3 ? par_.p_t : 0.0)) / tr;
    double dev[6];
    for (int i = 0; i < 6; ++i) dev[i] = k.That[i] - (i < 3 ? 1.0 / 3.0 : 0.0);
    const double dev2 = ddot(dev, dev);
    const double tan_psi = std::sqrt(3.0 * dev2);
    const double cos3t = dev2 > 1e-24 ? std::clamp(-std::sqrt(6.0) * trace_cube(dev) / std::pow(dev2, 1.5), -1.0, 1.0) : 1.0;
    const double t2 = tan_psi * tan_psi;
    const double arg = t2 / 8.0 + (2.0 - t2) / std::max(2.0 + std::sqrt(2.0) * tan_psi * cos3t, 1e-12);
    k.F = std::max(std::sqrt(std::max(arg, 0.0)) - tan_psi / (2.0 * std::sqrt(2.0)), 0.0);
    // Pycnotropy and barotropy; e below e_d has no dilatant part left.
    const double ratio = 3.0 * ps / par_.h_s, ratio_n = std::pow(ratio, par_.n);
    const double x = std::exp(-ratio_n);
    const double ei = par_.e_i0 * x, ec = par_.e_c0 * x, ed = par_.e_d0 * x;
    const double fe = power(ec / pt.e, par_.beta);
    k.fd = power(std::max((pt.e - ed) / (ec - ed), 0.0), par_.alpha);
    const double fb = fb_factor_ * (1.0 + ei) / ei * ratio / ratio_n;  // (3 p_s / h_s)^(1 - n)
    k.fs = fb * fe / ddot(k.That, k.That);
    return k;
}

void Hypoplastic::rate(const Point& pt, const double* d, double* dT, double* ddelta) const {
    const Stiffness k = stiffness(pt);
    const double F2 = k.F * k.F, a2 = a_ * a_;
    // L:x = fs (F^2 x + a^2 T^ (T^:x)); N = fs fd a F (T^ + T^*).
    auto apply_L = [&](const double* x, double* y) {
        const double tx = ddot(k.That, x);
        for (int i = 0; i < 6; ++i) y[i] = k.fs * (F2 * x[i] + a2 * k.That[i] * tx);
    };
    double N[6];
    for (int i = 0; i < 6; ++i) N[i] = k.fs * k.fd * a_ * k.F * (2.0 * k.That[i] - (i < 3 ? 1.0 / 3.0 : 0.0));
    double LD[6];
    apply_L(d, LD);
    if (!igs_) {
        const double nd = norm(d);
        for (int i = 0; i < 6; ++i) dT[i] = LD[i] + N[i] * nd;
        return;
    }
    const double dnorm = norm(pt.delta);
    const double rho = std::min(dnorm / par_.R_max, 1.0);
    double dhat[6] = {0, 0, 0, 0, 0, 0};
    if (dnorm > 0.0)
        for (int i = 0; i < 6; ++i) dhat[i] = pt.delta[i] / dnorm;
    const double rc = power(rho, par_.chi), along = ddot(dhat, d);
    const double m = rc * par_.m_T + (1.0 - rc) * par_.m_R;
    double Ld[6];
    apply_L(dhat, Ld);
    if (along > 0.0) {
        // Loading in the direction of the intergranular strain: back towards L + N |D|.
        const double rb = power(rho, par_.beta_r);
        for (int i = 0; i < 6; ++i) {
            dT[i] = m * LD[i] + rc * ((1.0 - par_.m_T) * Ld[i] + N[i]) * along;
            ddelta[i] = d[i] - rb * dhat[i] * along;
        }
    } else {
        for (int i = 0; i < 6; ++i) {
            dT[i] = m * LD[i] + rc * (par_.m_R - par_.m_T) * Ld[i] * along;
            ddelta[i] = d[i];
        }
    }
}

// A shifted mean stress below p_min (a point pulled apart) becomes the isotropic p_min.
void Hypoplastic::keep_compressive(Point& pt) const {
    if (shifted_mean_pressure(pt.T, par_.p_t) >= par_.p_min) return;
    for (int i = 0; i < 3; ++i) pt.T[i] = par_.p_t - par_.p_min;
    for (int i = 3; i < 6; ++i) pt.T[i] = 0.0;
}

void Hypoplastic::update_point(const double* d, Point& pt) const {
    keep_compressive(pt);
    // Steps below 1e-9 of the increment are taken whatever their error estimate.
    SubstepClock clock(par_.tolerance, 100000, 1e-12, 1e-9);
    while (clock.unfinished()) {
        if (clock.exhausted()) throw std::runtime_error("hypoplastic: substepping did not converge");
        const double dT = clock.fraction();
        double sub[6], k1[6], k2[6], g1[6] = {}, g2[6] = {};
        for (int i = 0; i < 6; ++i) sub[i] = dT * d[i];
        const double dvol = sub[0] + sub[1] + sub[2];
        rate(pt, sub, k1, g1);
        Point mid = pt;
        for (int i = 0; i < 6; ++i) {
            mid.T[i] += k1[i];
            mid.delta[i] += g1[i];
        }
        mid.e = (1.0 + pt.e) * std::exp(dvol) - 1.0;
        if (shifted_mean_pressure(mid.T, par_.p_t) < par_.p_min) {
            // The grains separate within this substep: the point ends on the floor state,
            // whatever the path; no error control is needed (or possible) across the reset.
            keep_compressive(mid);
            pt = mid;
            clock.accept(0.0);
            continue;
        }
        rate(mid, sub, k2, g2);
        Point next = pt;
        double dk[6], dg[6];
        for (int i = 0; i < 6; ++i) {
            next.T[i] += 0.5 * (k1[i] + k2[i]);
            next.delta[i] += 0.5 * (g1[i] + g2[i]);
            dk[i] = 0.5 * (k2[i] - k1[i]);
            dg[i] = 0.5 * (g2[i] - g1[i]);
        }
        next.e = mid.e;
        const double scale = std::max(norm(next.T), par_.p_min + par_.p_t);
        if (!clock.accept(std::max(norm(dk) / scale, igs_ ? norm(dg) / par_.R_max : 0.0))) continue;
        keep_compressive(next);
        if (igs_) {  // |delta| <= R_max holds for the exact rate; keep it under round-off
            const double dn = norm(next.delta);
            if (dn > par_.R_max)
                for (int i = 0; i < 6; ++i) next.delta[i] *= par_.R_max / dn;
        }
        pt = next;
    }
}

void Hypoplastic::update(int count, const int* points, const double* de, double* stress, double* state,
                         int stride) const {
    const int ie = num_state() - 1;
    for (int k = 0; k < count; ++k) {
        const int idx = points[k];
        const double* e = de + 6 * idx;
        double* s = stress + 6 * idx;
        double* st = state + static_cast<std::size_t>(stride) * idx;
        const double d[6] = {e[0], e[1], e[2], 0.5 * e[3], 0.5 * e[4], 0.5 * e[5]};  // tensor shear
        if (d[0] == 0.0 && d[1] == 0.0 && d[2] == 0.0 && d[3] == 0.0 && d[4] == 0.0 && d[5] == 0.0) continue;
        Point pt;
        std::copy(s, s + 6, pt.T);
        for (int i = 0; i < 6; ++i) pt.delta[i] = igs_ ? st[i] : 0.0;
        pt.e = st[ie];
        update_point(d, pt);
        std::copy(pt.T, pt.T + 6, s);
        if (igs_) std::copy(pt.delta, pt.delta + 6, st);
        st[ie] = pt.e;
    }
}

// The stiffest response at an isotropic state (where f_b f_e / tr(T^^2) is largest): the
// reversal stiffness m_R L with intergranular strain, or L + N in extension without.
double Hypoplastic::isotropic_p_wave(double p, double e) const {
    Point pt{};
    for (int i = 0; i < 3; ++i) pt.T[i] = -p;
    pt.e = e;
    const Stiffness k = stiffness(pt);
    const double ML = k.fs * (1.0 + a_ * a_ / 9.0);  // uniaxial strain at T^ = 1/3
    return std::max(igs_ ? par_.m_R * ML : ML, ML + k.fs * k.fd * a_ / 3.0);
}

double Hypoplastic::p_wave_modulus() const { return isotropic_p_wave(p_ref_, par_.void_ratio); }

double Hypoplastic::shear_modulus() const {
    Point pt{};
    for (int i = 0; i < 3; ++i) pt.T[i] = -p_ref_;
    pt.e = par_.void_ratio;
    return 0.5 * stiffness(pt).fs * (igs_ ? par_.m_R : 1.0);
}

double Hypoplastic::p_wave_modulus_at(const double* stress, const double* state) const {
    const double p = std::max(-(stress[0] + stress[1] + stress[2]) / 3.0, 0.0);
    return isotropic_p_wave(p, state[num_state() - 1]);
}

}  // namespace pilempm::mpm
