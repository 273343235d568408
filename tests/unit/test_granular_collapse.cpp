// The deposit front (points past an empty cell do not count) and the Lube et al. run-out
// laws the collapse cases are compared with.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/granular_collapse.hpp"

using namespace pilempm;

TEST(GranularCollapse, LubeLaws) {
    EXPECT_DOUBLE_EQ(coupling::lube_runout(0.5, false), 0.6);
    EXPECT_DOUBLE_EQ(coupling::lube_runout(4.0, false), 1.9 * std::cbrt(16.0));
    EXPECT_DOUBLE_EQ(coupling::lube_runout(0.5, true), 0.62);
    EXPECT_DOUBLE_EQ(coupling::lube_runout(2.0, true), 1.6 * std::sqrt(2.0));
    // The plane-strain transition joins the two regimes continuously.
    EXPECT_NEAR(coupling::lube_runout(1.8, false), coupling::lube_runout(1.7999999, false), 1e-6);
    EXPECT_NEAR(coupling::lube_runout(2.8, false), coupling::lube_runout(2.8000001, false), 1e-6);
    EXPECT_NEAR(coupling::lube_runout(2.0, false), 2.48, 0.005);
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
    EXPECT_DOUBLE_EQ(coupling::deposit_front<2>(m), 0.58);
    const double bridge[2] = {0.65, 0.02};  // fills cell 6: the grain joins the deposit
    m.particles.add(bridge, 1.0, 1.0, len, 0);
    EXPECT_DOUBLE_EQ(coupling::deposit_front<2>(m), 0.75);
}
