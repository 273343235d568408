// Issue 13, verification 3: a free collision of an FE bar (the pile's axisymmetric wall)
// and an MPM bar of the same tube section, material and length, through the penalty
// contact, in axisymmetry. Pile + soil momentum is conserved to round-off (1e-10) at every
// step; the penetration stays below 1 % of the cell; the stage's mean segment forces times
// its time are the impulse the pile took (its momentum, to round-off); and, as 1D wave
// theory has it for equal impedances and lengths, the striker stops and the struck bar leaves at the impact speed.
// Also the surface: the wall's boundary edges, outward and named by side; a solid pile's
// has none on the axis, and its axis nodes stay on the axis.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "core/conventions.hpp"
#include "coupling/contact/coupled_pile.hpp"
#include "fem/mesh/axisymmetric_mesher.hpp"
#include "mpm/setup/model_setup.hpp"

using namespace pilempm;
using namespace pilempm::coupling;

namespace {

constexpr double kInner = 1.0, kOuter = 1.2, kLength = 0.95;
constexpr double kModulus = 100.0e6, kDensity = 2000.0;

fem::PileMesh tube_mesh(double element_size) {
    fem::PileGeometry g;
    g.stations = {{0.0, kInner, kOuter}, {kLength, kInner, kOuter}};
    return fem::mesh_axisymmetric_wall(g, element_size, 4, std::string(PILEMPM_SOURCE_DIR) + "/meshes/pile_wall_axisymmetric.geo");
}

fem::LinearElasticSteel bar_material() {
    fem::LinearElasticSteel s;
    s.youngs_modulus = kModulus;
    s.poisson_ratio = 0.0;
    s.density = kDensity;
    return s;
}

}  // namespace

TEST(PileContactSurface, TheWallsBoundaryIsOutwardAndNamedBySide) {
    const auto mesh = tube_mesh(0.05);
    const ContactSurface s = pile_contact_surface(mesh);
    double length[5] = {};
    for (int k = 0; k < s.num_segments(); ++k) {
        const double* xa = &s.x[2 * s.a[k]];
        const double* xb = &s.x[2 * s.b[k]];
        length[static_cast<int>(s.side[k])] += std::hypot(xb[0] - xa[0], xb[1] - xa[1]);
        // The outward normal (t_y, -t_x) points away from the wall's mid-surface.
        const double nr = xb[1] - xa[1], nz = -(xb[0] - xa[0]);
        const double mr = 0.5 * (xa[0] + xb[0]) - 0.5 * (kInner + kOuter), mz = 0.5 * (xa[1] + xb[1]) - 0.5 * kLength;
        EXPECT_GT(nr * mr + nz * mz, 0.0) << "segment " << k;
    }
    EXPECT_NEAR(length[static_cast<int>(SurfaceSide::Outer)], kLength, 1e-12);
    EXPECT_NEAR(length[static_cast<int>(SurfaceSide::Inner)], kLength, 1e-12);
    EXPECT_NEAR(length[static_cast<int>(SurfaceSide::Toe)], kOuter - kInner, 1e-12);
    EXPECT_NEAR(length[static_cast<int>(SurfaceSide::Head)], kOuter - kInner, 1e-12);
}

namespace {

struct Collision {
    double momentum_error, penetration_over_cell, struck, striker, rigid_energy, impulse_error;
    int substeps;
};

// The MPM striker: the same tube below the pile's toe, moving up at v0, on cells of h.
mpm::MpmModel<2> striker(double h, double v0) {
    mpm::MpmModel<2> m;
    m.axisymmetric = true;
    m.grid.origin = {0.0, -0.1};
    m.grid.spacing = {h, h};
    m.grid.cells = {64, 100};
    m.grid.allocate();
    m.shape = mpm::ShapeKind::GIMP;
    m.gravity = {0.0, 0.0};
    m.flip = 1.0;
    m.materials.push_back(std::make_unique<mpm::LinearElastic>(kModulus, 0.0));
    mpm::fill_region<2>(m.grid, m.particles, [](const double* x) { return x[0] > kInner && x[0] < kOuter && x[1] > 0.0 && x[1] < kLength; },
                        2, kDensity, 0, true);
    for (std::size_t i = 0; i < m.particles.size(); ++i) m.particles.v[2 * i + 1] = v0;
    return m;
}

// Cells of h; the pile's elements h / 6 along the axis, so it subcycles inside each step.
Collision collide(double h) {
    const double v0 = 1.0, gap = 0.2 * h;
    fem::ExplicitPile pile(tube_mesh(h / 6.0), bar_material(), {});
    mpm::MpmModel<2> m = striker(h, v0);
    mpm::MpmSolver<2> soil(m);
    ContactSettings settings;
    settings.ring = full_ring(1.0);
    settings.axisymmetric = true;
    CoupledPile coupled(pile, settings, PileFrame{kLength + gap}, 0.0, false);  // no soil inside: no cut

    const double soil_dt = soil.stable_time_step();
    const double p0 = full_ring(soil.momentum()[1]);
    const double e0 = full_ring(0.5 * soil.total_mass() * v0 * v0);
    double worst_momentum = 0.0, penetration = 0.0;
    bool touched = false;
    long last_contact = -1;
    for (long n = 0; n < 20000; ++n) {
        coupled.step(soil, m, coupled.stable_time_step(m, soil_dt));  // shorter where it would penetrate
        worst_momentum = std::max(worst_momentum, std::abs(coupled.momentum()[1] + full_ring(soil.momentum()[1]) - p0) / p0);
        penetration = std::max(penetration, coupled.contact().totals().max_penetration);
        if (coupled.contact().totals().points_in_contact > 0) touched = true, last_contact = n;
        if (touched && n > last_contact + 200) break;  // apart for 200 steps
    }
    EXPECT_TRUE(touched);
    double pile_mass = 0.0;
    for (std::size_t k = 1; k < pile.operators().lumped_mass.size(); k += 2) pile_mass += pile.operators().lumped_mass[k];
    const double struck = coupled.momentum()[1] / pile_mass;
    const double striker = soil.momentum()[1] / soil.total_mass();
    const double e1 = 0.5 * pile_mass * struck * struck + full_ring(0.5 * soil.total_mass() * striker * striker);
    // The pile, at rest before, has the impulse the segments passed it over the stage.
    const auto mean = coupled.stage_mean_segment_force();
    double impulse = 0.0;
    for (std::size_t k = 1; k < mean.size(); k += 2) impulse += mean[k] * coupled.stage_time();
    const double impulse_error = std::abs(impulse - coupled.momentum()[1]) / std::abs(coupled.momentum()[1]);
    return {worst_momentum, penetration / h, struck / v0, striker / v0, e1 / e0, impulse_error, coupled.substeps()};
}

}  // namespace

TEST(PileContactSurface, ASolidPileHasNoSurfaceOnItsAxisAndItsAxisStaysOnIt) {
    fem::PileGeometry g;
    g.stations = {{0.0, 0.0, kOuter}, {kLength, 0.0, kOuter}};
    const auto mesh = fem::mesh_axisymmetric_wall(g, 0.05, 4, std::string(PILEMPM_SOURCE_DIR) + "/meshes/pile_wall_axisymmetric.geo");
    const ContactSurface s = pile_contact_surface(mesh);
    double length[5] = {};
    for (int k = 0; k < s.num_segments(); ++k)
        length[static_cast<int>(s.side[k])] += std::hypot(s.x[2 * s.b[k]] - s.x[2 * s.a[k]], s.x[2 * s.b[k] + 1] - s.x[2 * s.a[k] + 1]);
    EXPECT_EQ(length[static_cast<int>(SurfaceSide::Inner)], 0.0);
    EXPECT_NEAR(length[static_cast<int>(SurfaceSide::Outer)], kLength, 1e-12);
    EXPECT_NEAR(length[static_cast<int>(SurfaceSide::Toe)], kOuter, 1e-12);
    // Pushed at its head, the nodes on the axis move along it only.
    fem::ExplicitPile pile(mesh, bar_material(), {});
    const double dt = 0.9 * pile.stable_time_step();
    for (int n = 0; n < 200; ++n) {
        pile.compute_internal_force();
        pile.clear_external_force();
        pile.add_head_force(-1.0e5);
        pile.advance_velocity(dt);
        pile.advance_displacement(dt);
    }
    int on_axis = 0;
    for (int i = 0; i < mesh.num_nodes(); ++i) {
        if (mesh.coordinates[2 * i] != 0.0) continue;
        ++on_axis;
        EXPECT_EQ(pile.displacement()[2 * i], 0.0);
    }
    EXPECT_GT(on_axis, 10);
    EXPECT_LT(pile.displacement()[pile.mesh().axial_dof(pile.mesh().head_nodes.front())], 0.0);
    EXPECT_EQ(pile.toe_reaction(), 0.0);  // the axis's radial hold is not a toe reaction
}

TEST(PileSoilCollision, MomentumIsConservedAndTheStrikerStops) {
    double previous = 1.0;
    int most_substeps = 0;
    for (const double h : {0.05, 0.025}) {
        const Collision c = collide(h);
        std::printf("  h %.3f m: struck %.4f v0, striker %.4f v0, rigid-body energy %.4f of the impact's, "
                    "penetration %.4f h, momentum error %.2e, stage impulse error %.2e, %d substeps\n",
                    h, c.struck, c.striker, c.rigid_energy, c.penetration_over_cell, c.momentum_error, c.impulse_error,
                    c.substeps);
        EXPECT_LT(c.momentum_error, 1e-10);  // round-off over ~10^3 steps of sums over ~10^3 points
        EXPECT_LT(c.impulse_error, 1e-10);
        EXPECT_LT(c.penetration_over_cell, 0.01);
        most_substeps = std::max(most_substeps, c.substeps);
        EXPECT_NEAR(c.struck, 1.0, 0.03);
        EXPECT_NEAR(c.striker, 0.0, 0.03);
        // The bars' vibration after the impact (what the rigid-body energy misses) shrinks with h.
        EXPECT_LT(1.0 - c.rigid_energy, previous);
        previous = 1.0 - c.rigid_energy;
    }
    EXPECT_GT(most_substeps, 1);  // the pile subcycled inside the soil's step
}

// A pause's settlement: the pile follows the points it bears on (weighted by their contact
// force), not the soil elsewhere; it moves rigidly, so its toe moves by the settlement.
TEST(PileContactSurface, InAPauseThePileFollowsTheSoilItBearsOn) {
    const double h = 0.05, v0 = 1.0;
    fem::ExplicitPile pile(tube_mesh(h / 6.0), bar_material(), {});
    mpm::MpmModel<2> m = striker(h, v0);
    mpm::MpmSolver<2> soil(m);
    ContactSettings settings;
    settings.ring = full_ring(1.0);
    settings.axisymmetric = true;
    CoupledPile coupled(pile, settings, PileFrame{kLength + 0.2 * h}, 0.0, false);
    const double soil_dt = soil.stable_time_step();
    for (int n = 0; n < 2000 && coupled.contact().touches().empty(); ++n) coupled.step(soil, m, coupled.stable_time_step(m, soil_dt));
    ASSERT_FALSE(coupled.contact().touches().empty());
    const std::vector<double> before = m.particles.x;
    std::vector<char> touching(m.particles.size(), 0);
    for (const ContactTouch& t : coupled.contact().touches()) touching[t.point] = 1;
    const double settlement = 1.0e-3;
    for (std::size_t i = 0; i < m.particles.size(); ++i) m.particles.x[2 * i + 1] -= touching[i] ? settlement : 5.0 * settlement;
    const double toe = coupled.toe_elevation();
    coupled.follow_soil(m, before);
    EXPECT_NEAR(coupled.toe_elevation(), toe - settlement, 1e-12);
}

// The weight's work (the blow's energy ledger credits it): a pile falling freely for t has
// had m g (g t^2 / 2) done on it, all of it kinetic energy, at either gravity factor.
TEST(PileContactSurface, TheWeightsWorkOnAFallingPileIsItsKineticEnergy) {
    const double h = 0.05, g = 9.81;
    for (const double factor : {1.0, 0.5}) {
        fem::ExplicitPile pile(tube_mesh(h / 6.0), bar_material(), {});
        mpm::MpmModel<2> m = striker(h, 0.0);
        mpm::MpmSolver<2> soil(m);
        ContactSettings settings;
        settings.ring = full_ring(1.0);
        settings.axisymmetric = true;
        CoupledPile coupled(pile, settings, PileFrame{kLength + 1.0}, g, false);  // 1 m above the soil
        coupled.set_gravity_factor(factor);
        const double dt = coupled.stable_time_step(m, soil.stable_time_step());
        const int steps = static_cast<int>(std::ceil(0.05 / dt));
        for (int n = 0; n < steps; ++n) coupled.advance(m, dt);
        double mass = 0.0;
        for (std::size_t k = 1; k < pile.operators().lumped_mass.size(); k += 2) mass += pile.operators().lumped_mass[k];
        const double t = steps * dt, a = factor * g;
        EXPECT_NEAR(coupled.weight_work() / (mass * a * 0.5 * a * t * t), 1.0, 0.01);  // leapfrog: O(1 / steps)
        // v at the half step before t against u at t: within a step's share as well.
        EXPECT_NEAR(pile.kinetic_energy(pile.velocity()) / coupled.weight_work(), 1.0, 0.01);
    }
}
