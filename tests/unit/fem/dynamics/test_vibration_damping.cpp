// The damping of damped stages on the pile: a free rod moving down at v0 with a vibration
// on top keeps its momentum to round-off, and the vibration about the rigid motion decays
// as exp(-c t) per step (no forces: the velocities alone); a rod moving rigidly is left as
// it is (no drag on a steadily pushed pile). The split Cundall damping of quasi-static
// stages: momentum kept through the vibration's damping, the rigid motion braked by alpha.
#include <gtest/gtest.h>

#include <cmath>

#include "fem/dynamics/explicit_pile.hpp"
#include "fem/mesh/pile_geometry.hpp"
#include "fem/mesh/rod_mesh.hpp"

using namespace pilempm::fem;

namespace {

const LinearElasticSteel kSteel{210e9, 0.3, 7850.0};

double momentum(const ExplicitPile& pile) {
    double p = 0.0;
    for (std::size_t i = 0; i < pile.velocity().size(); ++i) p += pile.operators().lumped_mass[i] * pile.velocity()[i];
    return p;
}

}  // namespace

TEST(VibrationDamping, KeepsTheMomentumAndDecaysTheVibrationAboutTheRigidMotion) {
    ExplicitPile pile(mesh_rod(make_pile_geometry({{10.0, 1.0, 0.02}}), 0.25), kSteel, ToeSupport{ToeCondition::Free, 0.0});
    const int n = static_cast<int>(pile.velocity().size());
    std::vector<double> u(n, 0.0), v(n);
    const double v0 = -0.3;
    for (int i = 0; i < n; ++i) v[i] = v0 + 0.1 * std::sin(3.0 * i);
    pile.restore(u, v);
    double rigid = momentum(pile);
    double mass = 0.0;
    for (double m : pile.operators().lumped_mass) mass += m;
    rigid /= mass;
    const double rate = 50.0, dt = 1e-4;
    const int steps = 100;
    pile.set_vibration_damping(rate);
    const double p0 = momentum(pile);
    for (int s = 0; s < steps; ++s) {
        pile.clear_external_force();
        pile.advance_velocity(dt);  // no internal force computed: u stays 0, f_int 0
    }
    EXPECT_NEAR(momentum(pile), p0, 1e-12 * std::abs(p0));
    const double decay = std::exp(-rate * dt * steps);
    for (int i = 0; i < n; ++i) EXPECT_NEAR(pile.velocity()[i] - rigid, (v[i] - rigid) * decay, 1e-12) << "DOF " << i;
    // Rigid motion alone: untouched.
    std::vector<double> still(n, v0);
    pile.restore(u, still);
    for (int s = 0; s < steps; ++s) pile.advance_velocity(dt);
    for (int i = 0; i < n; ++i) EXPECT_NEAR(pile.velocity()[i], v0, 1e-15);
}

// Split damping (quasi-static stages): the vibration's damping forces sum to zero, so a free
// rod vibrating about a rigid motion keeps its momentum to round-off while its vibration
// dies; its rigid motion takes Cundall's alpha alone: a rod at rest under its weight falls
// at (1 - alpha) g once it moves (the first step starts at rest: no damping in it).
TEST(VibrationDamping, SplitDampingKeepsTheMomentumOfAVibratingRodAndBrakesItsRigidMotion) {
    ExplicitPile pile(mesh_rod(make_pile_geometry({{10.0, 1.0, 0.02}}), 0.25), kSteel, ToeSupport{ToeCondition::Free, 0.0});
    const int n = static_cast<int>(pile.velocity().size());  // a rod: every DOF axial
    const double alpha = 0.7, v0 = -0.3;
    std::vector<double> u(n), v(n, v0);
    for (int i = 0; i < n; ++i) u[i] = 1e-4 * std::sin(0.7 * i);
    pile.restore(u, v);
    pile.set_split_damping(alpha);
    const double dt = 0.9 * pile.damped_stable_time_step();
    const double p0 = momentum(pile);
    double mass = 0.0;
    for (double m : pile.operators().lumped_mass) mass += m;
    auto vibration_energy = [&] {  // strain energy and kinetic energy about the rigid motion
        pile.compute_internal_force();
        return pile.strain_energy() + pile.kinetic_energy(pile.velocity()) - 0.5 * p0 * p0 / mass;
    };
    const double e0 = vibration_energy();
    for (int s = 0; s < 400; ++s) {
        pile.compute_internal_force();
        pile.clear_external_force();
        pile.advance_velocity(dt);
        pile.advance_displacement(dt);
    }
    EXPECT_NEAR(momentum(pile), p0, 1e-10 * std::abs(p0));
    EXPECT_LT(vibration_energy(), 0.01 * e0);

    // At rest under its weight: one undamped step, then (1 - alpha) g.
    const double g = 9.81;
    pile.restore(std::vector<double>(n, 0.0), std::vector<double>(n, 0.0));
    const int steps = 50;
    for (int s = 0; s < steps; ++s) {
        pile.compute_internal_force();
        pile.clear_external_force();
        for (int i = 0; i < n; ++i) pile.add_nodal_force(i, -pile.operators().lumped_mass[i] * g);
        pile.advance_velocity(dt);
        pile.advance_displacement(dt);
    }
    for (int i = 0; i < n; ++i) EXPECT_NEAR(pile.velocity()[i], -g * dt * (1.0 + (steps - 1) * (1.0 - alpha)), 1e-9);
}
