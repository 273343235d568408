// The drivability study: refusal detection, cumulative blows, self-weight penetration.
#include <gtest/gtest.h>

#include <cmath>

#include "sand_pipe_pile.hpp"

using namespace pilempm;
using namespace pilempm::coupling;
using namespace pilempm::fem;

namespace {

DrivabilitySetup small_study() {
    DrivabilitySetup s = sand_pipe_pile();
    s.hammer.kind = HammerKind::RamCushion;
    s.hammer.ram_cushion.ram.mass = 5000.0;
    s.hammer.ram_cushion.impact_velocity = 4.0;
    s.hammer.ram_cushion.hammer_cushion = CushionSpec{3e9, 0.8};
    s.start_depth = 5.0;
    s.final_depth = 20.0;
    s.depth_step = 1.0;
    s.threads = 2;
    return s;
}

}  // namespace

TEST(DrivabilityStudy, CumulativeBlowsAreTheTrapezoidalIntegral) {
    const auto r = run_drivability(small_study());
    ASSERT_EQ(r.runs.size(), 1u);
    const Table& t = r.runs[0].table;
    ASSERT_EQ(t.rows(), 16u);
    double sum = 0.0;
    for (std::size_t i = 1; i < t.rows(); ++i)
        sum += 0.5 * (t.data[5][i] + t.data[5][i - 1]) * (t.data[0][i] - t.data[0][i - 1]) / 0.25;
    EXPECT_NEAR(t.data[6].back(), sum, 1e-9 * sum);
    // Dense sand: the blow count grows with depth overall.
    EXPECT_GT(t.data[5].back(), t.data[5].front());
}

TEST(DrivabilityStudy, RefusalIsTheFirstDepthAboveTheCriterion) {
    auto s = small_study();
    s.driving.refusal_blow_count = 30.0;  // low enough to be reached in this study
    const auto r = run_drivability(s);
    const Table& t = r.runs[0].table;
    double first = -1.0;
    for (std::size_t i = 0; i < t.rows() && first < 0.0; ++i)
        if (t.data[5][i] > 30.0) first = t.data[0][i];
    ASSERT_GT(first, 0.0) << "the study should refuse somewhere";
    EXPECT_DOUBLE_EQ(r.runs[0].refusal_depth, first);
    EXPECT_DOUBLE_EQ(r.runs[0].final_depth_reached, first);
}

TEST(DrivabilityStudy, SelfWeightPenetrationBalancesTheSrd) {
    const auto s = small_study();
    const double weight = 2.0e6;
    const double p = self_weight_penetration(s.soil, SrdMethod::AlmHamre2001, s.coefficients, 1.0, 1.5, 0.025,
                                             weight, 30.0, 0.05);
    const double srd = compute_srd(s.soil, SrdMethod::AlmHamre2001, s.coefficients, 1.5, 0.025, p, 0.05).total();
    EXPECT_NEAR(srd, weight, 0.001 * weight);
}

TEST(DrivabilityStudy, EnergyScalingKeepsTheHammerShape) {
    HammerSpec h;
    h.kind = HammerKind::RamCushion;
    h.ram_cushion.ram.mass = 1000.0;
    h.ram_cushion.impact_velocity = 4.0;
    const auto half = scaled_hammer(h, 0.25);
    EXPECT_DOUBLE_EQ(half.ram_cushion.impact_velocity, 2.0);  // energy x 1/4 -> velocity x 1/2
}

TEST(DrivabilityStudy, EnergyPlanSetsEachDepthsEnergy) {
    // A soft start: 30 % of the energy to 10 m, 100 % from 14 m, linear between. Each
    // depth point must be the blow count of a constant-energy run at the planned level.
    DrivabilitySetup plan = small_study();
    plan.energy_plan_depth = {10.0, 14.0};
    plan.energy_plan_level = {0.3, 1.0};
    EXPECT_DOUBLE_EQ(planned_energy_level(plan, 5.0, 1.0), 0.3);
    EXPECT_DOUBLE_EQ(planned_energy_level(plan, 12.0, 1.0), 0.65);
    EXPECT_DOUBLE_EQ(planned_energy_level(plan, 20.0, 0.8), 0.8);
    const auto r = run_drivability(plan);
    const Table& t = r.runs.front().table;
    const std::size_t level_col = t.columns.size() - 1;
    ASSERT_EQ(t.columns[level_col], "energy_level");
    for (double level : {0.3, 0.65, 1.0}) {
        DrivabilitySetup constant = small_study();
        constant.energy_levels = {level};
        const auto rc = run_drivability(constant);
        const Table& c = rc.runs.front().table;
        for (std::size_t i = 0; i < t.rows(); ++i) {
            if (std::abs(t.data[level_col][i] - level) > 1e-12) continue;
            EXPECT_DOUBLE_EQ(t.data[5][i], c.data[5][i]) << "depth " << t.data[0][i];
        }
    }
    // At 5 m, 30 % of the energy takes more blows than the full energy.
    const auto full = run_drivability(small_study());
    EXPECT_GT(t.data[5][0], full.runs.front().table.data[5][0]);
}
