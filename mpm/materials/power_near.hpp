#pragma once
// x^m from a nearby base's power: (x0 (1 + d))^m = x0^m (1 + d)^m with the binomial series of
// (1 + d)^m to d^5, for |d| <= 1e-3 (a stress update's stiffness factor from the last
// decomposition's: pow costs some 60 cycles, this a division and a dozen multiplies). The
// series' remainder, |C(m, 6)| d^6 < 1e-18 for 0 <= m <= 1, is below rounding; farther
// away, or for another m, std::pow.
#include <cmath>

namespace pilempm::mpm {

inline double power_near(double x, double x0, double x0_power_m, double m) {
    const double d = x / x0 - 1.0;
    if (!(std::abs(d) <= 1e-3) || !(m >= 0.0 && m <= 1.0)) return std::pow(x, m);
    const double s = 1.0 + (m - 4.0) / 5.0 * d;
    const double t = 1.0 + (m - 3.0) / 4.0 * d * s;
    const double u = 1.0 + (m - 2.0) / 3.0 * d * t;
    const double v = 1.0 + (m - 1.0) / 2.0 * d * u;
    return x0_power_m * (1.0 + m * d * v);
}

}  // namespace pilempm::mpm
