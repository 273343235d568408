// A rigid Coulomb wall: a block sliding on it under gravity decelerates at mu g and stops
// after v0^2 / (2 mu g); it never sinks into the wall.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mpm/setup/model_setup.hpp"
#include "mpm/solver/mpm_solver.hpp"

using namespace pilempm::mpm;

namespace {

struct SlideResult {
    double distance;      // of the centre of mass, m
    double lowest_point;  // m (the wall is y = 0)
};

SlideResult slide(double mu, double v0, ShapeKind shape) {
    MpmModel<2> m;
    m.grid.origin = {0.0, 0.0};
    m.grid.spacing = {0.1, 0.1};
    m.grid.cells = {30, 8};
    m.grid.allocate();
    m.shape = shape;
    m.gravity = {0.0, -9.81};
    m.materials.push_back(std::make_unique<LinearElastic>(50e6, 0.3));
    fill_region<2>(m.grid, m.particles, [](const double* x) { return x[0] > 0.2 && x[0] < 1.2 && x[1] < 0.5; }, 2,
                   2000.0, 0, false);
    // Start in equilibrium under gravity (uniaxial vertical stress), sliding at v0.
    apply_k0_stress<2>(m.particles, 0.5, 9.81, [](double) { return 2000.0; }, [](double) { return 0.0; });
    for (std::size_t i = 0; i < m.particles.size(); ++i) m.particles.v[2 * i] = v0;
    apply_boundary<2>(m.grid, 1, 0, BoundaryKind::Frictional, 0, 0, 0, false, mu);
    MpmSolver<2> s(m);
    auto centre = [&] {
        double x = 0.0, mass = 0.0;
        for (std::size_t i = 0; i < m.particles.size(); ++i) {
            x += m.particles.mass[i] * m.particles.x[2 * i];
            mass += m.particles.mass[i];
        }
        return x / mass;
    };
    const double x0 = centre();
    const double dt = s.stable_time_step();
    SlideResult r{0.0, 1e300};
    // At least 500 steps (so a block at rest is watched too), then until it stops.
    for (int n = 0; n < 20000 && (n < 500 || s.momentum()[0] > 1e-6 * std::max(v0, 1e-3) * s.total_mass()); ++n) {
        s.step(dt);
        for (std::size_t i = 0; i < m.particles.size(); ++i) r.lowest_point = std::min(r.lowest_point, m.particles.x[2 * i + 1]);
    }
    r.distance = centre() - x0;
    return r;
}

}  // namespace

TEST(MpmFrictionWall, SlidingBlockStopsAfterTheCoulombDistance) {
    for (double mu : {0.2, 0.4}) {
        const auto r = slide(mu, 1.0, ShapeKind::GIMP);
        const double exact = 1.0 / (2.0 * mu * 9.81);
        EXPECT_NEAR(r.distance, exact, 0.03 * exact) << "mu " << mu;
        std::printf("mu %.1f: stopped after %.4f m, closed form %.4f m\n", mu, r.distance, exact);
        EXPECT_GT(r.lowest_point, 0.0) << "points entered the wall";
    }
}

TEST(MpmFrictionWall, ABlockAtRestStaysPut) {
    const auto r = slide(0.5, 0.0, ShapeKind::GIMP);
    EXPECT_NEAR(r.distance, 0.0, 1e-9);
}
