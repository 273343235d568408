#include "mpm/grid/field_cut.hpp"

#include <algorithm>
#include <cmath>

namespace pilempm::mpm {

namespace {

// The side of p against the directed line c -> d: +1 left or on it, -1 right.
int side(const double* c, const double* d, const double* p) {
    const double cross = (d[0] - c[0]) * (p[1] - c[1]) - (d[1] - c[1]) * (p[0] - c[0]);
    return cross >= 0.0 ? 1 : -1;
}

}  // namespace

void FieldCut::bound() {
    x_low = 1e300, x_high = -1e300;
    for (std::size_t k = 0; k < vertices.size(); k += 2) {
        x_low = std::min(x_low, vertices[k]);
        x_high = std::max(x_high, vertices[k]);
    }
}

bool FieldCut::crosses(const double* a, const double* b) const {
    if (std::max(a[0], b[0]) < x_low || std::min(a[0], b[0]) > x_high) return false;
    const int n = num_vertices();
    if (n < 2) return false;
    const double lo = std::min(a[1], b[1]), hi = std::max(a[1], b[1]);
    const double* v = vertices.data();
    if (hi < v[1] || lo > v[2 * n - 1]) return false;
    // The first polyline segment that reaches lo (vertices ascend in y).
    int k = 0, top = n - 1;
    while (top - k > 1) {
        const int mid = (k + top) / 2;
        (v[2 * mid + 1] <= lo ? k : top) = mid;
    }
    // Crossings counted with half-open ends, so a line through a vertex counts once; b is
    // across when the count is odd.
    int crossings = 0;
    for (; k < n - 1 && v[2 * k + 1] <= hi; ++k) {
        const double* c = v + 2 * k;
        const double* d = v + 2 * k + 2;
        if (side(c, d, a) == side(c, d, b)) continue;
        const double ca = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        const double da = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
        if ((ca > 0.0) != (da > 0.0)) ++crossings;
    }
    return crossings % 2 == 1;
}

int FieldCut::normal_away_from(const double* p, double* n) const {
    const int count = num_vertices();
    double best = 1e300;
    int nearest = -1;
    n[0] = n[1] = 0.0;
    for (int k = 0; k + 1 < count; ++k) {
        const double* c = &vertices[2 * k];
        const double* d = c + 2;
        const double ex = d[0] - c[0], ey = d[1] - c[1], length2 = ex * ex + ey * ey;
        if (!(length2 > 0.0)) continue;
        const double t = std::clamp(((p[0] - c[0]) * ex + (p[1] - c[1]) * ey) / length2, 0.0, 1.0);
        const double dx = p[0] - c[0] - t * ex, dy = p[1] - c[1] - t * ey, distance2 = dx * dx + dy * dy;
        if (distance2 >= best) continue;
        best = distance2;
        nearest = k;
        // The segment's right-hand normal points away from a point on its left, and back.
        const double s = side(c, d, p) / std::sqrt(length2);
        n[0] = s * ey;
        n[1] = -s * ex;
    }
    return nearest;
}

void apply_field_cuts(const Grid<2>& grid, const std::vector<FieldCut>& cuts, const double* x, const double* half,
                      Stencil<2>& s) {
    // The stencil's nodes are those of the cells the point's domain reaches along x: a line
    // from the point to any of them stays within those cells' x range, and most points (the
    // soil away from the wall) have no cut there.
    const double reach = std::abs(half[0]) + std::abs(half[2]);
    const double low = grid.coordinate(0, grid.cell_beyond(0, x[0] - reach));
    const double high = grid.coordinate(0, grid.cell_beyond(0, x[0] + reach) + 1);
    bool near = false;
    for (const auto& cut : cuts) near = near || (high >= cut.x_low && low <= cut.x_high);
    if (!near) return;
    for (int k = 0; k < s.count; ++k) {
        const int stored = s.e[k].node / grid.fields;
        const auto ijk = grid.stored_ijk(stored);
        const double node[2] = {grid.coordinate(0, ijk[0]), grid.coordinate(1, ijk[1])};
        for (const auto& cut : cuts)
            if (cut.crosses(x, node)) s.e[k].node += cut.offset;
    }
}

}  // namespace pilempm::mpm
