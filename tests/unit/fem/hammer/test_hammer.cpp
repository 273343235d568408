// Hammer models: the seed 001 pulse, cushion restitution, contact momentum.
#include <gtest/gtest.h>

#include <cmath>

#include "fem/hammer/hammer.hpp"
#include "fem/mesh/pile_geometry.hpp"
#include "fem/mesh/rod_mesh.hpp"

using namespace pilempm;

TEST(HalfSinePulse, Seed001PeakForce) {
    // Seed 001: 220 t, 2 m, eta 0.95, t_i 20 ms -> 102 825 kN (16 365 kN/rad).
    const double f = fem::half_sine_peak_force(220e3, 2.0, 0.95, 0.020, 9.81);
    EXPECT_NEAR(f, 102825e3, 1e-4 * 102825e3);
    EXPECT_NEAR(f / (2.0 * M_PI), 16365e3, 1e-4 * 16365e3);
    fem::PrescribedForce p{f, 0.020, {}, {}};
    EXPECT_NEAR(p.at(0.010), f, 1e-9 * f);
    EXPECT_EQ(p.at(0.021), 0.0);
}

TEST(ForceTable, InterpolatesLinearly) {
    fem::PrescribedForce p{0, 0, {0.0, 0.001, 0.003}, {0.0, 2e6, 0.0}};
    EXPECT_NEAR(p.at(0.0005), 1e6, 1e-6);
    EXPECT_NEAR(p.at(0.002), 1e6, 1e-6);
    EXPECT_EQ(p.at(0.004), 0.0);
}

namespace {
// One central-difference step of pile and hammer together, as the pile-wave driver does.
void step(fem::ExplicitPile& pile, fem::HammerChain& chain, double dt) {
    pile.compute_internal_force();
    pile.clear_external_force();
    chain.compute_forces(pile);
    pile.advance_velocity(dt);
    chain.advance_velocity(dt);
    chain.resolve_contacts(dt, pile);
    pile.advance_displacement(dt);
    chain.advance_displacement(dt);
}

// A rigid ram on a cushion on a short, very stiff pile with a fixed toe: the ram
// leaves with e times its impact speed.
double rebound_ratio(double restitution) {
    const fem::LinearElasticSteel steel{210e9, 0.3, 7850.0};
    const auto g = fem::make_pile_geometry({{1.0, 2.0, 0.5}});
    fem::ExplicitPile pile(fem::mesh_rod(g, 0.1), steel, {fem::ToeCondition::Fixed, 0.0});
    fem::RamCushionSpec spec;
    spec.ram.mass = 1000.0;
    spec.impact_velocity = 2.0;
    spec.hammer_cushion = fem::CushionSpec{1e8, restitution};
    spec.gravity = 0.0;
    fem::HammerChain chain(spec, 0.1);
    const double dt = 0.5 * chain.stable_time_step(pile.head_mass(), pile.operators().max_frequency);
    int n = 0;
    while (chain.ram_velocity() < 0.0 && ++n < 200000) step(pile, chain, dt);
    // Let the cushion finish unloading.
    while (chain.force_on_head() > 0.0 && ++n < 400000) step(pile, chain, dt);
    return chain.ram_velocity() / spec.impact_velocity;
}
}  // namespace

TEST(HammerCushion, ReboundFollowsTheCoefficientOfRestitution) {
    EXPECT_NEAR(rebound_ratio(0.8), 0.8, 0.01);
    EXPECT_NEAR(rebound_ratio(0.5), 0.5, 0.01);
}

TEST(RigidContact, ConservesMomentumAndNeverPulls) {
    const fem::LinearElasticSteel steel{210e9, 0.3, 7850.0};
    const auto g = fem::make_pile_geometry({{10.0, 0.6, 0.0125}});
    fem::ExplicitPile pile(fem::mesh_rod(g, 0.1), steel, {fem::ToeCondition::Free, 0.0});
    fem::RamCushionSpec spec;
    spec.ram.mass = 500.0;
    spec.impact_velocity = 3.0;
    spec.gravity = 0.0;
    fem::HammerChain chain(spec, 0.1);
    const double dt = 0.9 * pile.stable_time_step();
    for (int n = 0; n < 3000; ++n) {
        step(pile, chain, dt);
        EXPECT_GE(chain.force_on_head(), 0.0);
    }
    double p = spec.ram.mass * chain.ram_velocity();
    const auto& v = pile.velocity();
    for (std::size_t i = 0; i < v.size(); ++i) p += pile.operators().lumped_mass[i] * v[i];
    EXPECT_NEAR(p, -spec.ram.mass * spec.impact_velocity, 1e-9 * spec.ram.mass * spec.impact_velocity);
}
