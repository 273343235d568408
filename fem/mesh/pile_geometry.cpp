#include "fem/mesh/pile_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace pilempm::fem {
namespace {

template <class Field>
double interpolate(const std::vector<PileStation>& s, double z, Field field) {
    if (s.empty()) throw std::logic_error("PileGeometry has no stations");
    if (z <= s.front().z) return field(s.front());
    for (std::size_t i = 1; i < s.size(); ++i) {
        if (z <= s[i].z) {
            const double dz = s[i].z - s[i - 1].z;
            if (dz <= 0.0) return field(s[i]);
            const double w = (z - s[i - 1].z) / dz;
            return (1.0 - w) * field(s[i - 1]) + w * field(s[i]);
        }
    }
    return field(s.back());
}

}  // namespace

double PileGeometry::inner_radius_at(double z) const {
    return interpolate(stations, z, [](const PileStation& p) { return p.inner_radius; });
}
double PileGeometry::outer_radius_at(double z) const {
    return interpolate(stations, z, [](const PileStation& p) { return p.outer_radius; });
}
double PileGeometry::area_at(double z) const {
    const double ri = inner_radius_at(z), ro = outer_radius_at(z);
    return std::numbers::pi * (ro * ro - ri * ri);
}

PileGeometry make_pile_geometry(const std::vector<PileSegment>& head_to_toe,
                                double taper_ratio) {
    if (head_to_toe.empty()) throw std::invalid_argument("pile has no segments");
    // Walk from the toe up so z grows.
    std::vector<PileSegment> seg(head_to_toe.rbegin(), head_to_toe.rend());
    PileGeometry g;
    double z = 0.0;
    auto radii = [](const PileSegment& s) {
        const double ro = 0.5 * s.outer_diameter;
        return std::pair{ro - s.wall_thickness, ro};
    };
    auto [ri0, ro0] = radii(seg.front());
    g.stations.push_back({0.0, ri0, ro0});
    for (std::size_t k = 0; k < seg.size(); ++k) {
        const auto [ri, ro] = radii(seg[k]);
        const double z_top = z + seg[k].length;
        if (k + 1 < seg.size()) {
            const auto [ri_up, ro_up] = radii(seg[k + 1]);
            const double jump = std::max(std::abs(ri_up - ri), std::abs(ro_up - ro));
            // The taper lies in the segment above, so this segment keeps its full length.
            const double taper = std::min(taper_ratio * jump, 0.5 * seg[k + 1].length);
            g.stations.push_back({z_top, ri, ro});
            if (jump > 0.0 && taper > 0.0) {
                const double zt = z_top + taper;
                g.stations.push_back({zt, ri_up, ro_up});
            } else if (jump > 0.0) {
                g.stations.push_back({z_top, ri_up, ro_up});
            }
        } else {
            g.stations.push_back({z_top, ri, ro});
        }
        z = z_top;
    }
    return g;
}

}  // namespace pilempm::fem
