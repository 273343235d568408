// An absorbing boundary under a column at rest in gravity: in a static stage it holds like
// a roller and keeps its reaction, the column's weight (rho g H per metre); in the dynamic
// stage after, that held force with the dashpots keeps the column at rest, where the
// dashpots alone would let it sink at g (a wave verification has no weight to carry).
#include <gtest/gtest.h>

#include <cmath>

#include "mpm/setup/model_setup.hpp"
#include "mpm/solver/mpm_solver.hpp"

using namespace pilempm::mpm;

namespace {

constexpr double kRho = 2000.0, kG = 9.81, kHeight = 2.0, kWidth = 0.4;

MpmModel<2> column_on_absorbing_base() {
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
    apply_boundary<2>(m.grid, 1, 0, BoundaryKind::Absorbing, kRho, std::sqrt(M / kRho), std::sqrt(E / (2 * (1 + nu)) / kRho));
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
