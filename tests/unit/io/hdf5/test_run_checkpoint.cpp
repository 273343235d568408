// A run's checkpoint: the driver's state comes back exactly (every field, set to values
// no default has), and a checkpoint written before a field existed reads its default.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/table.hpp"
#include "io/hdf5/mpm_checkpoint.hpp"
#include "io/hdf5/run_checkpoint.hpp"
#include "mpm/points/particles.hpp"

namespace fs = std::filesystem;
using namespace pilempm;

namespace {

fs::path scratch_file(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("pilempm-run-checkpoint-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir / (name + ".h5");
}

mpm::Particles<2> two_points() {
    mpm::Particles<2> p;
    const double lengths[2] = {0.25, 0.25};
    for (int i = 0; i < 2; ++i) {
        double x[2] = {0.3 + i / 3.0, 1.0 / 7.0};
        p.add(x, 2.0 + i, 0.0625, lengths, 0);
    }
    return p;
}

io::RunCheckpoint sample_run() {
    io::RunCheckpoint run;
    run.driver.stage = 7;
    run.driver.stage_begun = true;
    run.driver.stage_start_time = 1.0 / 3.0;
    run.driver.stage_steps = 1234567;
    run.driver.next_snapshot = std::sqrt(2.0);
    run.driver.initial_snapshot_written = true;
    run.driver.blow_start_time = 0.1 + 0.2;
    run.driver.blow_start_toe = -4.7 / 3.0;
    run.driver.last_blow_end_toe = -4.8 / 7.0;
    run.driver.low_set_blows = 3;
    run.driver.rest_since = 2.0 / 9.0;
    run.solver.time = 5.0 / 11.0;
    run.solver.steps = 98765;
    run.solver.absorbed_energy = 1e6 / 3.0;
    run.solver.external_work = -2e5 / 7.0;
    run.history = Table("history", {"time_s", "step"});
    run.history.data[0] = {0.0, 1.0 / 3.0};
    run.history.data[1] = {0.0, 1.0};
    run.driver.extremes = Table("stage_extremes", {"stage", "max_x", "min_x"});
    run.driver.extremes.add_row({1.0, 2.0 / 3.0, -1.0 / 7.0});
    run.driver.stage_max = {1.0 / 3.0, 2.0, 5.0};
    run.driver.stage_min = {0.0, 1.0, -5.0};
    run.driver.last_row = {1.0 / 3.0, 2.0, 1.0 / 9.0};
    run.case_fingerprint = "case";
    return run;
}

}  // namespace

TEST(RunCheckpoint, TheDriversStateComesBackExactly) {
    const fs::path file = scratch_file("exact");
    const io::RunCheckpoint run = sample_run();
    io::write_run_checkpoint<2>(file, two_points(), run);
    mpm::Particles<2> q;
    const io::RunCheckpoint back = io::read_run_checkpoint<2>(file, q);
    const auto &a = run.driver, &b = back.driver;
    EXPECT_EQ(b.stage, a.stage);
    EXPECT_EQ(b.stage_begun, a.stage_begun);
    EXPECT_EQ(b.stage_start_time, a.stage_start_time);
    EXPECT_EQ(b.stage_steps, a.stage_steps);
    EXPECT_EQ(b.next_snapshot, a.next_snapshot);
    EXPECT_EQ(b.initial_snapshot_written, a.initial_snapshot_written);
    EXPECT_EQ(b.blow_start_time, a.blow_start_time);
    EXPECT_EQ(b.blow_start_toe, a.blow_start_toe);
    EXPECT_EQ(b.last_blow_end_toe, a.last_blow_end_toe);
    EXPECT_EQ(b.low_set_blows, a.low_set_blows);
    EXPECT_EQ(b.rest_since, a.rest_since);
    EXPECT_EQ(b.extremes.columns, a.extremes.columns);
    EXPECT_EQ(b.extremes.data, a.extremes.data);
    EXPECT_EQ(b.stage_max, a.stage_max);
    EXPECT_EQ(b.stage_min, a.stage_min);
    EXPECT_EQ(b.last_row, a.last_row);
    EXPECT_EQ(back.solver.time, run.solver.time);
    EXPECT_EQ(back.solver.steps, run.solver.steps);
    EXPECT_EQ(back.solver.absorbed_energy, run.solver.absorbed_energy);
    EXPECT_EQ(back.solver.external_work, run.solver.external_work);
    EXPECT_EQ(back.history.data, run.history.data);
    EXPECT_EQ(q.x.size(), 4u);
    fs::remove(file);
}

// Written before the drive kept where its last blow left the toe, or before it kept the
// stages' extremes: refused, naming what it lacks (a resumed drive would count its next set
// from another place, or lose the peaks of the blows before the resume).
TEST(RunCheckpoint, OneFromBeforeTheLastBlowsEndOrTheExtremesIsRefusedNamingIt) {
    const fs::path file = scratch_file("older");
    const io::RunCheckpoint run = sample_run();
    const auto& s = run.driver;
    const std::vector<std::pair<std::string, double>> older = {
        {"stage", s.stage}, {"stage_begun", 1.0}, {"stage_start_time", s.stage_start_time},
        {"stage_steps", static_cast<double>(s.stage_steps)}, {"next_snapshot", s.next_snapshot},
        {"initial_snapshot_written", 1.0}, {"blow_start_time", s.blow_start_time},
        {"blow_start_toe", s.blow_start_toe}, {"low_set_blows", s.low_set_blows}, {"rest_since", s.rest_since},
        {"absorbed_energy", 1.0}, {"external_work", 2.0}};
    io::CheckpointExtras extras;
    extras.tables.push_back(run.history);
    io::write_checkpoint<2>(file, two_points(), 1.0, 10, older, "case", extras);
    mpm::Particles<2> q;
    try {
        io::read_run_checkpoint<2>(file, q);
        ADD_FAILURE() << "read without last_blow_end_toe";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("last_blow_end_toe"), std::string::npos) << e.what();
    }
    std::vector<std::pair<std::string, double>> with_toe = older;
    with_toe.emplace_back("last_blow_end_toe", s.last_blow_end_toe);
    io::write_checkpoint<2>(file, two_points(), 1.0, 10, with_toe, "case", extras);
    try {
        io::read_run_checkpoint<2>(file, q);
        ADD_FAILURE() << "read without the stages' extremes";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("stage_extremes"), std::string::npos) << e.what();
    }
    fs::remove(file);
}
