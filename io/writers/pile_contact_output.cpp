#include "io/writers/pile_contact_output.hpp"

#include <algorithm>
#include <cmath>

#include "core/conventions.hpp"

namespace pilempm::io {

std::vector<Table> pile_traction_profiles(const coupling::CoupledPile& pile) {
    using coupling::SurfaceSide;
    const coupling::ContactSurface& s = pile.surface();
    const auto& force = pile.contact().segment_force();
    const std::vector<double> mean = pile.stage_mean_segment_force();
    const std::vector<std::string> columns = {"height_above_toe_m", "elevation_m", "radius_m", "length_m",
                                              "normal_traction_compression_Pa", "shear_traction_Pa",
                                              "stage_mean_normal_traction_compression_Pa", "stage_mean_shear_traction_Pa"};
    std::vector<Table> out;
    for (const auto& [side, name] : {std::pair{SurfaceSide::Outer, "outer"}, std::pair{SurfaceSide::Inner, "inner"},
                                     std::pair{SurfaceSide::Toe, "toe"}}) {
        struct Row {
            double key, height, elevation, radius, length, normal, shear, mean_normal, mean_shear;
        };
        std::vector<Row> rows;
        for (int k = 0; k < s.num_segments(); ++k) {
            if (s.side[k] != side) continue;
            const double* a = &s.x[2 * s.a[k]];
            const double* b = &s.x[2 * s.b[k]];
            const double r = 0.5 * (a[0] + b[0]), z = 0.5 * (a[1] + b[1]);
            const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
            const double nr = (b[1] - a[1]) / len, nz = -(b[0] - a[0]) / len;  // outward
            const double area = full_ring(r * len);
            // Compression across the segment, and the shear up a shaft or outward along the toe.
            auto normal = [&](const double* f) { return -(f[0] * nr + f[1] * nz) / area; };
            auto shear = [&](const double* f) { return (side == SurfaceSide::Toe ? f[0] : f[1]) / area; };
            const double* last = &force[2 * k];
            const double* stage = mean.empty() ? last : &mean[2 * k];  // no step taken: the last step's
            // Height above the toe in the pile's own frame (its reference mesh, toe at z = 0).
            const auto& ref = pile.pile().mesh().coordinates;
            const double height = 0.5 * (ref[2 * s.a[k] + 1] + ref[2 * s.b[k] + 1]);
            rows.push_back({side == SurfaceSide::Toe ? r : z, height, z, r, len, normal(last), shear(last), normal(stage),
                            shear(stage)});
        }
        std::sort(rows.begin(), rows.end(), [](const Row& x, const Row& y) { return x.key < y.key; });
        Table t(std::string("pile_tractions_") + name, columns);
        for (const auto& w : rows)
            t.add_row({w.height, w.elevation, w.radius, w.length, w.normal, w.shear, w.mean_normal, w.mean_shear});
        out.push_back(std::move(t));
    }
    return out;
}

}  // namespace pilempm::io
