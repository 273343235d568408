#pragma once
// Smith (1960) soil acting on the axial DOFs of pile nodes: an elastic-perfectly plastic
// spring of ultimate resistance R_u and quake Q (stiffness R_u / Q) plus a linear dashpot.
// Shaft springs resist both ways; the toe spring pushes only (the toe can lift off).
// Structure of arrays over soil points; the dashpots are handed to the pile, which takes
// them semi-implicitly (stable for any damping).
#include <vector>

#include "fem/dynamics/explicit_pile.hpp"
#include "fem/dynamics/pile_soil_reaction.hpp"

namespace pilempm::coupling {

struct SmithSoil final : fem::PileSoilReaction {
    std::vector<int> node;           // pile node the point acts on
    std::vector<double> ultimate;    // R_u, N
    std::vector<double> quake;       // Q, m
    std::vector<double> dashpot;     // c, N s/m (Smith-viscous J R_u, or Case J_c Z share)
    std::vector<char> toe;           // 1: compression only
    // State: plastic offset of each spring (m, downward), and the energy record.
    std::vector<double> plastic;
    std::vector<double> force;       // static resistance on the pile, N, up positive
    double plastic_work = 0.0;       // J

    std::size_t size() const { return node.size(); }
    void add_point(int pile_node, double r_u, double q, double c, bool is_toe);
    double total_ultimate() const;
    double elastic_energy() const;   // J, stored in the springs
    // Stable step bound of the springs on the pile's lumped masses.
    double stable_time_step(const fem::ExplicitPile& pile) const override;
    // Hands the dashpots to the pile (once, before stepping).
    void attach_dashpots(fem::ExplicitPile& pile) const;
    // Static resistance at u_n, added to the pile's external forces; updates plasticity.
    void add_forces(fem::ExplicitPile& pile) override;
};

}  // namespace pilempm::coupling
