#include "coupling/wave_equation/drivability_verification.hpp"

#include <cmath>
#include <numbers>

#include "fem/dynamics/section_gauge.hpp"

namespace pilempm::coupling {

namespace {

double impedance(const fem::ExplicitPile& pile) {
    double L = 0.0;
    for (int n = 0; n < pile.mesh().num_nodes(); ++n) L = std::max(L, pile.mesh().z(n));
    const fem::SectionGauge head(pile.mesh(), L);
    return head.area() * pile.steel().youngs_modulus / pile.steel().wave_speed();
}

}  // namespace

std::vector<VerificationCheck> check_static_push(const DrivabilitySetup& s, const SoilCase& c, double depth) {
    const auto srd = srd_for_driving(s, c, depth);
    fem::ExplicitPile pile(s.mesh, s.steel, {});
    SmithSoil soil = make_smith_soil(pile, srd, s.smith, impedance(pile));
    soil.attach_dashpots(pile);
    // Far enough to mobilise the toe: its quake plus the pile's elastic shortening.
    const double push = 3.0 * (s.smith.toe_quake + srd.total() * pile.mesh().z(pile.mesh().num_nodes() - 1) /
                                                       (s.steel.youngs_modulus * M_PI * s.outer_diameter * s.wall_thickness));
    const double capacity = static_push_capacity(pile, soil, 2e-3, push);
    return {make_check("static_push_resistance_N", capacity, srd.total(), 0.01, true,
                       "slow push of the Smith pile against the SRD at " + std::to_string(depth) + " m")};
}

std::vector<VerificationCheck> check_bearing_graph(const Table& g) {
    if (g.rows() < 2) throw std::invalid_argument("bearing_graph_monotonic needs a bearing graph of 2 or more points");
    int violations = 0;
    for (std::size_t r = 1; r < g.rows(); ++r) {
        if (g.data[0][r] != g.data[0][r - 1]) continue;  // a new energy level starts
        if (!(g.data[1][r] > g.data[1][r - 1])) continue;
        if (!(g.data[3][r] >= g.data[3][r - 1])) ++violations;  // blows per 0.25 m rise
        if (!(g.data[2][r] <= g.data[2][r - 1])) ++violations;  // set falls
    }
    return {make_check("bearing_graph_monotonicity_violations", violations, 0.0, 0.0, false,
                       "blow count rises and set falls as the resistance grows")};
}

std::vector<VerificationCheck> check_blow_energy(const DrivabilitySetup& s, const SoilCase& c, double depth) {
    const auto srd = srd_for_driving(s, c, depth);
    fem::ExplicitPile pile(s.mesh, s.steel, {});
    SmithSoil soil = make_smith_soil(pile, srd, s.smith, impedance(pile));
    soil.attach_dashpots(pile);
    const BlowOutcome b = simulate_blow(pile, soil, s.hammer, s.ram_element_size, s.driving.blow);
    const double accounted = b.energy_pile + b.energy_hammer + b.energy_soil_plastic + b.energy_soil_damping +
                             b.energy_soil_elastic;
    return {make_check("blow_energy_accounted_J", accounted, b.energy_in, 0.01, true,
                       "hammer energy = pile + hammer remainder + soil plastic + damping + elastic")};
}

std::vector<VerificationCheck> check_danish_formula(const DrivabilitySetup& s, const PenetrationResult& p) {
    const double E = p.last.enthru, R = p.srd_shaft + p.srd_toe;
    double L = 0.0;
    for (int n = 0; n < s.mesh.num_nodes(); ++n) L = std::max(L, s.mesh.z(n));
    const double area = std::numbers::pi * (s.outer_diameter - s.wall_thickness) * s.wall_thickness;
    const double elastic = std::sqrt(2.0 * E * L / (area * s.steel.youngs_modulus));
    const double danish = E / R - 0.5 * elastic;
    VerificationCheck c = make_check("set_per_blow_vs_danish_formula_m", p.set, danish, 3.0, false,
                                     "same order as the Danish formula with ENTHRU: within a factor of 3");
    c.within_factor = true;
    c.passed = danish > 0.0 && p.set > 0.0 && p.set <= 3.0 * danish && p.set >= danish / 3.0;
    return {c};
}

}  // namespace pilempm::coupling
