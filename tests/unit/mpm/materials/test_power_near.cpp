// The stiffness factor's power from a nearby one: within a few ulp of std::pow over bases
// from 1e-3 to 1e3, exponents 0 to 1 and relative distances up to the series' 1e-3; pow
// itself beyond.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mpm/materials/power_near.hpp"

using pilempm::mpm::power_near;

TEST(PowerNear, MatchesPowToRounding) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> log_base(-3.0, 3.0), exponent(0.0, 1.0), step(-1e-3, 1e-3);
    double worst = 0.0;
    for (int k = 0; k < 200000; ++k) {
        const double x0 = std::pow(10.0, log_base(rng)), m = k % 10 == 0 ? (k % 20 == 0 ? 0.0 : 1.0) : exponent(rng);
        const double x = x0 * (1.0 + step(rng));
        const double exact = std::pow(x, m);
        worst = std::max(worst, std::abs(power_near(x, x0, std::pow(x0, m), m) / exact - 1.0));
    }
    EXPECT_LT(worst, 1e-15);  // a few ulp (2.2e-16 each)
}

TEST(PowerNear, FarBasesFallBackToPow) {
    EXPECT_EQ(power_near(2.0, 1.0, 1.0, 0.5), std::pow(2.0, 0.5));
    EXPECT_EQ(power_near(1.0011, 1.0, 1.0, 0.45), std::pow(1.0011, 0.45));
    EXPECT_EQ(power_near(1.0005, 1.0, 1.0, 1.5), std::pow(1.0005, 1.5));  // m outside [0, 1]
}
