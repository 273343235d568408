// The rod pile's fast paths give the very numbers of the generic ones (the drivability
// outputs are compared bit for bit across such changes).
#include <gtest/gtest.h>

#include "fem/dynamics/explicit_pile.hpp"
#include "fem/mesh/pile_geometry.hpp"
#include "fem/mesh/rod_mesh.hpp"

using namespace pilempm::fem;

namespace {

const LinearElasticSteel kSteel{210e9, 0.3, 7850.0};

PileMesh tapered_rod() {
    return mesh_rod(make_pile_geometry({{6.0, 1.2, 0.03}, {4.0, 1.0, 0.02}}), 0.25);
}

// The same rod cut into two blocks: no longer one chain, so the generic element loop.
PileMesh in_two_blocks(PileMesh mesh) {
    ElementBlock& first = mesh.blocks[0];
    ElementBlock second = first;
    const int half = first.num_elements() / 2;
    first.connectivity.resize(2 * half);
    first.section_area.resize(half);
    second.connectivity.erase(second.connectivity.begin(), second.connectivity.begin() + 2 * half);
    second.section_area.erase(second.section_area.begin(), second.section_area.begin() + half);
    mesh.blocks.push_back(second);
    return mesh;
}

// Steps under a head force that rises and falls, on a damped toe.
void strike(ExplicitPile& pile, int steps) {
    const double dt = 0.9 * pile.stable_time_step();
    for (int n = 0; n < steps; ++n) {
        pile.compute_internal_force();
        pile.clear_external_force();
        pile.add_head_force(-1e6 * (n < steps / 4 ? n : 0));
        pile.advance_velocity(n % 5 == 0 ? 0.5 * dt : dt);  // the half steps of restarts
        pile.advance_displacement(dt);
    }
    pile.compute_internal_force();
}

}  // namespace

TEST(ExplicitPileFastPaths, RodChainGivesTheGenericForcesExactly) {
    const ToeSupport toe{ToeCondition::Dashpot, 2e7};
    ExplicitPile chain(tapered_rod(), kSteel, toe);
    ExplicitPile generic(in_two_blocks(tapered_rod()), kSteel, toe);
    strike(chain, 400);
    strike(generic, 400);
    EXPECT_EQ(chain.internal_force(), generic.internal_force());
    EXPECT_EQ(chain.displacement(), generic.displacement());
    EXPECT_EQ(chain.velocity(), generic.velocity());
    EXPECT_EQ(chain.toe_reaction(), generic.toe_reaction());
    std::vector<double> a, b;
    chain.axial_stress(a);
    generic.axial_stress(b);
    EXPECT_EQ(a, b);
}

TEST(ExplicitPileFastPaths, DampingAddedAfterAStepActs) {
    // The velocity update keeps its coefficients between steps; a dashpot added after
    // a step (at rest, so the state stays zero) must still count.
    ExplicitPile late(tapered_rod(), kSteel, {ToeCondition::Free, 0.0});
    late.compute_internal_force();
    late.clear_external_force();
    late.advance_velocity(0.9 * late.stable_time_step());
    ExplicitPile early(tapered_rod(), kSteel, {ToeCondition::Free, 0.0});
    early.add_nodal_damping(early.mesh().axial_dof(3), 5e6);
    late.add_nodal_damping(late.mesh().axial_dof(3), 5e6);
    strike(early, 200);
    strike(late, 200);
    EXPECT_EQ(early.velocity(), late.velocity());
    EXPECT_EQ(early.toe_reaction(), late.toe_reaction());
    EXPECT_NE(early.toe_reaction(), 0.0);
}
