#pragma once
// Progress of a long run on a terminal: stage, simulated time, step, ETA. Silent when
// stderr is not a terminal (logs stay clean) or with --quiet.
#include <chrono>
#include <string>

namespace pilempm::io {

class TerminalProgress {
public:
    TerminalProgress(std::string stage, bool enabled);
    void update(double time, double duration, long step);
    // For work counted in items (depth points, blows): "what: done of total".
    void update_count(long done, long total, const char* what);
    void done();

private:
    std::string stage_;
    bool enabled_;
    std::chrono::steady_clock::time_point start_, last_;
    bool printed_ = false;
};

}  // namespace pilempm::io
