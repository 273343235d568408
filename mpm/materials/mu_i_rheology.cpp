#include "mpm/materials/mu_i_rheology.hpp"

#include <cmath>
#include <stdexcept>

namespace pilempm::mpm {

MuIRheology::MuIRheology(const MuIParameters& p) : par_(p) {
    if (!(p.youngs_modulus > 0.0) || !(p.poisson_ratio > -1.0 && p.poisson_ratio < 0.5))
        throw std::invalid_argument("mu(I) rheology: E > 0, -1 < nu < 0.5");
    if (!(p.mu_s > 0.0) || !(p.mu_2 >= p.mu_s) || !(p.I_0 > 0.0))
        throw std::invalid_argument("mu(I) rheology: 0 < mu_s <= mu_2, I_0 > 0");
    if (!(p.grain_diameter > 0.0) || !(p.grain_density > 0.0))
        throw std::invalid_argument("mu(I) rheology: grain diameter and density > 0");
    const double E = p.youngs_modulus, nu = p.poisson_ratio;
    lambda_ = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    mu_ = E / (2.0 * (1.0 + nu));
}

const char* MuIRheology::state_name(int k) const {
    return k == 0 ? "plastic_shear_strain" : k == 1 ? "inertial_number" : "";
}

double MuIRheology::friction(double I) const {
    return I > 0.0 ? par_.mu_s + (par_.mu_2 - par_.mu_s) * I / (par_.I_0 + I) : par_.mu_s;
}

double MuIRheology::inertial_number(double shear_rate, double p) const {
    return shear_rate * par_.grain_diameter / std::sqrt(p / par_.grain_density);
}

// With x = dg and a = dt I_0 sqrt(p / rho_s) / d (the increment at which I = I_0),
// mu = mu_s + dmu x / (a + x), and tau_trial - G x = p mu is
//   G x^2 - B x - a b = 0,   b = tau_trial - mu_s p > 0,   B = b - G a - dmu p,
// whose positive root is taken in the form that does not cancel.
double MuIRheology::plastic_shear_increment(double tau_trial, double p) const {
    const double G = mu_, b = tau_trial - par_.mu_s * p;
    if (!(dt_ > 0.0)) return b / G;  // quasi-static: onto mu_s
    const double a = dt_ * par_.I_0 * std::sqrt(p / par_.grain_density) / par_.grain_diameter;
    const double B = b - G * a - (par_.mu_2 - par_.mu_s) * p;
    const double root = std::sqrt(B * B + 4.0 * G * a * b);
    return B >= 0.0 ? (B + root) / (2.0 * G) : 2.0 * a * b / (root - B);
}

void MuIRheology::update(int count, const int* points, const double* dstrain, double* stress, double* state,
                         int stride) const {
    const double G = mu_, lambda = lambda_;
    for (int k = 0; k < count; ++k) {
        const int pt = points[k];
        const double* e = dstrain + 6 * pt;
        double* s = stress + 6 * pt;
        double* q = state + static_cast<long>(stride) * pt;
        const double tr = lambda * (e[0] + e[1] + e[2]);
        double t[6] = {s[0] + tr + 2.0 * G * e[0], s[1] + tr + 2.0 * G * e[1], s[2] + tr + 2.0 * G * e[2],
                       s[3] + G * e[3],            s[4] + G * e[4],            s[5] + G * e[5]};
        const double p = -(t[0] + t[1] + t[2]) / 3.0;
        if (!(p > 0.0)) {  // disconnected: the grains have separated
            for (int i = 0; i < 6; ++i) s[i] = 0.0;
            q[1] = 0.0;
            continue;
        }
        const double d0 = t[0] + p, d1 = t[1] + p, d2 = t[2] + p;
        const double tau = std::sqrt(0.5 * (d0 * d0 + d1 * d1 + d2 * d2) + t[3] * t[3] + t[4] * t[4] + t[5] * t[5]);
        if (tau <= par_.mu_s * p) {
            for (int i = 0; i < 6; ++i) s[i] = t[i];
            q[1] = 0.0;
            continue;
        }
        const double dg = plastic_shear_increment(tau, p);
        const double scale = (tau - G * dg) / tau;  // the deviator shrinks along itself
        s[0] = scale * d0 - p;
        s[1] = scale * d1 - p;
        s[2] = scale * d2 - p;
        s[3] = scale * t[3];
        s[4] = scale * t[4];
        s[5] = scale * t[5];
        q[0] += dg;
        q[1] = dt_ > 0.0 ? inertial_number(dg / dt_, p) : 0.0;
    }
}

}  // namespace pilempm::mpm
