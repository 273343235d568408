// A history resumed from an earlier build's checkpoint: the shaft's total resistance, which
// that build did not record, is the outer plus the inner shaft's in its rows (so the blows
// it drove keep their peak shaft resistance); rows recorded since keep theirs.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "coupling/contact/pile_recorder.hpp"

TEST(PileHistory, AnEarlierBuildsRowsGetTheShaftsTotalFromItsTwoSides) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    pilempm::Table h("history", {"time_s", "outer_shaft_resistance_N", "inner_shaft_resistance_N", "shaft_resistance_N"});
    h.add_row({0.0, 3.0, 4.0, nan});
    h.add_row({0.1, -1.5, 2.0, nan});
    h.add_row({0.2, 5.0, 6.0, 10.0});  // recorded: kept as it is
    pilempm::coupling::complete_pile_history(h);
    EXPECT_DOUBLE_EQ(h.data[3][0], 7.0);
    EXPECT_DOUBLE_EQ(h.data[3][1], 0.5);
    EXPECT_DOUBLE_EQ(h.data[3][2], 10.0);
    pilempm::Table other("history", {"time_s", "shaft_resistance_N"});  // no sides: nothing to derive
    other.add_row({0.0, nan});
    pilempm::coupling::complete_pile_history(other);
    EXPECT_TRUE(std::isnan(other.data[1][0]));
}
