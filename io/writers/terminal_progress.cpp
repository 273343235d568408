#include "io/writers/terminal_progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace pilempm::io {

TerminalProgress::TerminalProgress(std::string stage, bool enabled)
    : stage_(std::move(stage)), enabled_(enabled && ::isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

void TerminalProgress::update(double time, double duration, long step) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(200) && time < duration) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double fraction = duration > 0 ? time / duration : 1.0;
    const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    std::fprintf(stderr, "\r%s: t = %.2f ms of %.2f ms, step %ld, %3.0f %%, ETA %.0f s   ",
                 stage_.c_str(), time * 1e3, duration * 1e3, step, 100.0 * fraction, eta);
    std::fflush(stderr);
    printed_ = true;
}

void TerminalProgress::update_count(long done, long total, const char* what) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(200) && done < total) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double fraction = total > 0 ? static_cast<double>(done) / total : 1.0;
    const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    std::fprintf(stderr, "\r%s: %ld of %ld %s, %3.0f %%, ETA %.0f s   ", stage_.c_str(), done, total, what,
                 100.0 * fraction, eta);
    std::fflush(stderr);
    printed_ = true;
}

void TerminalProgress::done() {
    if (printed_) std::fprintf(stderr, "\n");
    printed_ = false;
}

}  // namespace pilempm::io
