// Element operators and the explicit pile: closed-form checks.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>

#include "fem/elements/element_kernels.hpp"
#include "fem/dynamics/explicit_pile.hpp"
#include "fem/mesh/pile_geometry.hpp"
#include "fem/mesh/rod_mesh.hpp"

using namespace pilempm::fem;

namespace {
const LinearElasticSteel kSteel{210e9, 0.3, 7850.0};

// One quad of the tube wall, counter-clockwise in (r, z).
const double kQuad[8] = {3.83, 0.0, 3.9, 0.0, 3.9, 0.05, 3.83, 0.05};

// One explicit step under a constant downward head force.
void push_head(ExplicitPile& pile, double force, double dt) {
    pile.compute_internal_force();
    pile.clear_external_force();
    pile.add_head_force(-force);
    pile.advance_velocity(dt);
    pile.advance_displacement(dt);
}

std::array<double, 8> times(const double* K, const std::array<double, 8>& u) {
    std::array<double, 8> f{};
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) f[i] += K[i * 8 + j] * u[j];
    return f;
}
}  // namespace

TEST(RodElement, StiffnessMassAndStressFollowTheBar) {
    const double z[2] = {1.0, 1.5}, area = 0.02;
    double K[4], m[2], S[2];
    rod2_operators(z, area, kSteel, K, m, S);
    EXPECT_NEAR(K[0], 210e9 * area / 0.5, 1e-6 * K[0]);
    EXPECT_NEAR(K[1], -K[0], 1e-9 * K[0]);
    EXPECT_NEAR(m[0] + m[1], 7850.0 * area * 0.5, 1e-12);
    // Stretching by 1e-4 gives tension E * strain.
    EXPECT_NEAR(S[0] * 0.0 + S[1] * 0.5e-4, 210e9 * 1e-4, 1.0);
    // Largest frequency 2c/L, so the stable step is L/c.
    const double md[2] = {m[0], m[1]};
    EXPECT_NEAR(2.0 / element_max_frequency(K, md, 2), 0.5 / kSteel.wave_speed(), 1e-12);
}

TEST(AxisymmetricQuad, AxialTranslationIsFreeOfForce) {
    double K[64], m[4], S[8];
    axisym_quad4_operators(kQuad, kSteel, K, m, S);
    const auto f = times(K, {0, 1, 0, 1, 0, 1, 0, 1});
    for (double fi : f) EXPECT_NEAR(fi, 0.0, 1e-6 * K[0]);
    // A radial translation stretches the hoop: not a free motion of a ring.
    const auto g = times(K, {1, 0, 1, 0, 1, 0, 1, 0});
    EXPECT_GT(std::abs(g[0]), 1e-3 * K[0]);
}

TEST(AxisymmetricQuad, MassIsTheRingMass) {
    double K[64], m[4], S[8];
    axisym_quad4_operators(kQuad, kSteel, K, m, S);
    const double exact = 7850.0 * std::numbers::pi * (3.9 * 3.9 - 3.83 * 3.83) * 0.05;
    EXPECT_NEAR(m[0] + m[1] + m[2] + m[3], exact, 1e-10 * exact);
}

TEST(AxisymmetricQuad, UniaxialStressPatchTest) {
    // u_z = eps z, u_r = -nu eps r is uniaxial stress: sigma_z = E eps, no nodal force
    // but the end loads (sum of axial forces at the top = E eps A).
    double K[64], m[4], S[8];
    axisym_quad4_operators(kQuad, kSteel, K, m, S);
    const double eps = 1e-4, nu = kSteel.poisson_ratio;
    std::array<double, 8> u{};
    for (int a = 0; a < 4; ++a) {
        u[2 * a] = -nu * eps * kQuad[2 * a];
        u[2 * a + 1] = eps * kQuad[2 * a + 1];
    }
    double sigma = 0.0;
    for (int k = 0; k < 8; ++k) sigma += S[k] * u[k];
    EXPECT_NEAR(sigma, 210e9 * eps, 1e-8 * 210e9 * eps);
    const auto f = times(K, u);
    const double area = std::numbers::pi * (3.9 * 3.9 - 3.83 * 3.83);
    EXPECT_NEAR(f[5] + f[7], 210e9 * eps * area, 1e-8 * 210e9 * eps * area);
    EXPECT_NEAR(f[1] + f[3], -210e9 * eps * area, 1e-8 * 210e9 * eps * area);
    // No radial end forces in uniaxial stress: the radial rows sum to zero on each face.
    EXPECT_NEAR(f[0] + f[2] + f[4] + f[6], 0.0, 1e-6 * 210e9 * eps * area);
}

TEST(PileGeometry, TaperJoinsSegmentsOfDifferentWall) {
    const auto g = make_pile_geometry({{10.0, 2.0, 0.04}, {20.0, 2.0, 0.06}}, 4.0);
    EXPECT_DOUBLE_EQ(g.length(), 30.0);
    EXPECT_NEAR(g.inner_radius_at(0.0), 0.94, 1e-12);
    EXPECT_NEAR(g.inner_radius_at(29.0), 0.96, 1e-12);
    // Taper of 4 x 0.02 m = 0.08 m above the joint at z = 20 m.
    EXPECT_NEAR(g.inner_radius_at(20.04), 0.95, 1e-12);
}

TEST(ExplicitPile, MomentumEqualsImpulseOfTheHeadForce) {
    const auto geometry = make_pile_geometry({{10.0, 0.6, 0.0125}});
    ExplicitPile pile(mesh_rod(geometry, 0.1), kSteel, {ToeCondition::Free, 0.0});
    const double dt = 0.9 * pile.stable_time_step(), force = 1e6;
    const int steps = 500;
    for (int n = 0; n < steps; ++n) push_head(pile, force, dt);
    double p = 0.0;
    const auto& v = pile.velocity();
    for (std::size_t i = 0; i < v.size(); ++i) p += pile.operators().lumped_mass[i] * v[i];
    EXPECT_NEAR(p, -force * steps * dt, 1e-9 * force * steps * dt);
}

TEST(ExplicitPile, FixedToeReactsWhatTheHeadPushes) {
    // Under a constant head load the undamped pile oscillates about the static state, so
    // the toe reaction averaged over many round trips tends to the load.
    const auto geometry = make_pile_geometry({{5.0, 0.6, 0.0125}});
    ExplicitPile pile(mesh_rod(geometry, 0.1), kSteel, {ToeCondition::Fixed, 0.0});
    const double dt = 0.9 * pile.stable_time_step(), force = 1e6;
    double sum = 0.0;
    const int steps = 20000;
    for (int n = 0; n < steps; ++n) {
        push_head(pile, force, dt);
        sum += pile.toe_reaction();
    }
    EXPECT_NEAR(sum / steps, force, 0.01 * force);  // time-averaged over many round trips
}
