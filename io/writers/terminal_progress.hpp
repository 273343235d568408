#pragma once
// Progress of a long run: stage, simulated time, step, ETA. On a terminal one line
// rewritten every 0.2 s; into a log (nohup, a batch queue) a new line once a minute, so
// runs shorter than that leave the log clean. Silent with --quiet.
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
    bool due(bool finished);
    void emit(const char* line);

    std::string stage_;
    bool enabled_;
    bool terminal_;
    std::chrono::steady_clock::time_point start_, last_;
    bool printed_ = false;
};

}  // namespace pilempm::io
