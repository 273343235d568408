#include "coupling/driver/stop_request.hpp"

#include <csignal>
#include <cstdlib>

namespace pilempm::coupling {

namespace {
volatile std::sig_atomic_t g_stop_requested = 0;
extern "C" void on_stop_signal(int) { g_stop_requested = 1; }
}  // namespace

StopRequest::StopRequest(bool test_hook)
    : previous_int_(std::signal(SIGINT, on_stop_signal)), previous_term_(std::signal(SIGTERM, on_stop_signal)) {
    g_stop_requested = 0;
    interrupt_signal_ = SIGINT;
    if (!test_hook) return;
    if (const char* e = std::getenv("PILEMPM_INTERRUPT_AFTER_STEPS")) interrupt_after_ = std::atol(e);
    if (const char* e = std::getenv("PILEMPM_INTERRUPT_SIGNAL")) interrupt_signal_ = std::atoi(e);
}

StopRequest::~StopRequest() {
    std::signal(SIGINT, previous_int_);
    std::signal(SIGTERM, previous_term_);
}

void StopRequest::poll(long steps_taken) const {
    if (interrupt_after_ >= 0 && steps_taken >= interrupt_after_ && !g_stop_requested) std::raise(interrupt_signal_);
}

bool StopRequest::requested() const { return g_stop_requested != 0; }

}  // namespace pilempm::coupling
