// The damping of damped stages on the pile: a free rod moving down at v0 with a vibration
// on top keeps its momentum to round-off, and the vibration about the rigid motion decays
// as exp(-c t) per step (no forces: the velocities alone); a rod moving rigidly is left as
// it is (no drag on a steadily pushed pile).
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
