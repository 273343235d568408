#include "io/writers/mpm_run_output.hpp"

#include <chrono>
#include <cstdio>

#include "io/hdf5/run_checkpoint.hpp"

namespace pilempm::io {

namespace fs = std::filesystem;

template <int D>
MpmRunOutput<D>::MpmRunOutput(StagedDirectory& staged, std::vector<std::string> state_names,
                              std::string case_fingerprint, bool quiet, std::size_t history_segment_rows)
    : staged_(staged),
      vtk_(staged.path() / "vtk", "particles", std::move(state_names)),
      fingerprint_(std::move(case_fingerprint)),
      quiet_(quiet),
      progress_("", quiet),
      history_segments_(staged.path(), history_segment_rows) {}

template <int D>
void MpmRunOutput<D>::snapshot(double time, const mpm::MpmModel<D>& model) {
    vtk_.write(time, model.particles);
    if (also_) also_(time);
}

template <int D>
void MpmRunOutput<D>::checkpoint(const coupling::DriverState& state, const mpm::MpmModel<D>& model,
                                 const mpm::MpmSolver<D>& solver, const Table& history) {
    RunCheckpoint run;
    run.driver = state;
    run.solver = solver.state();
    run.history = history_segments_.seal(history);  // the rows not yet in a segment file
    run.history_segments = history_segments_.rows_per_segment();
    run.snapshot_times = vtk_.step_times();
    run.case_fingerprint = fingerprint_;
    if (body_) run.body = body_->state();
    write_run_checkpoint<D>(checkpoint_path(), model.particles, run);
    vtk_.finish();  // the series so far opens in ParaView while the run goes on, or after a kill
    staged_.keep_if_failed();
    if (also_at_checkpoint_) also_at_checkpoint_(state, history);
}

template <int D>
void MpmRunOutput<D>::stage_begin(int stage, const coupling::StageSpec& spec) {
    progress_.stage_begin(stage, spec);
    stage_began_ = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

template <int D>
void MpmRunOutput<D>::stage_progress(const coupling::StageSpec& spec, const coupling::DriverState& state,
                                     const mpm::MpmSolver<D>& solver) {
    progress_.stage_progress(spec, state, solver);
}

template <int D>
void MpmRunOutput<D>::stage_end(int stage, const coupling::StageSpec& spec, const coupling::StageReport& report) {
    progress_.stage_end(stage, spec, report);
    const double now = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    if (!report.stopped) walls_.push_back({stage, now - stage_began_});
    if (!quiet_ && spec.blow && !report.stopped && body_) {
        // The toe's depth below the seabed and the blow's set (as blows.csv counts it); with
        // a target depth, what is left at the last blows' set and pace (blow and pause).
        outlook_.add(report.set, last_blow_end_ < 0.0 ? -1.0 : now - last_blow_end_);
        last_blow_end_ = now;
        std::printf("%s: toe %.3f m below the seabed, set %.1f mm, %ld steps, %.1f s", spec.name.c_str(),
                    ground_ - body_->toe_elevation(), 1e3 * report.set, report.steps, now - stage_began_);
        const double remaining = body_->toe_elevation() - spec.end_toe_elevation;
        const auto e = outlook_.to_go(remaining);
        if (spec.end_toe_elevation > -1e299 && remaining > 0.0 && e.blows >= 0.0) {
            std::printf("; %.2f m to go, ~%.0f blows", remaining, e.blows);
            if (e.seconds >= 0.0) std::printf(", ~%.1f h", e.seconds / 3600.0);
        }
        std::printf("\n");
    }
    if (!quiet_ && spec.drive >= 0 && spec.consolidation && !report.stopped)  // a pause: its cost beside the blows'
        std::printf("%s: %ld implicit steps, %.1f s (linear solves %.1f s, %d of %d on a kept set-up)\n",
                    spec.name.c_str(), report.steps, now - stage_began_, report.linear_solve_seconds, report.setups_kept,
                    report.solves);
    if (!quiet_ && spec.quasi_static && !report.stopped)
        std::printf("stage '%s': %ld steps, unbalanced force ratio %.3g (tolerance %.3g)%s\n", spec.name.c_str(),
                    report.steps, report.unbalanced_ratio, spec.tolerance,
                    report.in_equilibrium ? "" : "  NOT IN EQUILIBRIUM");
    std::fflush(stdout);  // a long drive's log shows each blow as it ends
}

template <int D>
void MpmRunOutput<D>::drive_ended(const coupling::StageSpec& blow, const std::string& why) {
    if (!quiet_) std::printf("drive ended after %s: %s\n", blow.name.c_str(), why.c_str());
}

template class MpmRunOutput<2>;
template class MpmRunOutput<3>;

}  // namespace pilempm::io
