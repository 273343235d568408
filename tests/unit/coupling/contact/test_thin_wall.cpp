// Issue 13, verification 4: a held FE wall a tenth of a cell thick in a coarse grid, soil
// either side (axisymmetric: the plug inside an open pile and the soil outside). The
// outside soil, touching the wall, is pushed into it and slides down it; the inside soil must stay exactly at
// rest: the grid's fields are cut along the wall's mid-line, so the nodes both sides reach
// carry one field per side. Without the cut (the control) the inside soil is dragged along
// through the shared nodes. Also the cut's geometry: lines across the polyline, a line
// through its vertex counted once, a node on it on one side.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "core/conventions.hpp"
#include "coupling/contact/penalty_contact.hpp"
#include "coupling/contact/pile_surface.hpp"
#include "fem/mesh/axisymmetric_mesher.hpp"
#include "mpm/setup/model_setup.hpp"
#include "mpm/solver/mpm_solver.hpp"

using namespace pilempm;
using namespace pilempm::coupling;

TEST(FieldCut, ALineIsAcrossWhenItCrossesThePolylineAnOddNumberOfTimes) {
    mpm::FieldCut cut;
    cut.vertices = {1.0, 0.0, 1.0, 1.0, 1.2, 2.0};  // up, then leaning out
    const double in[2] = {0.9, 0.5}, out[2] = {1.1, 0.5}, far_out[2] = {1.5, 1.5}, above[2] = {0.9, 2.5};
    EXPECT_TRUE(cut.crosses(in, out));
    EXPECT_TRUE(cut.crosses(out, in));
    EXPECT_FALSE(cut.crosses(in, above));       // passes over the top
    EXPECT_TRUE(cut.crosses(in, far_out));
    const double through_vertex_a[2] = {0.8, 0.8}, through_vertex_b[2] = {1.2, 1.2};  // through (1, 1)
    EXPECT_TRUE(cut.crosses(through_vertex_a, through_vertex_b));
    const double on_cut[2] = {1.0, 0.5};  // on it: one side (the left, inside), consistently
    EXPECT_FALSE(cut.crosses(in, on_cut));
    EXPECT_TRUE(cut.crosses(out, on_cut));
    const double below_a[2] = {0.9, -0.5}, below_b[2] = {1.1, -0.2};  // under the toe: no cut
    EXPECT_FALSE(cut.crosses(below_a, below_b));
}

// The x range's early answer agrees with the full count for lines everywhere around the
// polyline, those that start or end on it and those through its vertices included.
TEST(FieldCut, TheBoundedCutAnswersAsTheFullCount) {
    mpm::FieldCut full;
    full.vertices = {1.0, 0.0, 1.0, 1.0, 1.2, 2.0, 1.1, 3.0};
    mpm::FieldCut bounded = full;
    bounded.bound();
    EXPECT_EQ(bounded.x_low, 1.0);
    EXPECT_EQ(bounded.x_high, 1.2);
    int lines = 0, across = 0;
    for (int i = 0; i <= 24; ++i)
        for (int j = 0; j <= 32; ++j)
            for (int k = 0; k <= 24; k += 3)
                for (int l = 0; l <= 32; l += 4) {
                    const double a[2] = {0.6 + 0.05 * i, -0.4 + 0.125 * j}, b[2] = {0.6 + 0.05 * k, -0.4 + 0.125 * l};
                    ASSERT_EQ(bounded.crosses(a, b), full.crosses(a, b)) << a[0] << "," << a[1] << " - " << b[0] << "," << b[1];
                    ++lines;
                    across += full.crosses(a, b);
                }
    EXPECT_GT(across, lines / 10);  // many lines do cross: the comparison is not all "no"
}

namespace {

constexpr double kWallMid = 0.995, kHalfThickness = 0.005, kToe = 0.2;  // outer face on r = 1

// The largest speed of the inside soil over the run (m/s), and the deepest penetration
// into the wall over the cell.
std::pair<double, double> run(bool cut) {
    const double h = 0.1;
    fem::PileGeometry g;
    g.stations = {{0.0, kWallMid - kHalfThickness, kWallMid + kHalfThickness},
                  {1.0, kWallMid - kHalfThickness, kWallMid + kHalfThickness}};
    const fem::PileMesh wall = fem::mesh_axisymmetric_wall(g, 0.05, 1, std::string(PILEMPM_SOURCE_DIR) + "/meshes/pile_wall_axisymmetric.geo");
    const PileFrame frame{kToe};
    ContactSurface surface = pile_contact_surface(wall);
    const std::vector<double> held(wall.coordinates.size(), 0.0);
    place_pile_surface(surface, wall, held, held, frame);

    mpm::MpmModel<2> m;
    m.axisymmetric = true;
    m.grid.origin = {0.0, 0.0};
    m.grid.spacing = {h, h};
    m.grid.cells = {20, 16};
    m.grid.fields = cut ? 2 : 1;
    m.grid.allocate();
    m.shape = mpm::ShapeKind::GIMP;
    m.gravity = {0.0, 0.0};
    m.materials.push_back(std::make_unique<mpm::LinearElastic>(1.0e6, 0.3));
    // Inside: domains up to r = 0.95 (4 cm from the wall); outside: from r = 1.0, touching.
    const int inside = mpm::fill_region<2>(m.grid, m.particles, [](const double* x) { return x[0] > 0.5 && x[0] < 0.95 && x[1] > 0.4 && x[1] < 1.0; },
                                           2, 2000.0, 0, true);
    mpm::fill_region<2>(m.grid, m.particles, [](const double* x) { return x[0] > 1.0 && x[0] < 1.4 && x[1] > 0.4 && x[1] < 1.0; }, 2,
                        2000.0, 0, true);
    for (std::size_t i = inside; i < m.particles.size(); ++i) {
        m.particles.v[2 * i] = -0.05;  // into the wall
        m.particles.v[2 * i + 1] = -1.0;  // and down it
    }
    if (cut) m.field_cuts = {mpm::FieldCut{pile_mid_line(wall, held, frame), 1}};
    ContactSettings settings;
    settings.friction = 0.3;
    settings.ring = full_ring(1.0);
    settings.axisymmetric = true;
    PenaltyContact contact(settings);
    mpm::MpmSolver<2> soil(m);
    contact.compute(m.particles, m.shape, surface, soil.stable_time_step(), m.materials);
    const double dt = std::min(soil.stable_time_step(), contact.totals().stable_time_step);
    double fastest = 0.0, penetration = 0.0;
    int touched = 0;
    for (double t = 0.0; t < 0.1; t += dt) {
        contact.compute(m.particles, m.shape, surface, dt, m.materials);
        soil.step(dt);
        touched = std::max(touched, contact.totals().points_in_contact);
        penetration = std::max(penetration, contact.totals().max_penetration);
        for (int i = 0; i < inside; ++i) fastest = std::max(fastest, std::hypot(m.particles.v[2 * i], m.particles.v[2 * i + 1]));
    }
    EXPECT_GT(touched, 0) << "the outside soil never reached the wall";
    return {fastest, penetration / h};
}

}  // namespace

TEST(ThinWall, TheSoilOnTheOtherSideOfACutWallStaysAtRest) {
    const auto [fastest, penetration] = run(true);
    std::printf("  with the cut: inside soil's fastest %.3e m/s, penetration %.4f of a cell\n", fastest, penetration);
    EXPECT_EQ(fastest, 0.0);
    EXPECT_LT(penetration, 0.01);
    const auto control = run(false);
    std::printf("  without it: inside soil's fastest %.3e m/s\n", control.first);
    EXPECT_GT(control.first, 1e-3);  // what the cut prevents
}
