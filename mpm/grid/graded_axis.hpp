#pragma once
// Node coordinates of a graded grid axis: fine cells where the pile and its stress
// concentrations are, coarse ones towards the far boundaries. The axis is a run of zones
// from the origin; each ends at `to` with cells of size `cell` there. The first zone is
// uniform; in each later one the cells change geometrically from the size the previous
// zone ended with to its own (uniform when the two are equal), their number chosen so the
// ratio of neighbouring cells is the smallest that fits the zone's length.
#include <string>
#include <vector>

namespace pilempm::mpm {

struct GridZone {
    double to = 0.0;    // m: the zone's far end, along the axis
    double cell = 0.0;  // m: the cell size at that end
};

// The largest ratio of neighbouring cells accepted: larger jumps make a point's domain
// reach past the neighbouring cell and spoil the grid's accuracy.
inline constexpr double kMaxGradingRatio = 1.5;

// Node coordinates from `origin` through the zones, the cell sizes divided by `refine`
// (grid sequences). Throws std::invalid_argument (a sentence naming the zone) when the
// zones do not run forward, a cell does not fit its zone, or the grading is steeper than
// kMaxGradingRatio.
std::vector<double> graded_axis(double origin, const std::vector<GridZone>& zones, double refine = 1.0);

}  // namespace pilempm::mpm
