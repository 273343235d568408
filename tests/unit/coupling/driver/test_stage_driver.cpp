// The stage driver without the executable: loads switched per stage with stage-relative
// times (a pulse's impulse against p A T), a quasi-static stage that relaxes and ends at
// rest, and a run stopped by a real signal and resumed from what the observer checkpointed
// (driver state, solver clock, history, particles) that ends exactly as an uninterrupted one.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <memory>

#include "coupling/driver/stage_driver.hpp"
#include "mpm/setup/model_setup.hpp"

using namespace pilempm;
using namespace pilempm::coupling;

namespace {

constexpr double kWidth = 0.4, kHeight = 1.0, kDensity = 2000.0;

// An elastic block kWidth x kHeight with its lower left corner at `corner`, on a 0.1 m grid
// of `cells`, no gravity, no supports: a free body.
mpm::MpmModel<2> block(std::array<double, 2> corner = {0.2, 0.2}, std::array<int, 2> cells = {8, 16}) {
    mpm::MpmModel<2> m;
    m.grid.origin = {0.0, 0.0};
    m.grid.spacing = {0.1, 0.1};
    m.grid.cells = cells;
    m.grid.allocate();
    m.flip = 1.0;
    m.materials.push_back(std::make_unique<mpm::LinearElastic>(20e6, 0.3));
    mpm::fill_region<2>(m.grid, m.particles, [corner](const double* x) {
        return x[0] > corner[0] && x[0] < corner[0] + kWidth && x[1] > corner[1] && x[1] < corner[1] + kHeight;
    }, 2, kDensity, 0, false);
    return m;
}

// A pressure p on the top face (outward normal +y), the force -p A split over the top row.
std::vector<StageLoad> top_pressure(const mpm::MpmModel<2>& m, double p, double duration, std::vector<int> stages) {
    std::vector<StageLoad> loads;
    const auto& pts = m.particles;
    double top = -1e300;
    for (std::size_t i = 0; i < pts.size(); ++i) top = std::max(top, pts.x[2 * i + 1] + 0.5 * pts.domain0[4 * i + 3]);
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const double half = 0.5 * pts.domain0[4 * i + 3];
        if (pts.x[2 * i + 1] + half < top - 1e-9) continue;
        StageLoad l;
        l.load.point = static_cast<int>(i);
        l.load.offset[1] = half;
        l.load.force[1] = -p * pts.domain0[4 * i + 0];
        l.duration = duration;
        l.stages = stages;
        loads.push_back(l);
    }
    return loads;
}

StageSpec dynamic(const char* name, double duration) {
    StageSpec s;
    s.name = name;
    s.duration = duration;
    return s;
}

// A blow of drive 0.
StageSpec blow(double duration) {
    StageSpec b = dynamic("blow", duration);
    b.blow = true;
    b.drive = 0;
    return b;
}

double momentum_y(const StageDriver<2>& d) { return d.solver().momentum()[1]; }

}  // namespace

// A pulse switched on in the second stage only acts there, from that stage's start: the
// impulse is p A T (to within one step, the pulse ends between steps), against zero for a
// pulse timed from the start of the run.
TEST(StageDriver, PulseTimesCountFromTheStageStart) {
    const double p = 50e3, T = 0.01;
    for (int acts_in_both : {0, 1}) {
        mpm::MpmModel<2> m = block();
        const auto loads = top_pressure(m, p, T, acts_in_both ? std::vector<int>{} : std::vector<int>{1});
        StageDriver<2> driver(m, {dynamic("rest", 0.03), dynamic("blow", 0.03)}, loads, {});
        const double dt = driver.solver().stable_time_step();
        ASSERT_LT(dt, T / 20);
        driver.run();
        const double expected = -p * kWidth * T * (acts_in_both ? 2 : 1);
        EXPECT_NEAR(momentum_y(driver), expected, p * kWidth * dt * (acts_in_both ? 2 : 1))
            << (acts_in_both ? "pulse in both stages" : "pulse in the second stage");
    }
}

// A held load acts only in the stages it names; with none it acts in all.
TEST(StageDriver, HeldLoadsActInTheirStagesOnly) {
    mpm::MpmModel<2> m = block();
    const double p = 10e3;
    StageDriver<2> driver(m, {dynamic("first", 0.02), dynamic("second", 0.01)}, top_pressure(m, p, 0.0, {1}), {});
    driver.run();
    // Only the second stage's 0.01 s of push.
    EXPECT_NEAR(momentum_y(driver), -p * kWidth * 0.01, 1e-9 * p * kWidth);
}

// A quasi-static stage under a held load relaxes (local damping) to equilibrium: the base
// carries p A; the stage leaves the body at rest with the clock where the stage began.
TEST(StageDriver, QuasiStaticStageRelaxesToEquilibriumAndEndsAtRest) {
    mpm::MpmModel<2> m = block({0.2, 0.0});
    mpm::apply_boundary<2>(m.grid, 1, 0, mpm::BoundaryKind::Roller);
    std::vector<int> base;
    for (int n = 0; n < m.grid.num_nodes(); ++n)
        if (m.grid.ijk(n)[1] == 0) base.push_back(n);
    StageSpec relax;
    relax.name = "relax";
    relax.quasi_static = true;
    relax.local_damping = 0.7;
    relax.tolerance = 1e-6;
    relax.max_steps = 20000;
    const double p = 20e3;
    StageDriver<2> driver(m, {relax}, top_pressure(m, p, 0.0, {}), {});
    driver.add_recorder(std::make_unique<EnergyRecorder<2>>());
    driver.add_recorder(std::make_unique<ReactionRecorder<2>>(base));
    driver.run();
    const Table& h = driver.history();
    EXPECT_LT(h.data[6].back(), 1e-3) << "unbalanced force ratio";
    // The roller base pushes up with the load on top (the last step's reaction).
    double reaction = 0.0;
    for (int n : base) reaction += m.grid.find_condition(n)->reaction[1];
    EXPECT_NEAR(reaction, p * kWidth, 1e-3 * p * kWidth);
    EXPECT_EQ(driver.solver().time(), 0.0);
    for (double v : m.particles.v) ASSERT_EQ(v, 0.0);
}

// A stage's gravity factor (n g in a centrifuge): the roller base of a block carries its
// weight at 1 g after the first quasi-static stage and n times it after a second at n = 4.
TEST(StageDriver, GravityFactorScalesTheWeightPerStage) {
    mpm::MpmModel<2> m = block({0.2, 0.0});
    m.gravity = {0.0, -9.81};
    mpm::apply_boundary<2>(m.grid, 1, 0, mpm::BoundaryKind::Roller);
    std::vector<int> base;
    for (int n = 0; n < m.grid.num_nodes(); ++n)
        if (m.grid.ijk(n)[1] == 0) base.push_back(n);
    StageSpec one;
    one.name = "1g";
    one.quasi_static = true;
    one.local_damping = 0.7;
    one.tolerance = 1e-7;
    one.max_steps = 40000;
    StageSpec four = one;
    four.name = "4g";
    four.gravity_factor = 4.0;
    const double weight = kDensity * 9.81 * kWidth * kHeight;  // per unit thickness
    auto reaction = [&] {
        double r = 0.0;
        for (int n : base) r += m.grid.find_condition(n)->reaction[1];
        return r;
    };
    StageDriver<2> first(m, {one}, {}, {});
    first.run();
    EXPECT_NEAR(reaction(), weight, 1e-3 * weight);
    StageDriver<2> second(m, {four}, {}, {});
    second.run();
    EXPECT_NEAR(reaction(), 4.0 * weight, 4e-3 * weight);
    EXPECT_DOUBLE_EQ(m.gravity[1], -4.0 * 9.81);
}

namespace {

// Keeps the last checkpoint in memory: everything a resumed run needs.
struct MemoryCheckpoint final : StageObserver<2> {
    mpm::Particles<2> particles;
    DriverState state;
    mpm::SolverState solver;
    Table history;
    int taken = 0;
    void checkpoint(const DriverState& s, const mpm::MpmModel<2>& m, const mpm::MpmSolver<2>& solver,
                    const Table& h) override {
        particles = m.particles;
        state = s;
        this->solver = solver.state();
        history = h;
        ++taken;
    }
};

// A column on a roller base under gravity, a roller at x = 0 and an absorbing side at x_max
// (which the blow's lateral motion does work on).
mpm::MpmModel<2> column_with_absorbing_side() {
    mpm::MpmModel<2> m = block({0.0, 0.0}, {4, 16});
    m.gravity = {0.0, -9.81};
    mpm::apply_boundary<2>(m.grid, 1, 0, mpm::BoundaryKind::Roller);
    mpm::apply_boundary<2>(m.grid, 0, 0, mpm::BoundaryKind::Roller);
    mpm::apply_boundary<2>(m.grid, 0, 1, mpm::BoundaryKind::Absorbing, kDensity, 116.0, 62.0);
    return m;
}

std::vector<StageSpec> settle_then_blow(int record_every = 1) {
    StageSpec settle;
    settle.name = "settle";
    settle.quasi_static = true;
    settle.local_damping = 0.7;
    settle.max_steps = 400;
    settle.tolerance = 1e-12;  // runs all its steps: a stop lands inside it
    StageSpec blow = dynamic("blow", 0.02);
    blow.record_every = record_every;
    blow.min_duration = 0.002;  // every row while the pulse acts
    return {settle, blow};
}

void add_recorders(StageDriver<2>& d) {
    d.add_recorder(std::make_unique<EnergyRecorder<2>>());
    d.add_recorder(std::make_unique<ProbeRecorder<2>>(std::vector<int>{0, 5}));
}

void expect_same_table(const Table& a, const Table& b) {
    ASSERT_EQ(a.columns, b.columns);
    ASSERT_EQ(a.rows(), b.rows());
    for (std::size_t r = 0; r < a.rows(); ++r)
        for (std::size_t c = 0; c < a.columns.size(); ++c) {
            if (std::isnan(a.data[c][r]) && std::isnan(b.data[c][r])) continue;
            ASSERT_EQ(a.data[c][r], b.data[c][r]) << a.name << " " << a.columns[c] << " row " << r;
        }
}

// Runs the column's stages until a real SIGINT after `stop_after` steps; `saved` then holds
// the checkpoint it left. `every_recorder`: energy and probes, else energy only.
void interrupt(long stop_after, int record_every, bool every_recorder, MemoryCheckpoint& saved) {
    mpm::MpmModel<2> m = column_with_absorbing_side();
    StageDriver<2> first(m, settle_then_blow(record_every), top_pressure(m, 20e3, 0.005, {1}), {}, &saved);
    if (every_recorder)
        add_recorders(first);
    else
        first.add_recorder(std::make_unique<EnergyRecorder<2>>());
    ::setenv("PILEMPM_INTERRUPT_AFTER_STEPS", std::to_string(stop_after).c_str(), 1);
    ::unsetenv("PILEMPM_INTERRUPT_SIGNAL");
    const StopRequest stop(true);
    const auto outcome = first.run(&stop);
    ::unsetenv("PILEMPM_INTERRUPT_AFTER_STEPS");
    ASSERT_EQ(outcome, StageDriver<2>::Outcome::Stopped);
}

// Interrupts with a real SIGINT after `stop_after` steps, resumes in a new model from the
// checkpoint, and compares the history, the stages' extremes and the final state with an
// uninterrupted run. The blow stores every `record_every`-th row.
void check_resume(long stop_after, int record_every = 1) {
    mpm::MpmModel<2> whole_model = column_with_absorbing_side();
    StageDriver<2> whole(whole_model, settle_then_blow(record_every), top_pressure(whole_model, 20e3, 0.005, {1}), {});
    add_recorders(whole);
    whole.run();

    MemoryCheckpoint saved;
    ASSERT_NO_FATAL_FAILURE(interrupt(stop_after, record_every, true, saved));
    ASSERT_EQ(saved.solver.steps, stop_after);

    // As the job does: the run is built from the case, then the checkpoint's points replace
    // the fresh ones.
    mpm::MpmModel<2> resumed_model = column_with_absorbing_side();
    const auto loads = top_pressure(resumed_model, 20e3, 0.005, {1});
    resumed_model.particles = saved.particles;
    StageDriver<2> resumed(resumed_model, settle_then_blow(record_every), loads, {});
    add_recorders(resumed);
    resumed.resume(saved.state, saved.solver, saved.history);
    ASSERT_EQ(resumed.run(), StageDriver<2>::Outcome::Completed);

    expect_same_table(whole.history(), resumed.history());
    ASSERT_EQ(whole.extremes().rows(), 2u);
    expect_same_table(whole.extremes(), resumed.extremes());
    EXPECT_GT(whole.solver().absorbed_energy(), 0.0);
    EXPECT_EQ(whole.solver().absorbed_energy(), resumed.solver().absorbed_energy());
    EXPECT_EQ(whole.solver().external_work(), resumed.solver().external_work());
    for (std::size_t i = 0; i < whole_model.particles.x.size(); ++i)
        ASSERT_EQ(whole_model.particles.x[i], resumed_model.particles.x[i]);
    for (std::size_t i = 0; i < whole_model.particles.stress.size(); ++i)
        ASSERT_EQ(whole_model.particles.stress[i], resumed_model.particles.stress[i]);
}

}  // namespace

TEST(StageDriver, StoppedInAQuasiStaticStageAndResumedEqualsUninterrupted) { check_resume(150); }
TEST(StageDriver, StoppedInADynamicStageAndResumedEqualsUninterrupted) { check_resume(420); }
TEST(StageDriver, StoppedInADecimatedStageAndResumedEqualsUninterrupted) { check_resume(423, 7); }
// A checkpoint without the stages' extremes (a build before they were kept) cannot give a
// resumed drive its exact peaks: refused, with the reason, instead of resumed.
TEST(StageDriver, ACheckpointWithoutExtremesIsRefused) {
    MemoryCheckpoint saved;
    ASSERT_NO_FATAL_FAILURE(interrupt(150, 1, true, saved));
    mpm::MpmModel<2> resumed_model = column_with_absorbing_side();
    const auto loads = top_pressure(resumed_model, 20e3, 0.005, {1});
    resumed_model.particles = saved.particles;
    StageDriver<2> resumed(resumed_model, settle_then_blow(1), loads, {});
    add_recorders(resumed);
    saved.state.extremes = Table();
    try {
        resumed.resume(saved.state, saved.solver, saved.history);
        FAIL() << "resumed without extremes";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("extremes"), std::string::npos) << e.what();
    }
}

// A blow that stores every 7th row: its rows are the full-rate run's at those steps, every
// step's while the pulse acts and its last; its extremes are those of every step all the
// same (the full-rate run's to the bit), so a drive's peaks do not depend on the decimation.
TEST(StageDriver, ADecimatedStageStoresEveryNthRowAndKeepsTheExactExtremes) {
    auto run = [](int record_every) {
        mpm::MpmModel<2> m = column_with_absorbing_side();
        auto d = std::make_unique<StageDriver<2>>(m, settle_then_blow(record_every), top_pressure(m, 20e3, 0.005, {1}),
                                                  DriverSettings{});
        add_recorders(*d);
        d->run();
        return std::make_pair(d->history(), d->extremes());
    };
    const auto [full, full_extremes] = run(1);
    const auto [sparse, sparse_extremes] = run(7);
    expect_same_table(full_extremes, sparse_extremes);
    const auto& full_step = full.column("step");
    const auto& sparse_step = sparse.column("step");
    const auto& full_time = full.column("time_s");
    const auto& stage = full.column("stage");
    std::size_t blow_rows = 0, expected = 0, j = 0;
    const std::size_t first = static_cast<std::size_t>(std::find(stage.begin(), stage.end(), 2.0) - stage.begin());
    ASSERT_GT(first, 0u);
    const double start = full_time[first - 1];  // the settling's clock stands at the blow's start
    for (std::size_t r = first; r < full.rows(); ++r) {
        const std::size_t n = r - first + 1;                // the blow's step count after this step
        const double in_stage = full_time[r - 1] - start;  // before this step
        const bool due = n % 7 == 0 || r + 1 == full.rows() || in_stage < 0.002;
        if (!due) continue;
        ++expected;
        while (j < sparse.rows() && sparse_step[j] < full_step[r]) ++j;
        ASSERT_LT(j, sparse.rows());
        ASSERT_EQ(sparse_step[j], full_step[r]);
        for (std::size_t c = 0; c < full.columns.size(); ++c) ASSERT_EQ(sparse.data[c][j], full.data[c][r]) << full.columns[c];
    }
    for (double st : sparse.column("stage")) blow_rows += st == 2.0 ? 1 : 0;
    EXPECT_EQ(blow_rows, expected);
    EXPECT_LT(blow_rows, full_step.back() / 3);  // far fewer than the stage's steps
}

// A checkpoint of an earlier build that recorded fewer columns (here: no probes) resumes
// with this build's: the old rows keep their values, the new columns are NaN up to the
// resume and recorded after it; a column this run does not record is an error.
TEST(StageDriver, ACheckpointWithFewerColumnsResumesWithTheNewOnesEmpty) {
    MemoryCheckpoint saved;
    ASSERT_NO_FATAL_FAILURE(interrupt(150, 1, false, saved));
    const std::size_t old_rows = saved.history.rows();
    ASSERT_GT(old_rows, 0u);

    mpm::MpmModel<2> resumed_model = column_with_absorbing_side();
    const auto loads = top_pressure(resumed_model, 20e3, 0.005, {1});
    resumed_model.particles = saved.particles;
    StageDriver<2> resumed(resumed_model, settle_then_blow(), loads, {});
    add_recorders(resumed);  // energy and probes
    resumed.resume(saved.state, saved.solver, saved.history);
    ASSERT_EQ(resumed.run(), StageDriver<2>::Outcome::Completed);
    const Table& h = resumed.history();
    const auto column = [&](const std::string& name) -> const std::vector<double>& {
        return h.data[static_cast<std::size_t>(std::find(h.columns.begin(), h.columns.end(), name) - h.columns.begin())];
    };
    const auto& probe = column("probe0_stress_vertical_Pa");
    const auto& kinetic = column("kinetic_energy_J");
    ASSERT_GT(h.rows(), old_rows);
    EXPECT_TRUE(std::isnan(probe[old_rows - 1]));
    EXPECT_FALSE(std::isnan(probe[old_rows]));
    const auto at = std::find(saved.history.columns.begin(), saved.history.columns.end(), "kinetic_energy_J");
    const auto& saved_kinetic = saved.history.data[static_cast<std::size_t>(at - saved.history.columns.begin())];
    for (std::size_t r = 0; r < old_rows; ++r) ASSERT_EQ(kinetic[r], saved_kinetic[r]) << "row " << r;

    Table unknown = saved.history;
    unknown.columns.push_back("a_column_no_recorder_writes");
    unknown.data.emplace_back(old_rows, 0.0);
    StageDriver<2> refused(resumed_model, settle_then_blow(), loads, {});
    add_recorders(refused);
    EXPECT_THROW(refused.resume(saved.state, saved.solver, unknown), std::runtime_error);
}

namespace {

// A body that sinks `set` metres on the first step of every blow, `creep` on the first step
// of every pause of a drive, and is otherwise at rest.
class SinkingBody final : public CoupledBody<2> {
public:
    SinkingBody(const std::vector<StageSpec>& stages, double set, double creep = 0.0)
        : stages_(stages), set_(set), creep_(creep) {}
    double stable_time_step(const mpm::MpmModel<2>&, double soil_dt) const override { return soil_dt; }
    void before_step(mpm::MpmModel<2>&, int stage, bool, double, double time_in_stage) override {
        if (time_in_stage != 0.0) return;
        if (stages_[stage].blow) toe_ -= set_;
        else if (stages_[stage].drive >= 0) toe_ -= creep_;
    }
    void come_to_rest() override {}
    void set_gravity_factor(double) override {}
    double max_speed() const override { return 0.0; }
    double toe_elevation() const override { return toe_; }
    std::vector<std::pair<std::string, std::vector<double>>> state() const override { return {}; }
    void restore(const std::vector<std::pair<std::string, std::vector<double>>>&) override {}

private:
    std::vector<StageSpec> stages_;
    double set_, creep_;
    double toe_ = 1.0;
};

// The sets a driver reports at each blow's end.
class SetsSeen final : public StageObserver<2> {
public:
    void stage_end(int, const StageSpec& spec, const StageReport& report) override {
        if (spec.blow) sets.push_back(report.set);
    }
    std::vector<double> sets;
};

// Five blows of a drive (each ends once the body is at rest after 2 ms, not at its 10 ms),
// then a stage after it; the stages the history saw.
std::vector<double> drive_stages_run(double set, double target, double refusal_set, int refusal_blows,
                                     double& first_blow_end) {
    auto m = block();
    std::vector<StageSpec> stages;
    for (int k = 0; k < 5; ++k) {
        StageSpec b = blow(0.01);
        b.rest_speed = 1e-3;
        b.min_duration = 0.002;
        b.end_toe_elevation = target;
        b.refusal_set = refusal_set;
        b.refusal_blows = refusal_blows;
        stages.push_back(b);
    }
    stages.push_back(dynamic("after", 0.001));
    SinkingBody body(stages, set);
    StageDriver<2> d(m, stages, {}, {});
    d.couple(&body);
    d.run();
    const auto& stage = d.history().data[2];
    const auto& time = d.history().data[0];
    std::vector<double> seen;
    first_blow_end = 0.0;
    for (std::size_t i = 0; i < stage.size(); ++i) {
        if (seen.empty() || seen.back() != stage[i]) seen.push_back(stage[i]);
        if (stage[i] == 1.0) first_blow_end = time[i];
    }
    return seen;
}

}  // namespace

// A drive ends when the toe reaches its target: three blows of 10 mm from 1.0 m reach
// 0.975 m, and the run goes on with the stage after the drive; each blow ends once the body
// is at rest after its shortest duration (2 ms and a step), not at its 10 ms.
TEST(StageDriver, ADriveEndsAtItsTargetDepth) {
    double end = 0.0;
    EXPECT_EQ(drive_stages_run(0.01, 0.975, 0.0, 0, end), (std::vector<double>{1, 2, 3, 6}));
    EXPECT_GE(end, 0.002);
    EXPECT_LT(end, 0.003);
}

// Refusal: two blows in a row each setting the pile less than 2 mm end the drive.
TEST(StageDriver, ADriveEndsAtRefusal) {
    double end = 0.0;
    EXPECT_EQ(drive_stages_run(0.001, -1e300, 0.002, 2, end), (std::vector<double>{1, 2, 6}));
    EXPECT_EQ(drive_stages_run(0.003, -1e300, 0.002, 2, end), (std::vector<double>{1, 2, 3, 4, 5, 6}));
}

// A blow's set counts from where the last blow left the toe, as it is read in the field and
// blows.csv counts it: 4 mm blows with 1 mm of creep in each pause report 4, 5, 5 mm.
TEST(StageDriver, ABlowsSetTakesThePausesCreepBeforeIt) {
    auto m = block();
    std::vector<StageSpec> stages;
    for (int k = 0; k < 3; ++k) {
        StageSpec pause = dynamic("pause", 0.001);
        pause.drive = 0;
        stages.push_back(blow(0.002));
        stages.push_back(pause);
    }
    SinkingBody body(stages, 0.004, 0.001);
    SetsSeen seen;
    StageDriver<2> d(m, stages, {}, {}, &seen);
    d.couple(&body);
    d.run();
    ASSERT_EQ(seen.sets.size(), 3u);
    EXPECT_NEAR(seen.sets[0], 0.004, 1e-15);
    EXPECT_NEAR(seen.sets[1], 0.005, 1e-15);
    EXPECT_NEAR(seen.sets[2], 0.005, 1e-15);
    EXPECT_NEAR(d.state().last_blow_end_toe, 1.0 - 3 * 0.004 - 2 * 0.001, 1e-15);
}

// A blow with settle_damping: undamped while its wave runs (min_duration), then the soil's
// local damping and the body's settling both at settle_damping; the stage after starts
// without either.
TEST(StageDriver, ABlowSettlesOnceItsWaveHasPassed) {
    struct Seen {
        double time_in_stage, soil_damping, body_damping;
        int stage;
    };
    class SettlingBody final : public CoupledBody<2> {
    public:
        std::vector<Seen> seen;
        double alpha = 0.0;
        double stable_time_step(const mpm::MpmModel<2>&, double soil_dt) const override { return soil_dt; }
        void before_step(mpm::MpmModel<2>& m, int stage, bool, double, double time_in_stage) override {
            seen.push_back({time_in_stage, m.local_damping, alpha, stage});
        }
        void come_to_rest() override {}
        void set_gravity_factor(double) override {}
        void set_settling(double a) override { alpha = a; }
        double max_speed() const override { return 1.0; }  // never at rest
        double toe_elevation() const override { return 1.0; }
        std::vector<std::pair<std::string, std::vector<double>>> state() const override { return {}; }
        void restore(const std::vector<std::pair<std::string, std::vector<double>>>&) override {}
    };
    auto m = block();
    StageSpec b = dynamic("blow", 0.004);
    b.blow = true;
    b.rest_speed = 1e-3;
    b.min_duration = 0.002;
    b.settle_damping = 0.6;
    const std::vector<StageSpec> stages{b, dynamic("after", 0.001)};
    SettlingBody body;
    StageDriver<2> d(m, stages, {}, {});
    d.couple(&body);
    d.run();
    int settled = 0, before = 0;
    for (const Seen& s : body.seen) {
        const bool settling = s.stage == 0 && s.time_in_stage >= 0.002;
        EXPECT_EQ(s.soil_damping, settling ? 0.6 : 0.0) << "stage " << s.stage << " at " << s.time_in_stage;
        EXPECT_EQ(s.body_damping, settling ? 0.6 : 0.0) << "stage " << s.stage << " at " << s.time_in_stage;
        settled += settling;
        before += s.stage == 0 && !settling;
    }
    EXPECT_GT(settled, 0);
    EXPECT_GT(before, 0);
}

// A pile bouncing on the soil passes through zero speed at the top of every bounce: here
// it dwells below rest_speed for 0.4 ms of every 2 ms until 10 ms, then rests. The blow
// must end once it has been slow for rest_span (1 ms) on end, after the bouncing; taken at
// rest at the first dwell (rest_span 0) it would end at 2 ms, the bounce still to come
// (the loose-sand case's sets then alternated, some negative).
TEST(StageDriver, ABlowIsNotAtRestAtTheTopOfABounce) {
    class BouncingBody final : public CoupledBody<2> {
    public:
        double t = 0.0;
        int stage = 0;
        double stable_time_step(const mpm::MpmModel<2>&, double soil_dt) const override { return soil_dt; }
        void before_step(mpm::MpmModel<2>&, int s, bool, double, double time_in_stage) override {
            t = time_in_stage, stage = s;
        }
        void come_to_rest() override {}
        void set_gravity_factor(double) override {}
        double max_speed() const override { return t < 0.01 && std::fmod(t, 0.002) > 0.0004 ? 0.1 : 0.0; }
        double toe_elevation() const override { return 1.0; }
        std::vector<std::pair<std::string, std::vector<double>>> state() const override { return {}; }
        void restore(const std::vector<std::pair<std::string, std::vector<double>>>&) override {}
    };
    auto blow_end = [](double rest_span) {
        auto m = block();
        StageSpec b = dynamic("blow", 0.02);
        b.blow = true;
        b.rest_speed = 1e-3;
        b.min_duration = 0.0015;
        b.rest_span = rest_span;
        const std::vector<StageSpec> stages{b, dynamic("after", 0.001)};
        BouncingBody body;
        StageDriver<2> d(m, stages, {}, {});
        d.couple(&body);
        d.run();
        double end = 0.0;
        for (std::size_t i = 0; i < d.history().data[2].size(); ++i)
            if (d.history().data[2][i] == 1.0) end = d.history().data[0][i];
        return end;
    };
    const double end = blow_end(0.001), end_at_first_dwell = blow_end(0.0);
    EXPECT_GE(end, 0.011);
    EXPECT_LT(end, 0.0125);
    EXPECT_LT(end_at_first_dwell, 0.003);
}
