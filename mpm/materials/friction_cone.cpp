#include "mpm/materials/friction_cone.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mpm/materials/critical_state_common.hpp"

namespace pilempm::mpm {

using critical_state::deviator_q;
using critical_state::mean_pressure;

FrictionCone FrictionCone::of_angle(double degrees, bool circular) {
    const double s = std::sin(degrees * std::numbers::pi / 180.0);
    return {6.0 * s / (3.0 - s), (9.0 - s * s) / (1.0 - s * s), std::pow((3.0 - s) / (3.0 + s), 4), circular};
}

// Matsuoka-Nakai at stress ratio eta and c = cos 3theta: I1 I2 = k I3 with I1 = 3p,
// I2 = 3p^2 - q^2/3, I3 = p^3 - p q^2/3 + 2 c q^3/27 gives, divided by p^3,
//   g(eta) = (k - 9) + (1 - k/3) eta^2 + (2 k c / 27) eta^3 = 0.
// Halley's method from Sheng et al.'s (2000) fit, which is exact at c = +-1: 2 iterations to
// round-off up to phi = 50 deg.
double FrictionCone::ratio_at(double c) const {
    if (circular) return M_c;
    c = std::clamp(c, -1.0, 1.0);
    double eta = M_c * std::sqrt(std::sqrt(2.0 * alpha4 / (1.0 + alpha4 - (1.0 - alpha4) * c)));
    const double A = 2.0 * k * c / 27.0, B = 1.0 - k / 3.0, C = k - 9.0;
    for (int it = 0; it < 20; ++it) {  // Halley: the error is cubed each time
        const double g = C + eta * eta * (B + A * eta), g1 = eta * (2.0 * B + 3.0 * A * eta), g2 = 2.0 * B + 6.0 * A * eta;
        const double d = 2.0 * g * g1 / (2.0 * g1 * g1 - g * g2);
        eta -= d;
        if (std::abs(d) < 1e-5 * eta) break;  // the next error ~ d^3: at round-off
    }
    return eta;
}

double lode_cos3theta(const double* st) {
    const double p = mean_pressure(st), q = deviator_q(st, p);
    if (!(q > 0.0)) return 0.0;
    const double xx = st[0] + p, yy = st[1] + p, zz = st[2] + p, xy = st[3], yz = st[4], zx = st[5];
    const double J3 = xx * (yy * zz - yz * yz) - xy * (xy * zz - yz * zx) + zx * (xy * yz - yy * zx);
    return std::clamp(-13.5 * J3 / (q * q * q), -1.0, 1.0);  // tension-positive deviator
}

double FrictionCone::return_to(double* s) const {
    const double p = mean_pressure(s);
    const double dev[6] = {s[0] + p, s[1] + p, s[2] + p, s[3], s[4], s[5]};
    const double q = deviator_q(s, p);
    if (!(p > 0.0)) {
        std::fill(s, s + 6, 0.0);
        return std::sqrt(2.0 / 3.0) * q;
    }
    const double M = ratio_at(lode_cos3theta(s));
    if (q <= M * p) return 0.0;
    const double keep = M * p / q;
    for (int i = 0; i < 3; ++i) s[i] = -p + keep * dev[i];
    for (int i = 3; i < 6; ++i) s[i] = keep * dev[i];
    return (1.0 - keep) * std::sqrt(2.0 / 3.0) * q;  // |dev| = sqrt(2/3) q
}

}  // namespace pilempm::mpm
