// The calibrated fast path: fitted to blows of a known Smith soil, the fit finds that soil
// again (its sets and head records, and the parameters the records can tell apart).
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/wave_equation/fast_path_calibration.hpp"
#include "sand_pipe_pile.hpp"

using namespace pilempm;
using namespace pilempm::coupling;

namespace {

// The 30 m pipe pile in dense sand struck by an 8 MN half-sine over 10 ms (a prescribed pulse, as the coupled North Sea case is).
DrivabilitySetup sand_setup() {
    DrivabilitySetup s = sand_pipe_pile();
    s.hammer.kind = fem::HammerKind::PrescribedForce;
    s.hammer.force.peak = 8e6;
    s.hammer.force.duration = 0.01;
    s.threads = 1;
    return s;
}

// "Coupled" blows made by the fast path itself on a soil the fit does not start from.
std::vector<CalibrationTarget> targets_of(const DrivabilitySetup& s, const FastPathSoil& truth) {
    const DrivabilitySetup t = with_soil(s, s.cases.front(), truth, "truth");
    std::vector<CalibrationTarget> out;
    for (double depth : {8.0, 12.0, 15.0}) {
        CalibrationTarget c;
        c.depth = depth;
        const auto p = drive_at_penetration(t.mesh, t.steel, srd_for_driving(t, t.cases.front(), depth), t.smith,
                                            t.hammer, t.ram_element_size, t.driving, &c.record);
        c.set = p.set;
        c.blows = p.blows;
        c.source = "synthetic at " + std::to_string(depth) + " m";
        out.push_back(c);
    }
    return out;
}

}  // namespace

TEST(FastPathCalibration, FindsTheSoilTheBlowsCameFrom) {
    const DrivabilitySetup s = sand_setup();
    FastPathSoil truth = starting_soil(s, s.cases.front());
    truth.srd_factor = 1.4;
    truth.smith.shaft_quake = 5e-3;
    truth.smith.toe_damping = 0.3;
    const auto targets = targets_of(s, truth);
    CalibrationOptions o;
    o.fit = {CalibrationParameter::SrdFactor, CalibrationParameter::ShaftQuake, CalibrationParameter::ToeDamping};
    o.regularisation = 0.0;  // nothing pulls toward the start: the blows alone decide
    const CalibrationResult r = calibrate_fast_path(s, s.cases.front(), targets, o);
    // Started 30-40 % off: the sets miss by tens of percent before the fit.
    EXPECT_GT(r.objective_before, 100.0 * r.objective_after);
    for (const auto& p : r.points) {
        EXPECT_GT(std::abs(p.fast_set_before / p.target.set - 1.0), 0.1) << p.target.source;
        EXPECT_NEAR(p.fast_set_after / p.target.set, 1.0, 0.02) << p.target.source;
        EXPECT_LT(p.record_misfit_after, 0.02) << p.target.source;
    }
    EXPECT_NEAR(r.after.srd_factor, 1.4, 0.05 * 1.4);
    EXPECT_NEAR(r.after.smith.shaft_quake, 5e-3, 0.1 * 5e-3);
    EXPECT_NEAR(r.after.smith.toe_damping, 0.3, 0.1 * 0.3);
    EXPECT_TRUE(r.at_bound.empty());
}

// The pull toward the defaults: strong, it keeps the soil where it started although the
// blows want 40 % more resistance; the objective reported is the misfit plus the pull.
TEST(FastPathCalibration, ThePullTowardTheStartWeighsAgainstTheMisfit) {
    const DrivabilitySetup s = sand_setup();
    FastPathSoil truth = starting_soil(s, s.cases.front());
    truth.srd_factor = 1.4;
    const auto targets = targets_of(s, truth);
    CalibrationOptions o;
    o.fit = {CalibrationParameter::SrdFactor};
    o.regularisation = 0.0;
    const double free_factor = calibrate_fast_path(s, s.cases.front(), targets, o).after.srd_factor;
    EXPECT_NEAR(free_factor, 1.4, 0.01 * 1.4);
    o.regularisation = 100.0;
    const CalibrationResult held = calibrate_fast_path(s, s.cases.front(), targets, o);
    EXPECT_LT(std::abs(std::log(held.after.srd_factor)), 0.05 * std::log(1.4));  // 2 % of the way
    double misfit = 0.0;
    for (const auto& p : held.points)
        misfit += target_misfit(p.target, p.fast_set_after, p.fast_after, held.record_window, false, o.record_weight);
    misfit /= static_cast<double>(held.points.size());
    const double pull = 100.0 * std::pow(std::log(held.after.srd_factor), 2);
    EXPECT_NEAR(held.objective_after, misfit + pull, 1e-9 * held.objective_before);
}

TEST(FastPathCalibration, TheRecordMisfitIsRelativeAndTheSetsIsLogarithmic) {
    CalibrationTarget t;
    t.set = 0.01;
    t.record.time = {0.0, 0.1, 0.2};
    t.record.velocity = {1.0, 2.0, 2.0};
    t.record.force = {0.0, 0.0, 0.0};
    HeadRecord fast;  // sampled at other times: linear between them
    fast.time = {0.0, 0.2};
    fast.velocity = {1.0, 3.0};
    fast.force = {0.0, 0.0};
    double rec = 0.0;
    // Velocity differences 0, 0, 1 over a norm of 1 + 4 + 4 (the window holds all three).
    const double m = target_misfit(t, 0.02, fast, 0.25, false, 2.0, &rec);
    EXPECT_NEAR(rec, std::sqrt(1.0 / 9.0), 1e-12);
    EXPECT_NEAR(m, std::pow(std::log(2.0), 2) + 2.0 / 9.0, 1e-12);
    // A window of the first two samples sees no difference.
    EXPECT_NEAR(target_misfit(t, 0.01, fast, 0.15, false, 1.0, &rec), 0.0, 1e-12);
}
