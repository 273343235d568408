// The unloading-point method on the record of a rigid pile on an elastic-perfectly plastic
// soil spring (k, R_u) and a dashpot c, loaded by a half-sine, its motion integrated here
// finely: the method must give back R_u at the unloading point and c from the peak load to
// it, and the spring's own curve for the derived static force once it yields.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "coupling/contact/unloading_point.hpp"

using namespace pilempm::coupling;

namespace {

struct Sdof {
    double mass = 2000.0, k = 5.0e8, yield = 1.0e6, c = 2.0e6, peak = 2.0e6, duration = 0.1;
};

// Velocity Verlet (the dashpot at the half step's velocity) at 1e-6 s, every 50th step kept.
RapidLoadRecord integrate(const Sdof& p, std::vector<double>& resistance) {
    const double dt = 1e-6;
    double x = 0.0, v = 0.0, plastic = 0.0;
    auto spring = [&](double at) {  // R(x) with its plastic slip updated
        double r = p.k * (at - plastic);
        if (std::abs(r) > p.yield) plastic = at - std::copysign(p.yield, r) / p.k, r = std::copysign(p.yield, r);
        return r;
    };
    RapidLoadRecord rec;
    double r = 0.0;
    for (long n = 1; n <= 150000; ++n) {
        const double t = n * dt;
        const double f = t < p.duration ? p.peak * std::sin(std::numbers::pi * t / p.duration) : 0.0;
        const double a = (f - r - p.c * v) / p.mass;
        v += a * dt;  // semi-implicit Euler: v_{n+1/2}
        x += v * dt;
        r = spring(x);
        if (n % 50 == 0) {
            rec.time.push_back(t), rec.force.push_back(f), rec.settlement.push_back(x), rec.velocity.push_back(v);
            resistance.push_back(r);
        }
    }
    return rec;
}

}  // namespace

TEST(UnloadingPoint, GivesBackTheSpringsYieldAndTheDashpotOfARigidPile) {
    const Sdof p;
    std::vector<double> resistance;
    const RapidLoadRecord rec = integrate(p, resistance);
    const UnloadingPointResult u = unloading_point(rec, p.mass);
    std::printf("  F_u %.4g N (R_u %.4g), C %.4g N s/m (c %.4g), s_max %.4g m, t_u %.4g s\n", u.static_resistance,
                p.yield, u.damping, p.c, u.max_settlement, u.unloading_time);
    EXPECT_NEAR(u.static_resistance / p.yield, 1.0, 0.005);
    EXPECT_NEAR(u.damping / p.c, 1.0, 0.01);
    // With inertia this small the pile stops as the load falls back to R_u: t = 5 T / 6.
    EXPECT_NEAR(u.unloading_time, 5.0 * p.duration / 6.0, 0.002);
    // The derived static force follows the spring wherever the pile moves (v > 5 % of its peak).
    const auto& s = u.curve.data[6];
    int compared = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (rec.velocity[i] < 0.05 * u.peak_velocity) continue;
        EXPECT_NEAR(s[i], resistance[i], 0.01 * p.yield) << "row " << i;
        ++compared;
    }
    EXPECT_GT(compared, 100);
    // Differences over 1 ms (a pile's wave period, averaging its ringing): as good on this record.
    const UnloadingPointResult smoothed = unloading_point(rec, p.mass, 1e-3);
    EXPECT_NEAR(smoothed.static_resistance / p.yield, 1.0, 0.005);
    EXPECT_NEAR(smoothed.damping / p.c, 1.0, 0.01);
}

TEST(UnloadingPoint, ARecordEndingWithThePileStillMovingDownHasNoUnloadingPoint) {
    RapidLoadRecord r{{0.0, 1.0, 2.0}, {0.0, 1.0, 1.0}, {0.0, 0.1, 0.2}, {0.1, 0.1, 0.1}};
    EXPECT_THROW(unloading_point(r, 1.0), std::invalid_argument);
}
