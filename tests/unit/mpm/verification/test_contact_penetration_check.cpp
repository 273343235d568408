// Issue 13's bound on the penalty contact's penetration, read from the history: the deepest
// pair over the whole run counts (a single step at 1.2 % of a cell fails the 1 % bound), a
// case may set its own bound, and rows without a value (NaN, before a resume across builds)
// are skipped.
#include <gtest/gtest.h>

#include <limits>

#include "mpm/verification/mpm_checks.hpp"

namespace pm = pilempm::mpm;

namespace {

pilempm::VerificationCheck check(const std::vector<double>& penetration, double bound = -1.0) {
    pilempm::Table h("history", {"time_s", "max_penetration_over_cell"});
    for (std::size_t i = 0; i < penetration.size(); ++i) h.add_row({0.1 * static_cast<double>(i), penetration[i]});
    pm::MpmCheckContext c;
    c.checks = {"contact_penetration"};
    if (bound > 0.0) c.parameters["penetration_tolerance"] = bound;
    const pm::MpmModel<2> model;
    const auto v = pm::run_mpm_verification<2>(c, model, {}, h);
    EXPECT_EQ(v.size(), 1u);
    return v.front();
}

}  // namespace

TEST(ContactPenetrationCheck, TheDeepestStepOfTheRunIsHeldToOnePerCentOfACell) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto within = check({nan, 0.001, 0.0095, 0.004});
    EXPECT_EQ(within.name, "contact_largest_penetration_over_cell");
    EXPECT_TRUE(within.passed);
    EXPECT_DOUBLE_EQ(within.computed, 0.0095);
    EXPECT_DOUBLE_EQ(within.tolerance, 0.01);
    const auto beyond = check({0.001, 0.012, 0.004});
    EXPECT_FALSE(beyond.passed);
    EXPECT_DOUBLE_EQ(beyond.computed, 0.012);
    EXPECT_TRUE(check({0.001, 0.012}, 0.02).passed);
}
