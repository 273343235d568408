#pragma once
// The whole state of a staged run in one checkpoint: the particles, the solver's clock and
// energy ledger, the stage driver's state, the history so far (its older rows in segment
// files beside it) and the times of the VTK snapshots already written. Resuming from it
// continues the run as if it had never stopped.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/table.hpp"
#include "coupling/driver/stage_driver.hpp"
#include "mpm/points/particles.hpp"
#include "mpm/solver/mpm_solver.hpp"

namespace pilempm::io {

struct RunCheckpoint {
    coupling::DriverState driver;
    mpm::SolverState solver;       // the clock and the energy ledger
    // The history: the rows after those sealed in segment files beside the checkpoint
    // (history_segments.hpp; rows in each segment, in order). assemble_history joins them.
    Table history;
    std::vector<double> history_segments;
    std::vector<double> snapshot_times;  // s, one per VTK file written
    // The coupled body's state (the pile, its contact history): named arrays.
    std::vector<std::pair<std::string, std::vector<double>>> body;
    std::string case_fingerprint;
};

template <int D>
void write_run_checkpoint(const std::filesystem::path& file, const mpm::Particles<D>& p, const RunCheckpoint& run);

// Throws std::runtime_error naming the file when it is not such a checkpoint.
template <int D>
RunCheckpoint read_run_checkpoint(const std::filesystem::path& file, mpm::Particles<D>& p);

}  // namespace pilempm::io
