// The drive's conservation check reads the history's mass and volume columns: a grains'
// volume that drifts by 1e-9 (what one step's porosity update missing a volume change of
// the smoothing would leave) fails it; round-off passes; the pore water is only reported.
#include <gtest/gtest.h>

#include "mpm/verification/mpm_checks.hpp"

namespace pm = pilempm::mpm;

namespace {

pilempm::Table history(double grain_drift) {
    pilempm::Table h("history", {"time_s", "soil_mass_kg", "soil_volume_m3", "pore_water_volume_m3"});
    // Soil volume 10, water 4 (grains 6); the water rises by 0.1 (the soil dilates and draws it in).
    h.add_row({0.0, 2000.0, 10.0, 4.0});
    h.add_row({1.0, 2000.0, 10.05, 4.05});
    h.add_row({2.0, 2000.0, 10.1 + 6.0 * grain_drift, 4.1});
    return h;
}

std::vector<pilempm::VerificationCheck> checks(const pilempm::Table& h) {
    pm::MpmCheckContext c;
    c.checks = {"conservation"};
    const pm::MpmModel<2> model;
    return pm::run_mpm_verification<2>(c, model, {}, h);
}

}  // namespace

TEST(ConservationCheck, HoldsRoundOffAndReportsThePoreWater) {
    const auto v = checks(history(1e-15));
    ASSERT_EQ(v.size(), 3u);
    EXPECT_EQ(v[0].name, "soil_mass_largest_change");
    EXPECT_TRUE(v[0].passed);
    EXPECT_EQ(v[0].computed, 0.0);
    EXPECT_TRUE(v[1].passed);
    EXPECT_LT(v[1].computed, 1e-14);
    EXPECT_TRUE(v[2].informative || v[2].passed);
    EXPECT_DOUBLE_EQ(v[2].computed, 4.1);
    EXPECT_DOUBLE_EQ(v[2].reference, 4.0);
}

TEST(ConservationCheck, AGrainVolumeDriftFailsIt) {
    const auto v = checks(history(1e-9));
    EXPECT_FALSE(v[1].passed);
    EXPECT_NEAR(v[1].computed, 1e-9, 1e-12);
}
