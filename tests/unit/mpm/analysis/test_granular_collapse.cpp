// The deposit front (points past an empty cell do not count) and the Lube et al. run-out
// laws the collapse cases are compared with.
#include <gtest/gtest.h>

#include <cmath>

#include "mpm/analysis/granular_collapse.hpp"

using namespace pilempm;

TEST(GranularCollapse, LubeLaws) {
    EXPECT_DOUBLE_EQ(mpm::lube_runout(0.5, false), 0.6);
    EXPECT_DOUBLE_EQ(mpm::lube_runout(4.0, false), 1.9 * std::cbrt(16.0));
    EXPECT_DOUBLE_EQ(mpm::lube_runout(0.5, true), 0.62);
    EXPECT_DOUBLE_EQ(mpm::lube_runout(2.0, true), 1.6 * std::sqrt(2.0));
    // The plane-strain transition joins the two regimes continuously.
    EXPECT_NEAR(mpm::lube_runout(1.8, false), mpm::lube_runout(1.7999999, false), 1e-6);
    EXPECT_NEAR(mpm::lube_runout(2.8, false), mpm::lube_runout(2.8000001, false), 1e-6);
    EXPECT_NEAR(mpm::lube_runout(2.0, false), 2.48, 0.005);
}

TEST(GranularCollapse, DepositFrontStopsAtAnEmptyCell) {
    mpm::MpmModel<2> m;
    m.grid.origin = {0.0, 0.0};
    m.grid.spacing = {0.1, 0.1};
    m.grid.cells = {20, 2};
    const double len[2] = {0.05, 0.05};
    // Points in cells 0..5 (contiguous), then a lone grain in cell 7: cell 6 is empty.
    for (double x : {0.02, 0.13, 0.27, 0.31, 0.44, 0.58, 0.75}) {
        const double pos[2] = {x, 0.02};
        m.particles.add(pos, 1.0, 1.0, len, 0);
    }
    EXPECT_DOUBLE_EQ(mpm::deposit_front<2>(m), 0.58);
    const double bridge[2] = {0.65, 0.02};  // fills cell 6: the grain joins the deposit
    m.particles.add(bridge, 1.0, 1.0, len, 0);
    EXPECT_DOUBLE_EQ(mpm::deposit_front<2>(m), 0.75);
}

// A wedge of points 0.1 m high at x = 0 thinning to nothing at x = 0.4 m: the profile is
// the wedge's thickness per column, in plane strain and (volume per radian) axisymmetry,
// and the front read at 0.02 m is where the wedge is that thin, to one column.
TEST(GranularCollapse, DepositProfileAndThicknessFront) {
    for (bool axisymmetric : {false, true}) {
        mpm::MpmModel<2> m;
        m.axisymmetric = axisymmetric;
        m.grid.origin = {0.0, 0.0};
        m.grid.spacing = {0.01, 0.01};
        m.grid.cells = {60, 12};
        const double h = 0.0025, len[2] = {h, h};
        for (double x = 0.5 * h; x < 0.4; x += h)
            for (double y = 0.5 * h; y < 0.1 * (1.0 - x / 0.4); y += h) {
                const double pos[2] = {x, y};
                const double vol = h * h * (axisymmetric ? x : 1.0);
                m.particles.add(pos, vol, vol, len, 0);
            }
        const auto profile = mpm::deposit_profile(m);
        ASSERT_EQ(profile.size(), 60u);
        for (int k : {5, 15, 25}) {
            const double xc = 0.01 * (k + 0.5), wedge = 0.1 * (1.0 - xc / 0.4);
            EXPECT_NEAR(profile[k], wedge, 0.004) << "column " << k << (axisymmetric ? " axisymmetric" : "");
        }
        EXPECT_EQ(profile[45], 0.0);
        const double front = mpm::thickness_front(m, profile, 0.02);  // wedge 0.02 m thick at 0.32 m
        EXPECT_NEAR(front, 0.32, 0.0101) << (axisymmetric ? "axisymmetric" : "plane strain");
    }
}
