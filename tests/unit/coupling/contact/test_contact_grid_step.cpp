// The penalty contact's stable step from the grid (PenaltyContact::grid_stable_time_step)
// and its stiffness from the point's domain. A block of soil pressed on a rigid plate, one
// point at its top light (a fifth of its domain's volume and mass, as a point carried from
// the axis round a toe): the step from the grid must not exceed the one the assembled
// springs on the grid's masses allow (Eigen's generalised eigenvalue, an independent
// computation), must be longer than the light point's own k / m_p allows, and the light
// point must push back as hard as a full one at the same overlap.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <map>
#include <memory>

#include "coupling/contact/penalty_contact.hpp"
#include "mpm/setup/model_setup.hpp"
#include "mpm/solver/mpm_solver.hpp"

using namespace pilempm;
using namespace pilempm::coupling;

namespace {

constexpr double kTop = 0.1, kOverlap = 2e-5, kE = 20e6, kNu = 0.3;

struct Pressed {
    mpm::MpmModel<2> m;
    ContactSurface plate;
    long light = -1;  // the light point
};

// A block [0.05, 0.15] x [0.02, kTop] on cells of `cell` (2 x 2 points a cell), the plate
// along y = kTop - kOverlap.
void press(Pressed& s, double cell = 0.01) {
    mpm::MpmModel<2>& m = s.m;
    m.grid.origin = {0.0, 0.0};
    m.grid.spacing = {cell, cell};
    m.grid.cells = {static_cast<int>(std::lround(0.2 / cell)),
                    static_cast<int>(std::lround(0.14 / cell))};
    m.grid.allocate();
    m.shape = mpm::ShapeKind::GIMP;
    m.gravity = {0.0, 0.0};
    m.materials.push_back(std::make_unique<mpm::LinearElastic>(kE, kNu));
    mpm::fill_region<2>(
        m.grid, m.particles,
        [](const double* x) { return x[0] > 0.05 && x[0] < 0.15 && x[1] > 0.02 && x[1] < kTop; }, 2,
        2000.0, 0, true);
    double best = 0.0;
    for (std::size_t i = 0; i < m.particles.size(); ++i) {
        const double* x = &m.particles.x[2 * i];
        const double score = x[1] - std::abs(x[0] - 0.1);  // top row, mid-block
        if (s.light < 0 || score > best) best = score, s.light = static_cast<long>(i);
    }
    m.particles.mass[s.light] *= 0.2;
    m.particles.volume[s.light] *= 0.2;
    m.particles.volume0[s.light] *= 0.2;
    s.plate.x = {0.0, kTop - kOverlap, 0.2,
                 kTop - kOverlap};  // from x = 0 to 0.2: the normal down, into the soil
    s.plate.v = {0.0, 0.0, 0.0, 0.0};
    s.plate.add_segment(0, 1, SurfaceSide::Other);
}

}  // namespace

// On two grids (cells of 1 and 0.5 cm): the bound holds and stays as tight on both.
TEST(ContactGridStep, NeverExceedsTheStepTheAssembledSpringsOnTheGridsMassesAllow) {
    for (const double cell : {0.01, 0.005}) {
        Pressed s;
        press(s, cell);
        mpm::MpmModel<2>& m = s.m;
        ContactSettings settings;
        settings.penalty_factor = 30.0;
        PenaltyContact contact(settings);
        mpm::MpmSolver<2> soil(m);
        contact.compute(m.particles, m.shape, s.plate, 1e-7, m.materials);
        soil.step(1e-7);  // the stencils and the grid's masses of the step the forces acted over
        const double grid_dt = contact.grid_stable_time_step(m.grid.mass, soil.stencils(), s.plate);

        // Every point of the top row touches (and only they): k = factor M A / h^2 with A the
        // domain's area (h / 2 square) and h its thickness: factor M for every one, the light one
        // too.
        const double M = kE * (1 - kNu) / ((1 + kNu) * (1 - 2 * kNu)),
                     k = settings.penalty_factor * M;
        ASSERT_EQ(contact.touches().size(),
                  static_cast<std::size_t>(std::lround(0.2 / cell)));  // 0.1 m of cells, 2 a cell
        std::map<int, int> entry;                                      // grid entry -> row
        for (const ContactTouch& t : contact.touches()) {
            const auto& st = soil.stencils()[t.point];
            for (int e = 0; e < st.count; ++e)
                entry.emplace(st.e[e].node, static_cast<int>(entry.size()));
        }
        // The springs on the grid (one direction: n n^T + t t^T = I with k_t = k_n), and the
        // masses of those entries.
        const int n = static_cast<int>(entry.size());
        Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n), Mass = Eigen::MatrixXd::Zero(n, n);
        for (const ContactTouch& t : contact.touches()) {
            const auto& st = soil.stencils()[t.point];
            for (int a = 0; a < st.count; ++a)
                for (int b = 0; b < st.count; ++b)
                    K(entry[st.e[a].node], entry[st.e[b].node]) += k * st.e[a].N * st.e[b].N;
        }
        for (const auto& [node, row] : entry) Mass(row, row) = m.grid.mass[node];
        Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(K, Mass,
                                                                        Eigen::EigenvaluesOnly);
        const double exact_dt =
            settings.stability_margin / std::sqrt(modes.eigenvalues().maxCoeff());
        const double point_dt = contact.totals().stable_time_step;
        std::printf(
            "  cells of %.3f m, step: from the points %.4e s, from the grid %.4e s, the assembled "
            "springs allow %.4e s\n",
            cell, point_dt, grid_dt, exact_dt);
        EXPECT_LE(grid_dt, exact_dt * (1 + 1e-12));  // a bound: never longer than the system allows
        EXPECT_GT(grid_dt, 0.7 * exact_dt);          // and not far short of it
        // The light point alone (k / m_p, five times a full point's) set the step from the points.
        const double full_mass = m.particles.mass[s.light] * 5.0;
        EXPECT_NEAR(point_dt, settings.stability_margin / std::sqrt(k / (0.2 * full_mass)),
                    1e-9 * point_dt);
        EXPECT_GT(grid_dt, 1.5 * point_dt);
    }
}

TEST(ContactGridStep, ALightPointPushesBackAsHardAsAFullOneAtTheSameOverlap) {
    // Plane strain: k = 4 M (the default factor; A / h^2 = 1); axisymmetric: per radian, 4 M r.
    for (const bool axisymmetric : {false, true}) {
        Pressed s;
        press(s);
        mpm::MpmModel<2>& m = s.m;
        ContactSettings settings;
        settings.axisymmetric = axisymmetric;
        PenaltyContact contact(settings);
        contact.compute(m.particles, m.shape, s.plate, 1e-7, m.materials);
        const double M = kE * (1 - kNu) / ((1 + kNu) * (1 - 2 * kNu));
        ASSERT_EQ(contact.touches().size(), 20u);
        for (const ContactTouch& t : contact.touches()) {
            const double r = axisymmetric ? m.particles.x[2 * t.point] : 1.0;
            const double expected = 4.0 * M * r * kOverlap;
            EXPECT_NEAR(-m.particles.external_force[2 * t.point + 1], expected, 1e-9 * expected)
                << "point " << t.point;
        }
    }
}
