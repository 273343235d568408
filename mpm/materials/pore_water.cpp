#include "mpm/materials/pore_water.hpp"

#include <algorithm>
#include <cmath>

namespace pilempm::mpm {

const char* drainage_name(Drainage d) {
    switch (d) {
        case Drainage::Dry: return "dry";
        case Drainage::Drained: return "drained";
        case Drainage::Undrained: return "undrained";
        case Drainage::Coupled: return "coupled";
    }
    return "?";
}

SaturatedWaveSpeeds saturated_wave_speeds(double M, double n, double rho_s, const PoreWater& w) {
    const double Kw = w.bulk_modulus, rho_w = w.density, rho_sat = rho_s + n * rho_w;
    SaturatedWaveSpeeds c;
    c.undrained = std::sqrt((M + Kw / n) / rho_sat);
    // 1D v-w without drag, displacements u (solid) and U (water):
    // rho_s u_tt = (M + (1-n)^2 K_w/n) u_xx + (1-n) K_w U_xx, rho_w U_tt = (1-n) K_w/n u_xx + K_w U_xx.
    const double a = (M + (1.0 - n) * (1.0 - n) * Kw / n) / rho_s, b = (1.0 - n) * Kw / rho_s;
    const double cc = (1.0 - n) * Kw / (n * rho_w), d = Kw / rho_w;
    const double tr = a + d, det = a * d - b * cc;
    const double largest = 0.5 * (tr + std::sqrt(std::max(0.0, tr * tr - 4.0 * det)));
    c.fastest = std::max(c.undrained, std::sqrt(largest));
    return c;
}

double skempton_b(double K, double n, double Kw) { return 1.0 / (1.0 + n * K / Kw); }

}  // namespace pilempm::mpm
