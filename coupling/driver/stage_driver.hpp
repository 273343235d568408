#pragma once
// The stage driver: runs a model through its stages (quasi-static relaxation, dynamic
// phases), switches the loads per stage, samples the recorders into the history, takes
// snapshots on a clock of simulated time, and checkpoints. Everything it carries from one
// step to the next is in DriverState, the solver's clock and the history, so a run resumed
// from a checkpoint continues exactly as if it had never stopped. Output goes through a
// StageObserver (VTK, checkpoint files, progress): the driver itself writes nothing.
#include <algorithm>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/table.hpp"
#include "coupling/driver/coupled_body.hpp"
#include "coupling/driver/history_extremes.hpp"
#include "coupling/driver/recorders.hpp"
#include "coupling/driver/stage.hpp"
#include "coupling/driver/stop_request.hpp"
#include "mpm/implicit/consolidation.hpp"
#include "mpm/solver/mpm_solver.hpp"

namespace pilempm::coupling {

// The driver's own state between steps (checkpointed with the model).
struct DriverState {
    int stage = 0;                  // stage running, or next to run (== count: all done)
    bool stage_begun = false;       // the stage's start time is set (it was under way)
    double stage_start_time = 0.0;  // s: solver time when the stage began
    long stage_steps = 0;           // steps taken in the stage
    double next_snapshot = 0.0;     // s of simulated time
    bool initial_snapshot_written = false;
    // Impact driving: when the last blow began (s), its body's toe then (m), where the last
    // blow left the toe (m; NaN before the first), and the blows in a row that set the pile
    // less than the refusal set.
    double blow_start_time = 0.0;
    double blow_start_toe = 0.0;
    double last_blow_end_toe = std::numeric_limits<double>::quiet_NaN();
    int low_set_blows = 0;
    // s: since when the body has been slower than the stage's rest_speed (< 0: moving).
    double rest_since = -1.0;
    // Each finished stage's extremes of the history (history_extremes.hpp), the running ones
    // of the stage under way, and the last row sampled (a stage that stores every n-th row
    // stores its last one at its end).
    Table extremes;
    std::vector<double> stage_max, stage_min, last_row;
};

struct DriverSettings {
    double snapshot_interval = 0.0;  // s; 0: snapshots at stage ends only
    long checkpoint_every = 0;       // steps; 0: at stage ends (and on a stop) only
    int quasi_static_record_every = 10;  // steps between history rows in quasi-static stages
};

struct StageReport {
    long steps = 0;              // the last step's index within the stage
    double unbalanced_ratio = 0.0;
    bool in_equilibrium = false;  // quasi-static: the tolerance was met
    bool stopped = false;         // a stop request ended the stage early
    double set = std::numeric_limits<double>::quiet_NaN();  // m, a blow's (as blows.csv counts it)
    // Consolidation: the linear solves' wall time (set-up and iterations) and how many kept
    // the last one's set-up (its pattern unchanged), since the stage began or resumed.
    double linear_solve_seconds = 0.0;
    int solves = 0, setups_kept = 0;
};

template <int D>
class StageObserver {
public:
    virtual ~StageObserver() = default;
    virtual void snapshot(double /*time*/, const mpm::MpmModel<D>& /*model*/) {}
    virtual void checkpoint(const DriverState& /*state*/, const mpm::MpmModel<D>& /*model*/,
                            const mpm::MpmSolver<D>& /*solver*/, const Table& /*history*/) {}
    virtual void stage_begin(int /*stage*/, const StageSpec& /*spec*/) {}
    virtual void stage_progress(const StageSpec& /*spec*/, const DriverState& /*state*/,
                                const mpm::MpmSolver<D>& /*solver*/) {}
    // Also called when a stop ends the stage early.
    virtual void stage_end(int /*stage*/, const StageSpec& /*spec*/, const StageReport& /*report*/) {}
    // A drive ended before its last blow (why: the target depth, refusal).
    virtual void drive_ended(const StageSpec& /*blow*/, const std::string& /*why*/) {}
};

template <int D>
class StageDriver {
public:
    enum class Outcome { Completed, Stopped };

    StageDriver(mpm::MpmModel<D>& model, std::vector<StageSpec> stages, std::vector<StageLoad> loads,
                DriverSettings settings, StageObserver<D>* observer = nullptr);

    // A body carried along (the pile): it acts before each of the soil's steps. Not owned.
    void couple(CoupledBody<D>* body) { body_ = body; }

    // History columns: time_s, step, stage (1-based), then each recorder's, in order added.
    void add_recorder(std::unique_ptr<Recorder<D>> recorder);

    // A run resumed from a checkpoint: the particles are already in the model; this brings
    // back the driver's state, the solver's clock and energy ledger, and the history. A
    // checkpoint without the extremes (an earlier build's, every row stored) has them
    // rebuilt from its history.
    void resume(const DriverState& state, const mpm::SolverState& solver, Table history);

    // Runs the stages left; Stopped when `stop` asked for it (a checkpoint has been taken).
    Outcome run(const StopRequest* stop = nullptr);

    const Table& history() const { return history_; }
    // Each finished stage's extremes of the history (history_extremes.hpp).
    const Table& extremes() const { return state_.extremes; }
    const DriverState& state() const { return state_; }
    const mpm::MpmSolver<D>& solver() const { return solver_; }
    const std::vector<StageSpec>& stages() const { return stages_; }
    // The last consolidation step's linear solve (unknowns, iterations, residual), for logs.
    const mpm::ConsolidationStepReport& last_consolidation() const { return last_consolidation_; }

private:
    void apply_loads(bool quasi_static, double time_in_stage);
    // Samples the recorders into a history row (stored when `store`) and the stage's extremes.
    void record(bool store = true);
    // Stores the last row sampled unless the history already ends with it.
    void store_last_row();
    void checkpoint();
    bool periodic_checkpoint_and_stop(const StopRequest* stop);
    bool run_quasi_static(const StageSpec& st, const StopRequest* stop);
    bool run_dynamic(const StageSpec& st, const StopRequest* stop);
    bool run_consolidation(const StageSpec& st, const StopRequest* stop);
    void begin_stage(const StageSpec& st);
    int end_stage(const StageSpec& st);
    double blow_set() const;  // m, the blow just run (body_ set)
    bool after_real_time_step(const StageSpec& st, StageReport& report, const StopRequest* stop, bool store = true);
    double step_size() const;
    // The soil's unbalanced force ratio, or the body's where larger (a quasi-static stage's end).
    double unbalanced_force_ratio() const {
        return std::max(solver_.unbalanced_force_ratio(), body_ ? body_->unbalanced_force_ratio() : 0.0);
    }
    void step(double dt, bool quasi_static);

    mpm::MpmModel<D>& m_;
    mpm::MpmSolver<D> solver_;
    std::vector<StageSpec> stages_;
    std::vector<StageLoad> loads_;
    DriverSettings settings_;
    StageObserver<D>* observer_;
    StageObserver<D> quiet_;
    std::vector<std::unique_ptr<Recorder<D>>> recorders_;
    CoupledBody<D>* body_ = nullptr;
    Table history_;
    DriverState state_;
    mpm::ConsolidationStepReport last_consolidation_;
    std::vector<double> x_before_;  // the points' positions before a consolidation step (scratch)
    std::array<double, D> gravity_;  // the case's, before a stage's factor
    double flip_dynamic_;  // the model's velocity transfer, restored after quasi-static stages
    bool apic_dynamic_;
};

extern template class StageDriver<2>;
extern template class StageDriver<3>;

}  // namespace pilempm::coupling
