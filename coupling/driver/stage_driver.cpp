#include "coupling/driver/stage_driver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace pilempm::coupling {

template <int D>
StageDriver<D>::StageDriver(mpm::MpmModel<D>& model, std::vector<StageSpec> stages, std::vector<StageLoad> loads,
                            DriverSettings settings, StageObserver<D>* observer)
    : m_(model),
      solver_(model),
      stages_(std::move(stages)),
      loads_(std::move(loads)),
      settings_(settings),
      observer_(observer ? observer : &quiet_),
      history_("history", {"time_s", "step", "stage"}),
      gravity_(model.gravity),
      flip_dynamic_(model.flip),
      apic_dynamic_(model.apic) {
    state_.next_snapshot = settings_.snapshot_interval;
    state_.extremes = empty_extremes(history_.columns);
}

template <int D>
void StageDriver<D>::add_recorder(std::unique_ptr<Recorder<D>> recorder) {
    if (history_.rows() > 0) throw std::logic_error("recorders are added before the run");
    recorder->add_columns(history_.columns);
    history_.data.resize(history_.columns.size());
    state_.extremes = empty_extremes(history_.columns);
    recorders_.push_back(std::move(recorder));
}

namespace {

// A row of values per column `from` in the order of `to` (NaN where `from` has none).
std::vector<double> by_column(const std::vector<double>& values, const std::vector<std::string>& from,
                              const std::vector<std::string>& to) {
    if (values.empty() || from == to) return values;
    std::vector<double> out(to.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t c = 0; c < to.size(); ++c) {
        const auto it = std::find(from.begin(), from.end(), to[c]);
        if (it != from.end()) out[c] = values[static_cast<std::size_t>(it - from.begin())];
    }
    return out;
}

// A table's columns in the order (and set) of `columns`: NaN for those it lacks; a column
// it has that `columns` has not is an error (a run must not drop what it recorded).
Table with_columns(const Table& t, const std::vector<std::string>& columns) {
    if (t.columns == columns) return t;
    Table merged(t.name, columns);
    for (std::size_t c = 0; c < columns.size(); ++c) {
        const auto it = std::find(t.columns.begin(), t.columns.end(), columns[c]);
        merged.data[c] = it != t.columns.end() ? t.data[static_cast<std::size_t>(it - t.columns.begin())]
                                              : std::vector<double>(t.rows(), std::numeric_limits<double>::quiet_NaN());
    }
    for (const auto& name : t.columns)
        if (std::find(columns.begin(), columns.end(), name) == columns.end())
            throw std::runtime_error("the checkpoint's " + t.name + " records " + name + ", which this run does not");
    return merged;
}

}  // namespace

template <int D>
void StageDriver<D>::resume(const DriverState& state, const mpm::SolverState& solver, Table history) {
    // `pilempm run` refuses such a checkpoint where it reads it, before the output folder is
    // touched; this guards the library's other callers, whose state may be built in memory.
    if (state.extremes.columns.empty())
        throw std::runtime_error("the checkpoint holds no stages' extremes (written by a pilempm older than commit 11abd81): "
                                 "rerun the case from its start");
    // A checkpoint of an earlier build that recorded fewer columns: its rows go on with the
    // new columns empty (NaN) up to the resume, so a long campaign survives an upgrade.
    const std::vector<std::string> recorded = history.columns;
    history_ = with_columns(history, history_.columns);
    state_ = state;
    state_.extremes = with_columns(state_.extremes, empty_extremes(history_.columns).columns);
    state_.stage_max = by_column(state_.stage_max, recorded, history_.columns);
    state_.stage_min = by_column(state_.stage_min, recorded, history_.columns);
    state_.last_row = by_column(state_.last_row, recorded, history_.columns);
    solver_.restore(solver);
}

template <int D>
void StageDriver<D>::apply_loads(bool quasi_static, double time_in_stage) {
    auto& active = m_.surface_loads;
    active.clear();
    for (const auto& l : loads_) {
        const double f = l.factor(state_.stage, quasi_static, time_in_stage);
        if (f == 0.0) continue;
        active.push_back(l.load);
        if (f != 1.0)
            for (double& x : active.back().force) x *= f;
    }
}

template <int D>
void StageDriver<D>::record(bool store) {
    std::vector<double>& row = state_.last_row;  // kept: a decimated stage stores its last at its end
    row.assign({solver_.time(), static_cast<double>(solver_.steps()), static_cast<double>(state_.stage + 1)});
    for (const auto& r : recorders_) r->sample(m_, solver_, row);
    fold_extremes(row, state_.stage_max, state_.stage_min);
    if (store)
        for (std::size_t k = 0; k < row.size(); ++k) history_.data[k].push_back(row[k]);
}

template <int D>
void StageDriver<D>::store_last_row() {
    const auto& row = state_.last_row;
    if (row.empty() || (history_.rows() > 0 && history_.data[1].back() == row[1])) return;  // [1]: the step
    for (std::size_t k = 0; k < row.size(); ++k) history_.data[k].push_back(row[k]);
}

template <int D>
void StageDriver<D>::checkpoint() {
    observer_->checkpoint(state_, m_, solver_, history_);
}

// After each step: the periodic checkpoint, then the stop request (checkpointed too).
template <int D>
bool StageDriver<D>::periodic_checkpoint_and_stop(const StopRequest* stop) {
    if (settings_.checkpoint_every > 0 && solver_.steps() % settings_.checkpoint_every == 0) checkpoint();
    if (!stop) return false;
    stop->poll(solver_.steps());
    if (!stop->requested()) return false;
    checkpoint();
    return true;
}

// The soil's stable step, and the coupled body's limit on it.
template <int D>
double StageDriver<D>::step_size() const {
    const double dt = solver_.stable_time_step();
    return body_ ? std::min(dt, body_->stable_time_step(m_, dt)) : dt;
}

// The body first (its forces on the points, itself over the step), then the soil.
template <int D>
void StageDriver<D>::step(double dt, bool quasi_static) {
    if (body_)
        body_->before_step(m_, state_.stage, quasi_static, dt,
                           quasi_static ? 0.0 : solver_.time() - state_.stage_start_time);
    solver_.step(dt);
    if (body_) body_->after_step(m_, solver_.stencils());
}

// Pseudo-time: the clock stands still, held loads only, until equilibrium. The local damping
// is the dissipation: PIC's velocity projection would fight it (pure PIC never settles), so
// the stage runs pure FLIP. Returns false when stopped.
template <int D>
bool StageDriver<D>::run_quasi_static(const StageSpec& st, const StopRequest* stop) {
    m_.flip = 1.0;
    m_.apic = false;
    StageReport report;
    long n = state_.stage_steps;
    bool last_recorded = false;
    for (; n < st.max_steps; ++n) {
        apply_loads(true, 0.0);
        step(step_size(), true);
        state_.stage_steps = n + 1;
        last_recorded = n % settings_.quasi_static_record_every == 0;
        if (last_recorded) record();
        if (n >= 100 && unbalanced_force_ratio() < st.tolerance) break;
        if (periodic_checkpoint_and_stop(stop)) {
            report.steps = n;
            report.unbalanced_ratio = unbalanced_force_ratio();
            report.stopped = true;
            observer_->stage_end(state_.stage, st, report);
            return false;
        }
        observer_->stage_progress(st, state_, solver_);
    }
    m_.flip = flip_dynamic_;
    m_.apic = apic_dynamic_;
    std::fill(m_.particles.v.begin(), m_.particles.v.end(), 0.0);  // a nil step: start at rest
    std::fill(m_.particles.C.begin(), m_.particles.C.end(), 0.0);
    if (body_) body_->come_to_rest();
    solver_.set_time(state_.stage_start_time, solver_.steps());
    if (!last_recorded) record();  // the stage's final state is in the history (a blow's set starts there)
    report.steps = n;
    report.unbalanced_ratio = unbalanced_force_ratio();
    report.in_equilibrium = report.unbalanced_ratio < st.tolerance;
    observer_->stage_end(state_.stage, st, report);
    return true;
}

// After a step in real time (dynamic, consolidation): the history row, a snapshot when its
// clock says, the periodic checkpoint and the stop request. False when stopped.
template <int D>
bool StageDriver<D>::after_real_time_step(const StageSpec& st, StageReport& report, const StopRequest* stop,
                                          bool store) {
    record(store);
    if (settings_.snapshot_interval > 0.0 && solver_.time() >= state_.next_snapshot - 1e-12) {
        observer_->snapshot(solver_.time(), m_);
        state_.next_snapshot += settings_.snapshot_interval;
    }
    if (periodic_checkpoint_and_stop(stop)) {
        report.steps = state_.stage_steps;
        report.stopped = true;
        observer_->stage_end(state_.stage, st, report);
        return false;
    }
    observer_->stage_progress(st, state_, solver_);
    return true;
}

template <int D>
bool StageDriver<D>::run_dynamic(const StageSpec& st, const StopRequest* stop) {
    const double t_end = state_.stage_start_time + st.duration;
    StageReport report;
    while (solver_.time() < t_end - 1e-15) {
        // A blow has died out: the body at rest for rest_span. Asked before the step, of the
        // state a checkpoint holds, so a resumed run decides as the uninterrupted one did.
        const double in_stage = solver_.time() - state_.stage_start_time;
        if (st.rest_speed > 0.0 && body_ && state_.stage_steps > 0) {
            if (body_->max_speed() >= st.rest_speed) state_.rest_since = -1.0;
            else if (state_.rest_since < 0.0) state_.rest_since = solver_.time();
            if (in_stage >= st.min_duration && state_.rest_since >= 0.0 &&
                solver_.time() - state_.rest_since >= st.rest_span - 1e-15)
                break;
        }
        const bool settling = st.settle_damping > 0.0 && state_.stage_steps > 0 && in_stage >= st.min_duration;
        m_.local_damping = settling ? st.settle_damping : st.local_damping;
        if (body_) body_->set_settling(settling ? st.settle_damping : 0.0);
        apply_loads(false, in_stage);
        step(std::min(step_size(), t_end - solver_.time()), false);
        ++state_.stage_steps;
        const bool store = st.record_every <= 1 || in_stage < st.min_duration || state_.stage_steps % st.record_every == 0;
        if (!after_real_time_step(st, report, stop, store)) return false;
    }
    store_last_row();  // the stage's end state is in the history (the next stage's "before")
    report.steps = state_.stage_steps;
    report.unbalanced_ratio = solver_.unbalanced_force_ratio();
    if (st.blow && body_) report.set = blow_set();
    observer_->stage_end(state_.stage, st, report);
    return true;
}

// A blow's set counts from where the last blow left the toe, as a set is read in the field
// and blows.csv counts it: the pause's settlement goes to the blow after it.
template <int D>
double StageDriver<D>::blow_set() const {
    const double from = std::isnan(state_.last_blow_end_toe) ? state_.blow_start_toe : state_.last_blow_end_toe;
    return from - body_->toe_elevation();
}

// Real time with the soil at rest: implicit u-p steps growing geometrically, the last one
// ending the stage on its duration. Held loads act (a pulse is a dynamic stage's).
template <int D>
bool StageDriver<D>::run_consolidation(const StageSpec& st, const StopRequest* stop) {
    if (body_) body_->come_to_rest();  // the pause: the pile rests with the soil
    mpm::ConsolidationSolver<D> consolidation(m_, st.linear_solver, st.direct_below);
    const double r = st.step_growth;
    const double first = r == 1.0 ? st.duration / st.steps : st.duration * (r - 1.0) / (std::pow(r, st.steps) - 1.0);
    const double t_end = state_.stage_start_time + st.duration;
    StageReport report;
    for (long n = state_.stage_steps; n < st.steps; ++n) {
        apply_loads(true, solver_.time() - state_.stage_start_time);
        const double dt = n + 1 == st.steps ? t_end - solver_.time() : first * std::pow(r, static_cast<double>(n));
        if (body_) x_before_ = m_.particles.x;
        const mpm::ConsolidationStepReport step = consolidation.step(dt);
        if (body_) body_->follow_soil(m_, x_before_);
        last_consolidation_ = step;
        report.linear_solve_seconds += step.solve.setup_seconds + step.solve.solve_seconds;
        ++report.solves;
        report.setups_kept += step.solve.setup_kept ? 1 : 0;
        solver_.set_time(solver_.time() + dt, solver_.steps() + 1);
        solver_.set_unbalanced_force_ratio(step.unbalanced_ratio);
        state_.stage_steps = n + 1;
        if (!after_real_time_step(st, report, stop)) return false;
    }
    report.steps = state_.stage_steps;
    observer_->stage_end(state_.stage, st, report);
    return true;
}

// A blow's start: when, and where the body's toe is (its set is measured from there).
template <int D>
void StageDriver<D>::begin_stage(const StageSpec& st) {
    state_.stage_begun = true;
    state_.stage_start_time = solver_.time();
    state_.stage_steps = 0;
    state_.rest_since = -1.0;
    state_.stage_max.clear();
    state_.stage_min.clear();
    if (st.blow) {
        state_.blow_start_time = solver_.time();
        state_.blow_start_toe = body_ ? body_->toe_elevation() : 0.0;
    }
}

// After a stage: the stage to go on from (its own index, or a drive's last once the drive is
// over: the target depth reached, or refusal).
template <int D>
int StageDriver<D>::end_stage(const StageSpec& st) {
    const int here = state_.stage;
    if (!st.blow || !body_) return here;
    const double toe = body_->toe_elevation();
    const double set = blow_set();
    state_.last_blow_end_toe = toe;
    state_.low_set_blows = set < st.refusal_set ? state_.low_set_blows + 1 : 0;
    std::string why;
    if (toe <= st.end_toe_elevation)
        why = "the toe reached its target elevation";
    else if (st.refusal_blows > 0 && state_.low_set_blows >= st.refusal_blows)
        why = "refusal: " + std::to_string(st.refusal_blows) + " blows in a row each set the pile less than " +
              std::to_string(st.refusal_set * 1e3) + " mm";
    if (why.empty()) return here;
    int last = here;
    while (last + 1 < static_cast<int>(stages_.size()) && stages_[last + 1].drive == st.drive) ++last;
    if (last > here) observer_->drive_ended(st, why);
    return last;
}

template <int D>
typename StageDriver<D>::Outcome StageDriver<D>::run(const StopRequest* stop) {
    if (!state_.initial_snapshot_written) {
        observer_->snapshot(solver_.time(), m_);
        state_.initial_snapshot_written = true;
    }
    for (; state_.stage < static_cast<int>(stages_.size()); ++state_.stage) {
        StageSpec st = stages_[state_.stage];
        if (!state_.stage_begun) begin_stage(st);
        // A pause lasts what is left of the interval from the last blow's start.
        if (st.blow_interval > 0.0) st.duration = st.blow_interval - (state_.stage_start_time - state_.blow_start_time);
        observer_->stage_begin(state_.stage, st);
        m_.local_damping = st.local_damping;
        solver_.set_drained(st.drained);
        solver_.set_static_boundaries(st.quasi_static);
        for (int d = 0; d < D; ++d) m_.gravity[d] = st.gravity_factor * gravity_[d];
        if (body_) body_->set_gravity_factor(st.gravity_factor);
        if (body_) body_->set_settling(0.0);
        // A blow that took the whole interval leaves its pause nothing (it ends as it begins).
        const bool nothing_left = st.blow_interval > 0.0 && st.duration <= 1e-12;
        if (nothing_left) observer_->stage_end(state_.stage, st, StageReport{});
        const bool finished = nothing_left      ? true
                              : st.consolidation ? run_consolidation(st, stop)
                              : st.quasi_static  ? run_quasi_static(st, stop)
                                                 : run_dynamic(st, stop);
        if (!finished) return Outcome::Stopped;
        add_extremes_row(state_.extremes, state_.stage + 1, state_.stage_max, state_.stage_min);
        state_.stage_max.clear();
        state_.stage_min.clear();
        if (st.snapshot_at_end) observer_->snapshot(solver_.time(), m_);
        state_.stage = end_stage(st);
        // The checkpoint at a stage's end names the next stage, not yet begun.
        state_.stage_begun = false;
        state_.stage_steps = 0;
        ++state_.stage;
        checkpoint();
        --state_.stage;
    }
    return Outcome::Completed;
}

template class StageDriver<2>;
template class StageDriver<3>;

}  // namespace pilempm::coupling
