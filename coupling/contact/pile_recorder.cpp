#include "coupling/contact/pile_recorder.hpp"

#include <algorithm>

namespace pilempm::coupling {

void PileRecorder::add_columns(std::vector<std::string>& columns) const {
    for (const char* c : {"pile_head_settlement_m", "pile_head_force_N", "outer_shaft_resistance_N",
                          "inner_shaft_resistance_N", "base_resistance_N", "contact_points", "contact_points_inside",
                          "max_penetration_over_cell", "pile_toe_elevation_m", "pile_head_velocity_m_s", "enthru_J"})
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
    row.push_back(up(SurfaceSide::Toe));
    row.push_back(static_cast<double>(t.points_in_contact));
    row.push_back(static_cast<double>(t.points_inside));
    row.push_back(t.max_penetration / std::min(m.grid.spacing[0], m.grid.spacing[1]));
    // The toe where the surface was placed this step (its lowest node, soil's frame).
    const auto& x = pile_.surface().x;
    double toe = 1e300;
    for (std::size_t k = 1; k < x.size(); k += 2) toe = std::min(toe, x[k]);
    row.push_back(x.empty() ? pile_.frame().toe_elevation : toe);
    row.push_back(-pile_.pile().head_velocity());  // down positive: with the head force, F and Z v of a blow
    row.push_back(pile_.enthru());
}

}  // namespace pilempm::coupling
