// The plug's surface: the top point of each ring, averaged over the rings' areas (ring k of
// n from the axis has area pi (2k + 1) (R / n)^2), so a dome at the axis moves the mean by
// its small share of the area and a ring by the wall by its large one.
#include <gtest/gtest.h>

#include "coupling/contact/plug_surface.hpp"

using pilempm::coupling::PlugSurface;

TEST(PlugSurface, TheMeanLevelWeighsEachRingsTopByItsArea) {
    PlugSurface plug(2.0, 0.5);  // rings 0-0.5, 0.5-1, 1-1.5, 1.5-2 m: areas 1, 3, 5, 7 x pi / 16
    const double tops[4] = {4.0, 3.0, 2.0, 1.0};  // a dome at the axis
    for (int k = 0; k < 4; ++k)
        for (double z = 0.0; z <= tops[k] + 1e-12; z += 0.25) plug.add(0.5 * k + 0.2, z);
    EXPECT_NEAR(plug.mean_level(0.0), (1 * 4.0 + 3 * 3.0 + 5 * 2.0 + 7 * 1.0) / 16.0, 1e-12);  // 1.875
    // The wall's side (r >= 2) and points below the floor count for nothing.
    plug.add(2.0, 9.0);
    plug.add(2.4, 9.0);
    EXPECT_NEAR(plug.mean_level(0.0), 1.875, 1e-12);
    EXPECT_NEAR(plug.mean_level(1.5), (1 * 4.0 + 3 * 3.0 + 5 * 2.0 + 7 * 1.5) / 16.0, 1e-12);
}

TEST(PlugSurface, RingsWithoutPointsAreLeftOutAndAnEmptyPlugIsTheFloor) {
    PlugSurface plug(2.0, 0.5);
    EXPECT_EQ(plug.mean_level(-3.0), -3.0);
    plug.add(0.1, 2.0);  // ring 0, area 1
    plug.add(1.9, 1.0);  // ring 3, area 7
    EXPECT_NEAR(plug.mean_level(0.0), (2.0 + 7 * 1.0) / 8.0, 1e-12);
}

TEST(PlugSurface, AFineGridsRingsAreCappedAndStillCoverThePlug) {
    PlugSurface plug(3.7, 0.01);  // 370 rings asked, 64 kept
    for (int k = 0; k < 640; ++k) plug.add(3.7 * (k + 0.5) / 640.0, 5.0);
    EXPECT_NEAR(plug.mean_level(0.0), 5.0, 1e-12);
    plug.add(3.699, 5.0 + 127.0);  // the outermost ring (area 127 of 64^2 = 4096) one point higher
    EXPECT_NEAR(plug.mean_level(0.0), 5.0 + 127.0 * 127.0 / 4096.0, 1e-9);
}
