#include "io/writers/mpm_run_output.hpp"

#include <cstdio>

#include "io/hdf5/run_checkpoint.hpp"

namespace pilempm::io {

namespace fs = std::filesystem;

template <int D>
MpmRunOutput<D>::MpmRunOutput(StagedDirectory& staged, std::vector<std::string> state_names,
                              std::string case_fingerprint, bool quiet)
    : staged_(staged),
      vtk_(staged.path() / "vtk", "particles", std::move(state_names)),
      fingerprint_(std::move(case_fingerprint)),
      quiet_(quiet) {}

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
    run.history = history;
    run.snapshot_times = vtk_.step_times();
    run.case_fingerprint = fingerprint_;
    if (body_) run.body = body_->state();
    write_run_checkpoint<D>(checkpoint_path(), model.particles, run);
    staged_.keep_if_failed();
}

template <int D>
void MpmRunOutput<D>::stage_begin(int, const coupling::StageSpec& spec) {
    progress_ = std::make_unique<TerminalProgress>("mpm stage '" + spec.name + "'", !quiet_);
}

template <int D>
void MpmRunOutput<D>::stage_progress(const coupling::StageSpec& spec, const coupling::DriverState& state,
                                     const mpm::MpmSolver<D>& solver) {
    if (spec.quasi_static) progress_->update_count(state.stage_steps - 1, spec.max_steps, "steps (quasi-static)");
    else progress_->update(solver.time() - state.stage_start_time, spec.duration, solver.steps());
}

template <int D>
void MpmRunOutput<D>::stage_end(int, const coupling::StageSpec& spec, const coupling::StageReport& report) {
    if (progress_) progress_->done();
    progress_.reset();
    if (!quiet_ && spec.quasi_static && !report.stopped)
        std::printf("stage '%s': %ld steps, unbalanced force ratio %.3g (tolerance %.3g)%s\n", spec.name.c_str(),
                    report.steps, report.unbalanced_ratio, spec.tolerance,
                    report.in_equilibrium ? "" : "  NOT IN EQUILIBRIUM");
}

template class MpmRunOutput<2>;
template class MpmRunOutput<3>;

}  // namespace pilempm::io
