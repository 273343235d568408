// Grid transfers conserve mass and momentum: the grid holds exactly what the points carry,
// and a free body (no gravity, no supports) keeps its momentum step after step.
#include <gtest/gtest.h>

#include <cmath>

#include "mpm/setup/model_setup.hpp"
#include "mpm/solver/mpm_solver.hpp"

using namespace pilempm::mpm;

namespace {

template <int D>
MpmModel<D> spinning_block(ShapeKind shape) {
    MpmModel<D> m;
    for (int d = 0; d < D; ++d) {
        m.grid.origin[d] = 0.0;
        m.grid.spacing[d] = 0.2;
        m.grid.cells[d] = 12;
    }
    m.grid.allocate();
    m.shape = shape;
    m.materials.push_back(std::make_unique<LinearElastic>(1e6, 0.3));
    fill_region<D>(m.grid, m.particles, [](const double* x) {
        for (int d = 0; d < D; ++d)
            if (x[d] < 0.8 || x[d] > 1.6) return false;
        return true;
    }, 2, 1500.0, 0, false);
    // Translation plus a spin about the block's centre: every velocity differs.
    for (std::size_t i = 0; i < m.particles.size(); ++i) {
        const double* x = &m.particles.x[D * i];
        m.particles.v[D * i + 0] = 0.3 - 0.5 * (x[1] - 1.2);
        m.particles.v[D * i + 1] = -0.1 + 0.5 * (x[0] - 1.2);
    }
    return m;
}

template <int D>
void check_free_body(ShapeKind shape, bool apic = false) {
    MpmModel<D> m = spinning_block<D>(shape);
    m.apic = apic;
    MpmSolver<D> s(m);
    const auto p0 = s.momentum();
    const double mass0 = s.total_mass();
    const double dt = s.stable_time_step();
    for (int n = 0; n < 200; ++n) s.step(dt);
    // The grid after the last step's scatter holds exactly the points' mass.
    double grid_mass = 0.0;
    for (double x : m.grid.mass) grid_mass += x;
    EXPECT_NEAR(grid_mass, mass0, 1e-12 * mass0);
    const auto p1 = s.momentum();
    for (int d = 0; d < D; ++d) EXPECT_NEAR(p1[d], p0[d], 1e-10 * mass0);
}

}  // namespace

TEST(MpmConservation, FreeBodyKeepsMassAndMomentum2dGimp) { check_free_body<2>(ShapeKind::GIMP); }
TEST(MpmConservation, FreeBodyKeepsMassAndMomentum2dCpdi) { check_free_body<2>(ShapeKind::CPDI); }
TEST(MpmConservation, FreeBodyKeepsMassAndMomentum3dLinear) { check_free_body<3>(ShapeKind::Linear); }

TEST(MpmConservation, FreeBodyKeepsMassAndMomentumApic2dGimp) { check_free_body<2>(ShapeKind::GIMP, true); }
TEST(MpmConservation, FreeBodyKeepsMassAndMomentumApic2dCpdi) { check_free_body<2>(ShapeKind::CPDI, true); }
TEST(MpmConservation, FreeBodyKeepsMassAndMomentumApic3dGimp) { check_free_body<3>(ShapeKind::GIMP, true); }

// Spin of the block about its centre of mass (z component), from the point velocities.
double spin(const MpmModel<2>& m) {
    const auto& p = m.particles;
    double M = 0.0, X = 0.0, Y = 0.0, VX = 0.0, VY = 0.0, L = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double* x = &p.x[2 * i];
        const double* v = &p.v[2 * i];
        M += p.mass[i];
        X += p.mass[i] * x[0];
        Y += p.mass[i] * x[1];
        VX += p.mass[i] * v[0];
        VY += p.mass[i] * v[1];
        L += p.mass[i] * (x[0] * v[1] - x[1] * v[0]);
    }
    return L - (X * VY - Y * VX) / M;
}

// PIC projects every velocity field onto the grid's and damps a rigid spin; APIC carries
// the affine part of the field with each point, so the spin survives: a linear velocity
// field is reproduced exactly by the transfers.
TEST(MpmConservation, ApicKeepsTheSpinThatPicDamps) {
    auto spin_left = [](bool apic) {
        MpmModel<2> m = spinning_block<2>(ShapeKind::GIMP);
        m.apic = apic;
        m.flip = 0.0;  // pure PIC when not APIC
        // APIC's points start with the affine part of their field: the spin's gradient.
        for (std::size_t i = 0; i < m.particles.size(); ++i) {
            m.particles.C[4 * i + 1] = -0.5;
            m.particles.C[4 * i + 2] = 0.5;
        }
        MpmSolver<2> s(m);
        const double l0 = spin(m);
        const double dt = s.stable_time_step();
        for (int n = 0; n < 200; ++n) s.step(dt);
        return spin(m) / l0;
    };
    const double apic = spin_left(true), pic = spin_left(false);
    EXPECT_NEAR(apic, 1.0, 0.01);
    EXPECT_LT(pic, 0.95);  // the loss APIC avoids
}

TEST(MpmConservation, GravityChangesMomentumByItsImpulse) {
    MpmModel<2> m = spinning_block<2>(ShapeKind::GIMP);
    m.gravity = {0.0, -9.81};
    MpmSolver<2> s(m);
    const auto p0 = s.momentum();
    const double dt = s.stable_time_step();
    const int steps = 100;
    for (int n = 0; n < steps; ++n) s.step(dt);
    const double impulse = -9.81 * s.total_mass() * dt * steps;
    EXPECT_NEAR(s.momentum()[1] - p0[1], impulse, 1e-9 * std::abs(impulse));
    EXPECT_NEAR(s.momentum()[0], p0[0], 1e-9 * std::abs(impulse));
}

// Axisymmetry: nothing acts along the axis on a free ring, so its axial momentum (per
// radian) is kept, for a field that shears along r too. APIC's affine term must be taken
// about the centroid of the r-weighted weights, which lies outside the point by l^2 / (3 r):
// taken about the point, it added m (dv_z/dr) l^2 / (3 r) to the axial momentum every step.
TEST(MpmConservation, AxisymmetricApicKeepsAxialMomentum) {
    for (ShapeKind shape : {ShapeKind::GIMP, ShapeKind::CPDI}) {
        MpmModel<2> m;
        for (int d = 0; d < 2; ++d) {
            m.grid.origin[d] = 0.0;
            m.grid.spacing[d] = 0.2;
            m.grid.cells[d] = 12;
        }
        m.grid.allocate();
        m.shape = shape;
        m.axisymmetric = true;
        m.apic = true;
        m.materials.push_back(std::make_unique<LinearElastic>(1e6, 0.3));
        fill_region<2>(m.grid, m.particles, [](const double* x) {
            return x[0] > 0.2 && x[0] < 1.0 && x[1] > 0.8 && x[1] < 1.6;
        }, 2, 1500.0, 0, true);
        for (std::size_t i = 0; i < m.particles.size(); ++i) {
            m.particles.v[2 * i + 1] = -0.1 + 0.5 * (m.particles.x[2 * i] - 0.6);
            m.particles.C[4 * i + 2] = 0.5;  // dv_z / dr
        }
        MpmSolver<2> s(m);
        const double pz0 = s.momentum()[1], mass = s.total_mass();
        const double dt = s.stable_time_step();
        for (int n = 0; n < 200; ++n) s.step(dt);
        EXPECT_NEAR(s.momentum()[1], pz0, 1e-10 * mass);
    }
}
