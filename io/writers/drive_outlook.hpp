#pragma once
// What is left of a drive, as its log tells it after each blow: the depth to its target,
// and the blows and wall time that takes at the recent blows' mean set and pace.
#include <cstddef>
#include <deque>

namespace pilempm::io {

class DriveOutlook {
public:
    explicit DriveOutlook(std::size_t window = 10) : window_(window) {}

    // A blow ended `set` m deeper, `seconds` of wall time after the last blow ended (< 0:
    // unknown, the first blow of this invocation).
    void add(double set, double seconds) {
        sets_.push_back(set);
        if (sets_.size() > window_) sets_.pop_front();
        if (seconds >= 0.0) seconds_.push_back(seconds);
        if (seconds_.size() > window_) seconds_.pop_front();
    }

    struct Estimate {
        double blows = -1.0;    // < 0: the pile does not advance (no estimate)
        double seconds = -1.0;  // < 0: no pace yet
    };
    // `remaining`: m from the toe to the target.
    Estimate to_go(double remaining) const {
        Estimate e;
        double set = 0.0, pace = 0.0;
        for (double s : sets_) set += s;
        for (double t : seconds_) pace += t;
        if (sets_.empty() || !(set > 0.0)) return e;
        e.blows = remaining / (set / static_cast<double>(sets_.size()));
        if (!seconds_.empty()) e.seconds = e.blows * pace / static_cast<double>(seconds_.size());
        return e;
    }
    std::size_t blows_seen() const { return sets_.size(); }

private:
    std::size_t window_;
    std::deque<double> sets_, seconds_;
};

}  // namespace pilempm::io
