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

double ResistanceDistribution::shaft_dashpot_between(double d0, double d1, double fallback) const {
    if (shaft_damping.size() != depth.size() || depth.empty()) return fallback * shaft_between(d0, d1);
    // Runs of equal J are taken whole, so a uniform J gives exactly J x shaft_between.
    double c = 0.0;
    for (double a = d0; a < d1;) {
        std::size_t k = static_cast<std::size_t>(std::upper_bound(depth.begin(), depth.end(), a) - depth.begin());
        k = std::min(k, depth.size() - 1);
        const double j = shaft_damping[k];
        while (k + 1 < depth.size() && shaft_damping[k + 1] == j) ++k;
        const double b = k + 1 < depth.size() ? std::min(d1, depth[k]) : d1;
        c += j * shaft_between(a, b);
        a = b;
    }
    return c;
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
