#include "io/hdf5/run_checkpoint.hpp"

#include <stdexcept>

#include "io/hdf5/mpm_checkpoint.hpp"

namespace pilempm::io {

namespace {
const std::string kBodyPrefix = "body_";  // the coupled body's arrays among the extras
}  // namespace

template <int D>
void write_run_checkpoint(const std::filesystem::path& file, const mpm::Particles<D>& p, const RunCheckpoint& run) {
    const auto& s = run.driver;
    const std::vector<std::pair<std::string, double>> scalars = {
        {"stage", static_cast<double>(s.stage)},
        {"stage_begun", s.stage_begun ? 1.0 : 0.0},
        {"stage_start_time", s.stage_start_time},
        {"stage_steps", static_cast<double>(s.stage_steps)},
        {"next_snapshot", s.next_snapshot},
        {"initial_snapshot_written", s.initial_snapshot_written ? 1.0 : 0.0},
        {"blow_start_time", s.blow_start_time},
        {"blow_start_toe", s.blow_start_toe},
        {"last_blow_end_toe", s.last_blow_end_toe},
        {"low_set_blows", static_cast<double>(s.low_set_blows)},
        {"rest_since", s.rest_since},
        {"absorbed_energy", run.solver.absorbed_energy},
        {"external_work", run.solver.external_work},
    };
    CheckpointExtras extras;
    extras.arrays.emplace_back("snapshot_times", run.snapshot_times);
    extras.arrays.emplace_back("boundary_held_force", run.solver.held_force);
    extras.arrays.emplace_back("boundary_displacement", run.solver.boundary_displacement);
    extras.arrays.emplace_back("history_segments", run.history_segments);
    extras.arrays.emplace_back("driver_stage_max", s.stage_max);
    extras.arrays.emplace_back("driver_stage_min", s.stage_min);
    extras.arrays.emplace_back("driver_last_row", s.last_row);
    for (const auto& [name, values] : run.body) extras.arrays.emplace_back(kBodyPrefix + name, values);
    extras.tables.push_back(run.history);
    if (!s.extremes.columns.empty()) extras.tables.push_back(s.extremes);  // a stage driver's state has them
    write_checkpoint<D>(file, p, run.solver.time, run.solver.steps, scalars, run.case_fingerprint, extras);
}

template <int D>
RunCheckpoint read_run_checkpoint(const std::filesystem::path& file, mpm::Particles<D>& p) {
    const CheckpointInfo info = read_checkpoint<D>(file, p);
    auto scalar = [&](const char* name) {
        for (const auto& [key, value] : info.scalars)
            if (key == name) return value;
        throw std::runtime_error("MPM checkpoint " + file.string() + ": no scalar " + name +
                                 " (written by an older pilempm?)");
    };
    RunCheckpoint run;
    run.solver.time = info.time;
    run.solver.steps = info.step;
    run.case_fingerprint = info.case_fingerprint;
    run.driver.stage = static_cast<int>(scalar("stage"));
    run.driver.stage_begun = scalar("stage_begun") != 0.0;
    run.driver.stage_start_time = scalar("stage_start_time");
    run.driver.stage_steps = static_cast<long>(scalar("stage_steps"));
    run.driver.next_snapshot = scalar("next_snapshot");
    run.driver.initial_snapshot_written = scalar("initial_snapshot_written") != 0.0;
    run.driver.blow_start_time = scalar("blow_start_time");
    run.driver.blow_start_toe = scalar("blow_start_toe");
    run.driver.last_blow_end_toe = scalar("last_blow_end_toe");
    run.driver.low_set_blows = static_cast<int>(scalar("low_set_blows"));
    run.driver.rest_since = scalar("rest_since");
    run.solver.absorbed_energy = scalar("absorbed_energy");
    run.solver.external_work = scalar("external_work");
    for (const auto& [name, values] : info.extras.arrays) {
        if (name == "snapshot_times") run.snapshot_times = values;
        if (name == "boundary_held_force") run.solver.held_force = values;
        if (name == "boundary_displacement") run.solver.boundary_displacement = values;
        if (name == "history_segments") run.history_segments = values;  // none before them: all in the table
        if (name == "driver_stage_max") run.driver.stage_max = values;
        if (name == "driver_stage_min") run.driver.stage_min = values;
        if (name == "driver_last_row") run.driver.last_row = values;
        if (name.rfind(kBodyPrefix, 0) == 0) run.body.emplace_back(name.substr(kBodyPrefix.size()), values);
    }
    bool have_history = false, have_extremes = false;
    for (const auto& t : info.extras.tables) {
        if (t.name == "history") run.history = t, have_history = true;
        if (t.name == "stage_extremes") run.driver.extremes = t, have_extremes = true;
    }
    if (!have_history) throw std::runtime_error("MPM checkpoint " + file.string() + ": no history table");
    if (!have_extremes)
        throw std::runtime_error("MPM checkpoint " + file.string() +
                                 ": no stage_extremes table (written by a pilempm older than commit 11abd81?)");
    return run;
}

template void write_run_checkpoint<2>(const std::filesystem::path&, const mpm::Particles<2>&, const RunCheckpoint&);
template void write_run_checkpoint<3>(const std::filesystem::path&, const mpm::Particles<3>&, const RunCheckpoint&);
template RunCheckpoint read_run_checkpoint<2>(const std::filesystem::path&, mpm::Particles<2>&);
template RunCheckpoint read_run_checkpoint<3>(const std::filesystem::path&, mpm::Particles<3>&);

}  // namespace pilempm::io
