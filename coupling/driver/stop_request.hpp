#pragma once
// A request to stop a run early and keep a checkpoint: Ctrl-C (SIGINT) or a batch system's
// SIGTERM at a job's time limit. The handlers are installed while a StopRequest lives and
// the previous ones come back after it; the run polls requested() between steps.
namespace pilempm::coupling {

class StopRequest {
public:
    // test_hook: honour PILEMPM_INTERRUPT_AFTER_STEPS (and PILEMPM_INTERRUPT_SIGNAL, default
    // SIGINT): the process sends itself that signal once the run has taken that many steps,
    // so tests exercise the real handlers. A resumed run passes false.
    explicit StopRequest(bool test_hook);
    ~StopRequest();
    StopRequest(const StopRequest&) = delete;
    StopRequest& operator=(const StopRequest&) = delete;

    // Raises the test hook's signal when due; call once per step.
    void poll(long steps_taken) const;
    bool requested() const;

private:
    using Handler = void (*)(int);
    Handler previous_int_, previous_term_;
    long interrupt_after_ = -1;
    int interrupt_signal_ = 0;
};

}  // namespace pilempm::coupling
