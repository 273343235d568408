// An absorbing boundary under a column at rest in gravity: in a static stage it holds like
// a roller and keeps its reaction, the column's weight (rho g H per metre); in the dynamic
// stage after, that held force with the dashpots keeps the column at rest, where the
// dashpots alone would let it sink at g (a wave verification has no weight to carry). With
// the far field's springs a held force a little off balance (the column made 1 % heavier)
// moves the base by that imbalance over the springs' stiffness 2 G / R, where the dashpots
// alone let it creep on for as long as the run lasts (a drive of 233 blows lost a point
// through its far boundary that way).
#include <gtest/gtest.h>

#include <cmath>

#include "mpm/setup/model_setup.hpp"
#include "mpm/solver/mpm_solver.hpp"

using namespace pilempm::mpm;

namespace {

constexpr double kRho = 2000.0, kG = 9.81, kHeight = 2.0, kWidth = 0.4;

MpmModel<2> column_on_absorbing_base(double far_field_distance = 0.0) {
    MpmModel<2> m;
    m.grid.origin = {0.0, 0.0};
    m.grid.spacing = {0.1, 0.1};
    m.grid.cells = {4, 24};
    m.grid.allocate();
    m.gravity = {0.0, -kG};
    const double E = 50e6, nu = 0.3, M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
    m.materials.push_back(std::make_unique<LinearElastic>(E, nu));
    fill_region<2>(m.grid, m.particles, [](const double* x) { return x[1] < kHeight; }, 2, kRho, 0, false);
    apply_k0_stress<2>(m.particles, kHeight, kG, [](double) { return kRho; }, [nu](double) { return nu / (1 - nu); });
    apply_boundary<2>(m.grid, 0, 0, BoundaryKind::Roller);
    apply_boundary<2>(m.grid, 0, 1, BoundaryKind::Roller);
    apply_boundary<2>(m.grid, 1, 0, BoundaryKind::Absorbing, kRho, std::sqrt(M / kRho), std::sqrt(E / (2 * (1 + nu)) / kRho),
                      false, 0.0, 0.0, false, far_field_distance);
    return m;
}

double fastest_point(const MpmModel<2>& m) {
    double v = 0.0;
    for (double x : m.particles.v) v = std::max(v, std::abs(x));
    return v;
}

}  // namespace

TEST(AbsorbingBoundary, HoldsTheWeightItCarriedAtRestThroughTheDynamicStageAfter) {
    MpmModel<2> held = column_on_absorbing_base();
    MpmSolver<2> s(held);
    const double dt = s.stable_time_step();
    held.local_damping = 0.7;
    s.set_static_boundaries(true);
    for (int n = 0; n < 50; ++n) s.step(dt);
    double carried = 0.0;
    for (const auto& c : held.grid.conditions) carried += c.held_force[1];
    EXPECT_NEAR(carried, kRho * kG * kHeight * kWidth, 1e-3 * kRho * kG * kHeight * kWidth);
    const SolverState kept = s.state();
    held.local_damping = 0.0;
    s.set_static_boundaries(false);
    const int steps = 400;
    for (int n = 0; n < steps; ++n) s.step(dt);
    const double falling = kG * steps * dt;  // what the column would reach in free fall
    EXPECT_LT(fastest_point(held), 1e-3 * falling);
    // The held force is the solver's state: a restored solver holds the same.
    MpmModel<2> restored = column_on_absorbing_base();
    MpmSolver<2> r(restored);
    r.restore(kept);
    double restored_force = 0.0;
    for (const auto& c : restored.grid.conditions) restored_force += c.held_force[1];
    EXPECT_EQ(restored_force, carried);

    // The dashpots alone: the column sinks.
    MpmModel<2> free = column_on_absorbing_base();
    MpmSolver<2> f(free);
    for (int n = 0; n < steps; ++n) f.step(dt);
    EXPECT_GT(fastest_point(free), 0.05 * falling);
}

namespace {

// The column held, then 1 % heavier in a damped dynamic stage: the mean vertical
// displacement of its lowest row of points.
double base_displacement_after(double far_field_distance, int steps) {
    MpmModel<2> m = column_on_absorbing_base(far_field_distance);
    MpmSolver<2> s(m);
    const double dt = s.stable_time_step();
    m.local_damping = 0.7;
    s.set_static_boundaries(true);
    for (int n = 0; n < 50; ++n) s.step(dt);
    s.set_static_boundaries(false);
    const std::vector<double> y0 = m.particles.x;
    m.gravity = {0.0, -1.01 * kG};
    for (int n = 0; n < steps; ++n) s.step(dt);
    double sum = 0.0;
    int count = 0;
    for (std::size_t i = 0; i < m.particles.size(); ++i)
        if (y0[2 * i + 1] < 0.05) sum += m.particles.x[2 * i + 1] - y0[2 * i + 1], ++count;
    return sum / count;
}

}  // namespace

TEST(AbsorbingBoundary, ItsFarFieldSpringsHoldItWhereTheDashpotsAloneLetItCreep) {
    const double E = 50e6, nu = 0.3, G = E / (2 * (1 + nu)), R = 10.0;
    const double expected = -0.01 * kRho * kG * kHeight / (2.0 * G / R);  // -1.02e-4 m
    const double anchored = base_displacement_after(R, 6000);
    EXPECT_NEAR(anchored, expected, 0.02 * std::abs(expected));
    EXPECT_NEAR(base_displacement_after(R, 12000), anchored, 0.01 * std::abs(expected));  // at rest
    // Without springs the base goes on sinking, about twice as far in twice the time.
    const double creep = base_displacement_after(0.0, 3000), longer = base_displacement_after(0.0, 6000);
    EXPECT_LT(creep, 2.0 * expected);
    EXPECT_NEAR(longer / creep, 2.0, 0.2);
    EXPECT_LT(longer, 4.0 * expected);
}
