// A slip line through one material (a field cut whose sides are in frictional contact):
// the contact conserves momentum to round-off and never lets the sides interpenetrate; a
// block resting across a horizontal slip line carries its weight; a block on an inclined
// one slides at g (sin theta - mu cos theta) and sticks when tan theta < mu; on two grids.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "mpm/grid/field_contact.hpp"
#include "mpm/setup/model_setup.hpp"
#include "mpm/solver/mpm_solver.hpp"

using namespace pilempm::mpm;

namespace {

constexpr double kGravity = 9.81;
constexpr double kDensity = 2000.0;

FieldCut slip_line(double x0, double y0, double x1, double y1, double mu) {
    FieldCut cut{{x0, y0, x1, y1}, 1};
    cut.contact_segments = 1;
    cut.friction = mu;
    return cut;
}

// The points of m where they start that `select` picks.
std::vector<char> pick(const MpmModel<2>& m, bool (*select)(const double*)) {
    std::vector<char> picked(m.particles.size());
    for (std::size_t i = 0; i < picked.size(); ++i) picked[i] = select(&m.particles.x[2 * i]);
    return picked;
}

// The picked points' centre of mass, its coordinate `component`.
double mass_weighted(const MpmModel<2>& m, const std::vector<char>& picked, int component) {
    double sum = 0.0, mass = 0.0;
    for (std::size_t i = 0; i < m.particles.size(); ++i) {
        if (!picked[i]) continue;
        sum += m.particles.mass[i] * m.particles.x[2 * i + component];
        mass += m.particles.mass[i];
    }
    return sum / mass;
}

}  // namespace

TEST(FieldContact, TheNormalPointsFromTheNodesSideAcrossTheNearestSegment) {
    const FieldCut cut = slip_line(2.0, 0.0, 0.0, 2.0, 0.0);  // y = 2 - x, ascending in y
    double n[2];
    cut.normal_away_from(std::array<double, 2>{0.0, 0.0}.data(), n);  // below-left of it
    EXPECT_NEAR(n[0], std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(n[1], std::sqrt(0.5), 1e-15);
    cut.normal_away_from(std::array<double, 2>{2.0, 2.0}.data(), n);
    EXPECT_NEAR(n[0], -std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(n[1], -std::sqrt(0.5), 1e-15);
}

TEST(FieldContact, ApproachingSidesMeetWithMomentumKeptAndLeavingSidesAreLeftAlone) {
    Grid<2> g;
    g.origin = {0.0, 0.0};
    g.spacing = {1.0, 1.0};
    g.cells = {1, 1};
    g.fields = 2;
    g.allocate();
    g.activate_all();
    const FieldCut cut = slip_line(-1.0, 0.5, 2.0, 0.5, 0.3);  // horizontal: node (0, 0) below it
    const int node = g.index({0, 0});  // nearest to the wall of `bent` below
    const int a = 2 * node, b = a + 1;
    for (double vy : {-0.4, 0.7}) {  // b falling onto a, or lifting off it
        g.mass[a] = 2.0;
        g.mass[b] = 3.0;
        const double va[2] = {0.2, -0.1}, vb[2] = {-0.5, vy};
        for (int d = 0; d < 2; ++d) {
            g.velocity[2 * a + d] = va[d];
            g.velocity[2 * b + d] = vb[d];
        }
        std::vector<double> residual(g.velocity.size(), 0.0);
        contact_across_cuts(g, {cut}, 1e-12, 0.0, nullptr);
        const double* wa = &g.velocity[2 * a];
        const double* wb = &g.velocity[2 * b];
        for (int d = 0; d < 2; ++d)
            EXPECT_NEAR(2.0 * wa[d] + 3.0 * wb[d], 2.0 * va[d] + 3.0 * vb[d], 1e-15) << "momentum, vy " << vy;
        if (vy < 0.0) {
            // Normal: a common velocity, the centre of mass's (-0.28). Tangential: a's slip
            // past the centre of mass, 0.42, exceeds mu times its normal change, 0.3 x 0.18,
            // so it slides, slowed by exactly that.
            EXPECT_NEAR(wa[1], wb[1], 1e-15);
            EXPECT_NEAR(wa[1], (2.0 * -0.1 + 3.0 * vy) / 5.0, 1e-15);
            EXPECT_NEAR(wa[0] - va[0], -0.3 * std::abs(wa[1] - va[1]), 1e-15);
        } else {
            EXPECT_EQ(wa[0], va[0]);
            EXPECT_EQ(wb[1], vb[1]);
        }
    }
    // Where the nearest segment is a wall (the polyline's second, past its one slip segment),
    // the sides are left alone even when they approach.
    FieldCut bent = cut;
    bent.vertices = {3.0, -1.0, 0.3, -0.2, 0.3, 3.0};  // a slip segment, then a wall up x = 0.3
    g.velocity[2 * b + 1] = -0.4;
    const std::vector<double> before = g.velocity;
    contact_across_cuts(g, {bent}, 1e-12, 0.0, nullptr);
    EXPECT_EQ(g.velocity, before);
}

namespace {

// An elastic block 0.8 m wide from y = 0 (fixed) to 1 m, cut at y = 0.6 (a slip line, or a
// cut with nothing across it), geostatic at the start; after 0.2 s: how far the top part
// has sunk, and the lower part's vertical stress against rho g (H - y) at its points.
struct Rest {
    double sunk;          // m
    double stress_error;  // of the lower part's mean sigma_yy against rho g (H - y)'s, relative
};

Rest rest_across(double h, bool contact) {
    MpmModel<2> m;
    m.grid.origin = {0.0, 0.0};
    m.grid.spacing = {h, h};
    m.grid.cells = {static_cast<int>(std::lround(1.2 / h)), static_cast<int>(std::lround(1.4 / h))};
    m.grid.fields = 2;
    m.grid.allocate();
    m.shape = ShapeKind::GIMP;
    m.gravity = {0.0, -kGravity};
    m.local_damping = 0.2;
    m.materials.push_back(std::make_unique<LinearElastic>(50e6, 0.3));
    fill_region<2>(m.grid, m.particles, [](const double* x) { return x[0] > 0.2 && x[0] < 1.0 && x[1] < 1.0; }, 2,
                   kDensity, 0, false);
    apply_k0_stress<2>(m.particles, 1.0, kGravity, [](double) { return kDensity; }, [](double) { return 0.43; });
    apply_boundary<2>(m.grid, 1, 0, BoundaryKind::Fixed);
    FieldCut cut = slip_line(0.0, 0.6, 1.2, 0.6, 0.3);
    cut.contact_segments = contact ? 1 : 0;
    m.field_cuts = {cut};
    const auto upper = pick(m, [](const double* x) { return x[1] > 0.6; });
    const double y0 = mass_weighted(m, upper, 1);
    const std::vector<double> start = m.particles.x;
    MpmSolver<2> s(m);
    const double dt = s.stable_time_step();
    for (double t = 0.0; t < 0.2; t += dt) s.step(dt);
    Rest r{0.0, 0.0};
    r.sunk = y0 - mass_weighted(m, upper, 1);
    // Volume means, the fixed base's own disturbance aside: the sides are free, so only the
    // mean over a section is rho g (H - y) (the block's corners carry less, its middle more).
    double computed = 0.0, exact = 0.0;
    for (std::size_t i = 0; i < m.particles.size(); ++i) {
        const double y = start[2 * i + 1];
        if (y > 0.6 || y < 0.2) continue;
        computed += m.particles.volume[i] * m.particles.stress[6 * i + 1];
        exact -= m.particles.volume[i] * kDensity * kGravity * (1.0 - y);
    }
    r.stress_error = std::abs(computed / exact - 1.0);
    return r;
}

}  // namespace

TEST(FieldContact, ABlockAcrossAHorizontalSlipLineCarriesItsWeight) {
    const double free_fall = 0.5 * kGravity * 0.2 * 0.2;
    for (double h : {0.1, 0.05}) {
        const Rest with = rest_across(h, true);
        std::printf("h %.2f: top part sank %.2e m (free fall %.3f m), lower part's mean stress within %.2f %% of rho g (H - y)'s\n", h,
                    with.sunk, free_fall, 100.0 * with.stress_error);
        // The elastic shortening of the block under its weight is about 1e-5 m.
        EXPECT_LT(std::abs(with.sunk), 1e-3 * free_fall) << h;
        EXPECT_LT(with.stress_error, 0.05) << h;
    }
    // Without the contact the top part falls through the bottom: the test can fail.
    EXPECT_GT(rest_across(0.1, false).sunk, 0.1 * free_fall);
}

namespace {

constexpr double kSlope = 30.0 * std::numbers::pi / 180.0;
constexpr double kToe = 0.1;  // m: the slip line y = kToe + x tan theta

double on_slope(const double* x) { return kToe + x[0] * std::tan(kSlope); }

bool slider(const double* x) {
    const double above = (x[1] - on_slope(x)) * std::cos(kSlope);
    return x[0] > 1.2 && x[0] < 2.2 && above > 0.0 && above < 0.3;
}

// A block on the slip line through a wedge standing on a fixed base, from rest under
// gravity: its acceleration down the slope from how far it went in 0.3 s (2 s / t^2; the
// distance, unlike the velocity, hardly feels the block's elastic ringing).
double sliding_acceleration(double h, double mu) {
    MpmModel<2> m;
    m.grid.origin = {0.0, 0.0};
    m.grid.spacing = {h, h};
    m.grid.cells = {static_cast<int>(std::lround(2.8 / h)), static_cast<int>(std::lround(2.2 / h))};
    m.grid.fields = 2;
    m.grid.allocate();
    m.shape = ShapeKind::GIMP;
    m.gravity = {0.0, -kGravity};
    m.materials.push_back(std::make_unique<LinearElastic>(50e6, 0.3));
    fill_region<2>(m.grid, m.particles, [](const double* x) {
        return (x[0] > 0.1 && x[0] < 2.6 && x[1] < on_slope(x)) || slider(x);
    }, 2, kDensity, 0, false);
    apply_boundary<2>(m.grid, 1, 0, BoundaryKind::Fixed);
    m.field_cuts = {slip_line(0.0, kToe, 2.8, on_slope(std::array<double, 2>{2.8, 0.0}.data()), mu)};
    const auto block = pick(m, slider);
    const double x0 = mass_weighted(m, block, 0), y0 = mass_weighted(m, block, 1);
    MpmSolver<2> s(m);
    const double dt = s.stable_time_step(), duration = 0.3;
    for (double t = 0.0; t < duration; t += dt) s.step(dt);
    const double dx = mass_weighted(m, block, 0) - x0, dy = mass_weighted(m, block, 1) - y0;
    return -2.0 * (dx * std::cos(kSlope) + dy * std::sin(kSlope)) / (s.time() * s.time());
}

}  // namespace

TEST(FieldContact, ABlockSlidesDownAnInclinedSlipLineAtGTimesSinMinusMuCos) {
    const double mu = 0.2, exact = kGravity * (std::sin(kSlope) - mu * std::cos(kSlope));
    for (double h : {0.1, 0.05}) {
        const double a = sliding_acceleration(h, mu);
        std::printf("h %.2f: slides at %.4f m/s^2, closed form %.4f (%.2f %%)\n", h, a, exact, 100.0 * (a / exact - 1.0));
        EXPECT_NEAR(a, exact, (h > 0.075 ? 0.02 : 0.01) * exact) << h;  // 1 % on the finer grid
    }
}

TEST(FieldContact, ABlockOnASlipLineSticksWhenTanThetaIsBelowMu) {
    for (double h : {0.1, 0.05}) {
        const double a = sliding_acceleration(h, 0.8);
        std::printf("h %.2f: mu 0.8 > tan 30: moves at %.2e m/s^2\n", h, a);
        EXPECT_LT(std::abs(a), 0.01 * kGravity * std::sin(kSlope)) << h;
    }
}
