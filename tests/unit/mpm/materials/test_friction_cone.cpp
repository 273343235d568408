// The friction cone shared by the Cam clay models: M at the triaxial meridians in closed
// form (6 sin phi / (3 -+ sin phi)), a stress inside left alone, one at p' <= 0 zeroed (a
// cohesionless point carries no tension), and the return's removed deviator against the
// triaxial hand value.
#include <gtest/gtest.h>

#include <cmath>

#include "mpm/materials/friction_cone.hpp"

using namespace pilempm::mpm;

TEST(FrictionCone, TriaxialMeridiansInClosedForm) {
    for (double phi : {20.0, 35.0, 45.0}) {
        const double s = std::sin(phi * M_PI / 180.0);
        const FrictionCone mn = FrictionCone::of_angle(phi, false), dp = FrictionCone::of_angle(phi, true);
        EXPECT_NEAR(mn.ratio_at(1.0), 6.0 * s / (3.0 - s), 1e-12) << phi;
        EXPECT_NEAR(mn.ratio_at(-1.0), 6.0 * s / (3.0 + s), 1e-12) << phi;
        EXPECT_EQ(dp.ratio_at(-1.0), dp.ratio_at(1.0)) << phi;
    }
    EXPECT_FALSE(FrictionCone{}.exists());
}

TEST(FrictionCone, InsideUntouchedTensionZeroedOutsideReturned) {
    const FrictionCone cone = FrictionCone::of_angle(30.0, false);  // M_c = 1.2, M_e = 6/7
    double inside[6] = {-100e3, -100e3, -150e3, 0, 0, 0};           // q / p' = 50 / 116.7
    EXPECT_EQ(cone.return_to(inside), 0.0);
    EXPECT_EQ(inside[2], -150e3);
    double tension[6] = {20e3, -5e3, -5e3, 3e3, 0, 0};  // p' = -3.3 kPa
    EXPECT_GT(cone.return_to(tension), 0.0);
    for (double c : tension) EXPECT_EQ(c, 0.0);
    // Triaxial compression, axial along y (a Voigt component): sigma_a 400, sigma_r 100 kPa,
    // p' 200, q 300 > 1.2 p'; back to q = 240 at p' 200, so sigma_a 360, sigma_r 120 and
    // sqrt(2/3) x 60 kPa of deviator removed.
    double outside[6] = {-100e3, -400e3, -100e3, 0, 0, 0};
    EXPECT_NEAR(cone.return_to(outside), std::sqrt(2.0 / 3.0) * 60e3, 1e-6);
    EXPECT_NEAR(outside[1], -360e3, 1e-6);
    EXPECT_NEAR(outside[0], -120e3, 1e-6);
    EXPECT_NEAR(outside[2], -120e3, 1e-6);
}
