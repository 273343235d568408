#include "coupling/contact/pile_recorder.hpp"

#include <algorithm>
#include <cmath>

#include "coupling/contact/plug_surface.hpp"

namespace pilempm::coupling {

namespace {

// The toe's annulus in the soil's frame: its elevation and radial extent (the surface's
// nodes within a tenth of a cell of the lowest; a cone's apex alone makes a point).
struct ToeExtent {
    double elevation = 0.0, inner = 0.0, outer = 0.0;
};

ToeExtent toe_extent(const CoupledPile& pile, double cell) {
    const auto& x = pile.surface().x;
    ToeExtent t{1e300, 1e300, 0.0};
    if (x.empty()) return {pile.frame().toe_elevation, 0.0, 0.0};
    for (std::size_t k = 1; k < x.size(); k += 2) t.elevation = std::min(t.elevation, x[k]);
    for (std::size_t k = 0; k + 1 < x.size(); k += 2)
        if (x[k + 1] < t.elevation + 0.1 * cell) t.inner = std::min(t.inner, x[k]), t.outer = std::max(t.outer, x[k]);
    return t;
}

// In one pass over the points: the mean excess pore pressure of those within a cell of the
// toe's annulus and a cell and a half below it, and of those within a cell outside the
// shaft in each third of its embedded length, the upper first (0 when dry or none there);
// and an open pile's soil plug, from the toe to the mean level of the soil's surface inside
// the wall (rings a cell wide to a quarter of a cell clear of it; 0 for a closed pile).
struct AtPile {
    double pore_pressure = 0.0, plug_length = 0.0;
    double shaft_pore_pressure[3] = {0.0, 0.0, 0.0};
};

AtPile at_pile(const mpm::MpmModel<2>& m, const ToeExtent& t, double h, double ground) {
    const auto& p = m.particles;
    const bool wet = !p.pore_pressure.empty(), open = t.inner >= 0.25 * h;
    const double embedded = ground - t.elevation;
    double sum = 0.0, shaft[3] = {0.0, 0.0, 0.0};
    PlugSurface plug(open ? t.inner - 0.25 * h : 0.0, h);
    int n = 0, shaft_n[3] = {0, 0, 0};
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double r = p.x[2 * i], z = p.x[2 * i + 1];
        if (wet && r >= t.inner - h && r <= t.outer + h && z <= t.elevation && z >= t.elevation - 1.5 * h)
            sum += p.pore_pressure[i], ++n;
        if (wet && embedded > 0.0 && r >= t.outer && r <= t.outer + h && z > t.elevation && z < ground) {
            const int k = std::min(2, static_cast<int>(3.0 * (ground - z) / embedded));
            shaft[k] += p.pore_pressure[i], ++shaft_n[k];
        }
        if (open) plug.add(r, z);
    }
    AtPile out{n ? sum / n : 0.0, open ? plug.mean_level(t.elevation) - t.elevation : 0.0};
    for (int k = 0; k < 3; ++k) out.shaft_pore_pressure[k] = shaft_n[k] ? shaft[k] / shaft_n[k] : 0.0;
    return out;
}

}  // namespace

void PileRecorder::add_columns(std::vector<std::string>& columns) const {
    for (const char* c : {"pile_head_settlement_m", "pile_head_force_N", "outer_shaft_resistance_N",
                          "inner_shaft_resistance_N", "shaft_resistance_N", "base_resistance_N", "contact_points", "contact_points_inside",
                          "max_penetration_over_cell", "pile_toe_elevation_m", "pile_head_velocity_m_s", "enthru_J",
                          "pile_max_compression_Pa", "pile_max_tension_Pa", "toe_pore_pressure_Pa", "plug_length_m", "pile_energy_J",
                          "pile_weight_work_J", "shaft_pore_pressure_upper_Pa", "shaft_pore_pressure_middle_Pa",
                          "shaft_pore_pressure_lower_Pa"})
        columns.push_back(c);
}

void PileRecorder::sample(const mpm::MpmModel<2>& m, const mpm::MpmSolver<2>&, std::vector<double>& row) const {
    const auto& t = pile_.contact().totals();
    // Resistance: the soil's force on the pile, up positive.
    auto up = [&](SurfaceSide s) { return t.force_by_side[static_cast<int>(s)][1]; };
    row.push_back(pile_.head_settlement());
    row.push_back(pile_.head_force());
    row.push_back(up(SurfaceSide::Outer));
    row.push_back(up(SurfaceSide::Inner));
    row.push_back(up(SurfaceSide::Outer) + up(SurfaceSide::Inner));  // a blow's peak shaft resistance is this sum's
    row.push_back(up(SurfaceSide::Toe));
    row.push_back(static_cast<double>(t.points_in_contact));
    row.push_back(static_cast<double>(t.points_inside));
    row.push_back(t.max_penetration / std::min(m.grid.spacing[0], m.grid.spacing[1]));
    // The toe where the surface was placed this step (its lowest node, soil's frame).
    const double h = std::min(m.grid.spacing[0], m.grid.spacing[1]);
    const ToeExtent toe = toe_extent(pile_, h);
    row.push_back(toe.elevation);
    row.push_back(-pile_.pile().head_velocity());  // down positive: with the head force, F and Z v of a blow
    row.push_back(pile_.enthru());
    pile_.pile().axial_stress(stress_);
    double compression = 0.0, tension = 0.0;
    for (double s : stress_) compression = std::max(compression, -s), tension = std::max(tension, s);
    row.push_back(compression);
    row.push_back(tension);
    const AtPile soil = at_pile(m, toe, h, ground_);
    row.push_back(soil.pore_pressure);
    row.push_back(soil.plug_length);
    row.push_back(pile_.pile().strain_energy() + pile_.pile().kinetic_energy(pile_.pile().velocity()));
    row.push_back(pile_.weight_work());
    for (double u : soil.shaft_pore_pressure) row.push_back(u);
}

}  // namespace pilempm::coupling
