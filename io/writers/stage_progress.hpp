#pragma once
// Progress of a staged MPM run on the terminal (or a line a minute into a log): one
// progress line per stage, from its duration or its quasi-static step budget. Used by the
// run's own output and by the verification's grid-sequence reruns.
#include <memory>
#include <string>
#include <utility>

#include "coupling/driver/stage_driver.hpp"
#include "io/writers/terminal_progress.hpp"

namespace pilempm::io {

template <int D>
class StageProgress final : public coupling::StageObserver<D> {
public:
    // prefix: put before each stage's name ("grid 8x88, "); quiet: no output at all.
    StageProgress(std::string prefix, bool quiet) : prefix_(std::move(prefix)), quiet_(quiet) {}
    void stage_begin(int, const coupling::StageSpec& spec) override {
        line_ = std::make_unique<TerminalProgress>(prefix_ + "mpm stage '" + spec.name + "'", !quiet_);
    }
    void stage_progress(const coupling::StageSpec& spec, const coupling::DriverState& state,
                        const mpm::MpmSolver<D>& solver) override {
        if (spec.quasi_static) line_->update_count(state.stage_steps - 1, spec.max_steps, "steps (quasi-static)");
        else line_->update(solver.time() - state.stage_start_time, spec.duration, solver.steps());
    }
    void stage_end(int, const coupling::StageSpec&, const coupling::StageReport&) override {
        if (line_) line_->done();
        line_.reset();
    }

private:
    std::string prefix_;
    bool quiet_;
    std::unique_ptr<TerminalProgress> line_;
};

}  // namespace pilempm::io
