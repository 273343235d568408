// Removing points keeps every array of the others in step: positions, masses, stresses,
// state variables, materials.
#include <gtest/gtest.h>

#include "mpm/points/particles.hpp"

using namespace pilempm::mpm;

TEST(Particles, KeepOnlyCompactsEveryArrayInOrder) {
    Particles<2> p;
    p.resize_state(3);
    const double len[2] = {0.1, 0.2};
    for (int i = 0; i < 5; ++i) {
        const double x[2] = {1.0 * i, -1.0 * i};
        p.add(x, 10.0 + i, 1.0 + i, len, i % 2);
        p.stress[6 * i + 1] = -100.0 * i;
        p.state[3 * i + 2] = 0.5 * i;
        p.v[2 * i + 1] = 2.0 * i;
    }
    p.keep_only({1, 0, 0, 1, 1});
    ASSERT_EQ(p.size(), 3u);
    const int kept[3] = {0, 3, 4};
    for (int k = 0; k < 3; ++k) {
        const int i = kept[k];
        EXPECT_DOUBLE_EQ(p.x[2 * k], 1.0 * i);
        EXPECT_DOUBLE_EQ(p.x[2 * k + 1], -1.0 * i);
        EXPECT_DOUBLE_EQ(p.mass[k], 10.0 + i);
        EXPECT_DOUBLE_EQ(p.volume0[k], 1.0 + i);
        EXPECT_DOUBLE_EQ(p.stress[6 * k + 1], -100.0 * i);
        EXPECT_DOUBLE_EQ(p.state[3 * k + 2], 0.5 * i);
        EXPECT_DOUBLE_EQ(p.v[2 * k + 1], 2.0 * i);
        EXPECT_EQ(p.material[k], i % 2);
        EXPECT_DOUBLE_EQ(p.domain0[4 * k + 3], 0.2);
    }
    EXPECT_EQ(p.F.size(), 12u);
    EXPECT_EQ(p.porosity.size(), 3u);
    EXPECT_EQ(p.field.size(), 3u);
}
