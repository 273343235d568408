#include "io/writers/terminal_progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace pilempm::io {

TerminalProgress::TerminalProgress(std::string stage, bool enabled)
    : stage_(std::move(stage)), enabled_(enabled), terminal_(::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

bool TerminalProgress::due(bool finished) {
    if (!enabled_) return false;
    const auto now = std::chrono::steady_clock::now();
    const auto interval = terminal_ ? std::chrono::milliseconds(200) : std::chrono::milliseconds(60000);
    // A log gets the last line only if it already holds earlier ones.
    if (now - last_ < interval && !(finished && (terminal_ || printed_))) return false;
    last_ = now;
    return true;
}

void TerminalProgress::emit(const char* line) {
    std::fprintf(stderr, terminal_ ? "\r%s   " : "%s\n", line);
    std::fflush(stderr);
    printed_ = true;
}

void TerminalProgress::update(double time, double duration, long step) {
    if (!due(time >= duration)) return;
    const double elapsed = std::chrono::duration<double>(last_ - start_).count();
    const double fraction = duration > 0 ? time / duration : 1.0;
    const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    char line[256];
    std::snprintf(line, sizeof line, "%s: t = %.2f ms of %.2f ms, step %ld, %3.0f %%, %.0f s elapsed, ETA %.0f s",
                  stage_.c_str(), time * 1e3, duration * 1e3, step, 100.0 * fraction, elapsed, eta);
    emit(line);
}

void TerminalProgress::update_count(long done, long total, const char* what) {
    if (!due(done >= total)) return;
    const double elapsed = std::chrono::duration<double>(last_ - start_).count();
    const double fraction = total > 0 ? static_cast<double>(done) / total : 1.0;
    const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    char line[256];
    std::snprintf(line, sizeof line, "%s: %ld of %ld %s, %3.0f %%, %.0f s elapsed, ETA %.0f s", stage_.c_str(), done,
                  total, what, 100.0 * fraction, elapsed, eta);
    emit(line);
}

void TerminalProgress::done() {
    if (printed_ && terminal_) std::fprintf(stderr, "\n");
    printed_ = false;
}

}  // namespace pilempm::io
