#include "mpm/grid/graded_axis.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pilempm::mpm {

namespace {

std::string zone_name(std::size_t k) { return "zone " + std::to_string(k + 1); }

// n cells growing geometrically from h0 (the cell before the zone) towards h1 over L:
// h0 q, h0 q^2, ..., h0 q^n = h1 with sum q (h1 - h0) / (q - 1) = L gives q = L / (L - h1 + h0)
// and n = ln(h1 / h0) / ln q, rounded; q is then solved again for that n so the cells fill L
// exactly (the last one ends near h1) and every neighbour ratio, the first included, is q.
std::vector<double> graded_cells(double h0, double h1, double L) {
    if (std::abs(h1 - h0) <= 1e-12 * std::max(h0, h1)) {
        const int n = std::max(1, static_cast<int>(std::lround(L / h1)));
        return std::vector<double>(n, L / n);
    }
    const double q_estimate = L / (L - h1 + h0);
    const int n = std::max(1, static_cast<int>(std::lround(std::log(h1 / h0) / std::log(q_estimate))));
    auto length = [&](double q) {
        double sum = 0.0, h = h0;
        for (int k = 0; k < n; ++k) sum += h *= q;
        return sum;
    };
    double lo = 1e-3, hi = 1e3;  // length(q) increases with q; bisect to round-off
    for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
        const double mid = 0.5 * (lo + hi);
        (length(mid) < L ? lo : hi) = mid;
    }
    const double q = 0.5 * (lo + hi);
    std::vector<double> sizes(n);
    double h = h0;
    for (int k = 0; k < n; ++k) sizes[k] = h *= q;
    return sizes;
}

}  // namespace

std::vector<double> graded_axis(double origin, const std::vector<GridZone>& zones, double refine) {
    if (zones.empty()) throw std::invalid_argument("no zones: at least one {to, cell}");
    if (!(refine > 0.0)) throw std::invalid_argument("the refinement factor must be positive");
    std::vector<double> lines{origin};
    double start = origin, previous = 0.0;
    for (std::size_t k = 0; k < zones.size(); ++k) {
        const double L = zones[k].to - start, h = zones[k].cell / refine;
        if (!(L > 0.0))
            throw std::invalid_argument(zone_name(k) + " ends at " + std::to_string(zones[k].to) +
                                        " m, not beyond where it starts (" + std::to_string(start) + " m)");
        if (!(h > 0.0) || h > L * (1.0 + 1e-9))
            throw std::invalid_argument(zone_name(k) + ": a cell of " + std::to_string(zones[k].cell) +
                                        " m does not fit its length of " + std::to_string(L) + " m");
        const std::vector<double> sizes = graded_cells(k == 0 ? h : previous, h, L);
        double ratio = k == 0 ? 1.0 : std::max(sizes.front() / previous, previous / sizes.front());
        for (std::size_t j = 1; j < sizes.size(); ++j)
            ratio = std::max(ratio, std::max(sizes[j] / sizes[j - 1], sizes[j - 1] / sizes[j]));
        if (ratio > kMaxGradingRatio * (1.0 + 1e-9))
            throw std::invalid_argument(zone_name(k) + ": neighbouring cells differ by a factor of " +
                                        std::to_string(ratio) + ", more than " + std::to_string(kMaxGradingRatio) +
                                        " (lengthen the zone or bring its cell nearer the previous zone's)");
        for (double s : sizes) lines.push_back(lines.back() + s);
        lines.back() = zones[k].to;  // no round-off drift between zones
        start = zones[k].to;
        previous = sizes.back();
    }
    return lines;
}

}  // namespace pilempm::mpm
