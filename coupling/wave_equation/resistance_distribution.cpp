#include "coupling/wave_equation/resistance_distribution.hpp"

#include <algorithm>

namespace pilempm::coupling {

double ResistanceDistribution::shaft_per_metre_at(double d) const {
    if (depth.empty() || d < depth.front() || d > depth.back()) return 0.0;
    const auto it = std::upper_bound(depth.begin(), depth.end(), d);
    if (it == depth.end()) return shaft.back();
    const std::size_t i = static_cast<std::size_t>(it - depth.begin());
    if (i == 0) return shaft.front();
    const double w = (d - depth[i - 1]) / (depth[i] - depth[i - 1]);
    return (1.0 - w) * shaft[i - 1] + w * shaft[i];
}

double ResistanceDistribution::shaft_damping_at(double d, double fallback) const {
    if (shaft_damping.size() != depth.size() || depth.empty()) return fallback;
    const auto it = std::lower_bound(depth.begin(), depth.end(), d);
    const std::size_t i = it == depth.end() ? depth.size() - 1 : static_cast<std::size_t>(it - depth.begin());
    return shaft_damping[i];
}

double ResistanceDistribution::shaft_between(double d0, double d1) const {
    if (depth.size() < 2 || d1 <= d0) return 0.0;
    d0 = std::max(d0, depth.front());
    d1 = std::min(d1, depth.back());
    if (d1 <= d0) return 0.0;
    // Trapezoids over the samples and the two cut ends: exact for linear pieces.
    double sum = 0.0, a = d0, fa = shaft_per_metre_at(d0);
    for (std::size_t i = 0; i < depth.size(); ++i) {
        if (depth[i] <= d0) continue;
        if (depth[i] >= d1) break;
        sum += 0.5 * (fa + shaft[i]) * (depth[i] - a);
        a = depth[i];
        fa = shaft[i];
    }
    sum += 0.5 * (fa + shaft_per_metre_at(d1)) * (d1 - a);
    return sum;
}

}  // namespace pilempm::coupling
