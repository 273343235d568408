#pragma once
// Small helpers shared by the critical-state models (modified and subloading Cam clay):
// invariants in the soil-mechanics sense (p' and q compression positive) of a Voigt stress
// (tension positive, voigt.hpp), the isotropic elastic operator and the hypoelastic step
// with the volumetric law integrated exactly.
#include <algorithm>
#include <cmath>

namespace pilempm::mpm::critical_state {

inline double mean_pressure(const double* s) { return -(s[0] + s[1] + s[2]) / 3.0; }  // compression +

inline double deviator_q(const double* s, double p) {
    const double a = s[0] + p, b = s[1] + p, c = s[2] + p;
    return std::sqrt(1.5 * (a * a + b * b + c * c + 2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5])));
}

// Tensor norm of a Voigt stress (shear components counted twice).
inline double norm6(const double* s) {
    return std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

// y = De x for isotropic K, G; x in engineering form (strain-like), y stress-like.
inline void elastic_tangent(double K, double G, const double* x, double* y) {
    const double tr = (K - 2.0 / 3.0 * G) * (x[0] + x[1] + x[2]);
    for (int i = 0; i < 3; ++i) y[i] = tr + 2.0 * G * x[i];
    for (int i = 3; i < 6; ++i) y[i] = G * x[i];
}

// K = v p / kappa above p_min, constant below (a point at zero stress stays finite).
inline double bulk_modulus(double p, double v, double kappa, double p_min) { return v * std::max(p, p_min) / kappa; }

// Hypoelastic step: p follows exp(-v de_v / kappa) above p_min (exact for the kappa line),
// the shear modulus that of the secant bulk modulus (G / K fixed by Poisson's ratio).
inline void hypoelastic_step(const double* s_in, double v, const double* de, double kappa, double p_min,
                             double g_over_k, double* s_out) {
    const double p = mean_pressure(s_in), dev = de[0] + de[1] + de[2];
    const double pe = std::max(p, p_min);
    double K = bulk_modulus(p, v, kappa, p_min);
    if (std::abs(dev) > 1e-14) {
        const double p_new = pe * std::exp(-v * dev / kappa) + (p - pe);
        K = -(p_new - p) / dev;
    }
    const double G = g_over_k * K;
    const double mean_de = dev / 3.0;
    for (int i = 0; i < 3; ++i) s_out[i] = s_in[i] + K * dev + 2.0 * G * (de[i] - mean_de);
    for (int i = 3; i < 6; ++i) s_out[i] = s_in[i] + G * de[i];  // engineering shear
}

// G / K of an isotropic material with Poisson's ratio nu.
inline double shear_to_bulk(double nu) { return 3.0 * (1.0 - 2.0 * nu) / (2.0 * (1.0 + nu)); }

}  // namespace pilempm::mpm::critical_state
