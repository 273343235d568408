#pragma once
// The soil's surface inside an open pile: the highest point in each ring of the plug (rings
// of one width from the axis to the inner wall), averaged over the plug's area. The plug's
// length is that mean level over the toe, as the soil's volume inside sees it (IFR, PLR);
// the single highest point reads whatever stands up at one radius. Fixed storage: a pile's
// history samples it every step.
#include <algorithm>
#include <array>
#include <cmath>

namespace pilempm::coupling {

class PlugSurface {
public:
    static constexpr int kMaxRings = 64;

    // radius: the inside's (points at r >= radius are not the plug's); ring_width: about a
    // cell (wider where the plug would need more than kMaxRings).
    PlugSurface(double radius, double ring_width)
        : radius_(radius), rings_(std::clamp(static_cast<int>(std::ceil(radius / ring_width)), 1, kMaxRings)) {
        top_.fill(-HUGE_VAL);
    }

    void add(double r, double z) {
        if (!(r >= 0.0 && r < radius_)) return;
        const int k = std::min(rings_ - 1, static_cast<int>(r / radius_ * rings_));
        top_[k] = std::max(top_[k], z);
    }

    // The area-weighted mean of the rings' tops, each no lower than `floor` (the toe); rings
    // without a point left out; `floor` when none has one.
    double mean_level(double floor) const {
        double sum = 0.0, area = 0.0;
        for (int k = 0; k < rings_; ++k) {
            if (top_[k] == -HUGE_VAL) continue;
            const double w = static_cast<double>(2 * k + 1);  // (r_out^2 - r_in^2) / (radius / rings)^2
            sum += w * std::max(floor, top_[k]);
            area += w;
        }
        return area > 0.0 ? sum / area : floor;
    }

private:
    double radius_;
    int rings_;
    std::array<double, kMaxRings> top_;
};

}  // namespace pilempm::coupling
