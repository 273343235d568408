// Every folder's main header compiles on its own (they are what a reader opens first), and
// the per-radian rule converts both ways.
#include <gtest/gtest.h>

#include <cmath>

#include "core/core.hpp"
#include "coupling/coupling.hpp"
#include "fem/fem.hpp"
#include "io/io.hpp"
#include "mpm/mpm.hpp"

TEST(Conventions, PerRadianAndFullRingConvertBothWays) {
    // A ring of radius r and thickness t per radian holds r t; the whole ring 2 pi r t.
    const double r = 2.5, t = 0.07;
    EXPECT_NEAR(pilempm::full_ring(r * t), 2.0 * M_PI * r * t, 1e-15);
    EXPECT_NEAR(pilempm::per_radian(pilempm::full_ring(r * t)), r * t, 1e-15);
}
