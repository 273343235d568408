// volumetric_strain: nodal_average (MpmModel::smooth_dilatation). The nodal average of the
// volumetric strain increment keeps a uniform dilatation as it is, keeps the body's
// mass-weighted volume change exactly (sum over nodes of sum N m de_v), changes no point's
// deviatoric strain, and evens out a dilatation that varies from point to point.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "mpm/setup/model_setup.hpp"
#include "mpm/solver/mpm_solver.hpp"

using namespace pilempm::mpm;

namespace {

using VelocityField = std::function<void(const double* x, double* v)>;

// A block of points in a grid, with the velocity field given; one step, with or without the
// smoothing; returns each point's strain increment (6 per point) and mass.
std::vector<double> one_step(bool axisymmetric, bool smooth, const VelocityField& field, std::vector<double>* mass,
                             std::vector<double>* x = nullptr) {
    MpmModel<2> m;
    m.grid.origin = {0.0, 0.0};
    m.grid.spacing = {0.1, 0.1};
    m.grid.cells = {16, 16};
    m.grid.allocate();
    m.axisymmetric = axisymmetric;
    m.smooth_dilatation = smooth;
    m.flip = 1.0;
    m.materials.push_back(std::make_unique<LinearElastic>(1e6, 0.3));
    fill_region<2>(m.grid, m.particles, [](const double* x) { return x[0] > 0.2 && x[0] < 1.4 && x[1] > 0.2 && x[1] < 1.4; },
                   2, 1800.0, 0, axisymmetric);
    for (std::size_t i = 0; i < m.particles.size(); ++i) field(&m.particles.x[2 * i], &m.particles.v[2 * i]);
    MpmSolver<2> s(m);
    s.step(1e-4);
    if (mass) *mass = m.particles.mass;
    if (x) *x = m.particles.x;
    return m.particles.dstrain;
}

double volumetric(const std::vector<double>& de, std::size_t i) { return de[6 * i] + de[6 * i + 1] + de[6 * i + 2]; }

void check(bool axisymmetric) {
    const int normals = axisymmetric ? 3 : 2;
    // Uniform compression: the points away from the block's faces (where the grid's
    // gradient of even a linear field is not exact) keep their own, exact, increment (in
    // axisymmetry the mass grows with r, the nodal velocities of a linear field are not
    // exactly linear, and the increments differ from it and from each other by 1e-3).
    const double tolerance = axisymmetric ? 2e-8 : 1e-15;
    const VelocityField uniform = [](const double* x, double* v) {
        v[0] = -0.2 * x[0];
        v[1] = -0.2 * (x[1] - 0.8);
    };
    std::vector<double> x;
    const auto own_u = one_step(axisymmetric, false, uniform, nullptr, &x);
    const auto smooth_u = one_step(axisymmetric, true, uniform, nullptr);
    ASSERT_EQ(own_u.size(), smooth_u.size());
    int interior = 0;
    for (std::size_t i = 0; i < x.size() / 2; ++i) {
        if (x[2 * i] < 0.6 || x[2 * i] > 1.0 || x[2 * i + 1] < 0.6 || x[2 * i + 1] > 1.0) continue;
        ++interior;
        for (int c = 0; c < 6; ++c) EXPECT_NEAR(smooth_u[6 * i + c], own_u[6 * i + c], tolerance) << i;
        EXPECT_NEAR(volumetric(own_u, i), -0.2e-4 * normals, tolerance) << i;
    }
    EXPECT_GT(interior, 50);
    // A dilatation varying across the block.
    const VelocityField varying = [](const double* x, double* v) {
        v[0] = 0.3 * std::sin(7.0 * x[0]) * std::cos(3.0 * x[1]);
        v[1] = -0.2 * std::cos(5.0 * x[0] + 2.0 * x[1]);
    };
    std::vector<double> mass;
    const auto own = one_step(axisymmetric, false, varying, &mass), smooth = one_step(axisymmetric, true, varying, nullptr);
    double total_own = 0.0, total_smooth = 0.0, scale = 0.0, spread_own = 0.0, spread_smooth = 0.0, mean_own = 0.0,
           mean_smooth = 0.0, total_mass = 0.0;
    const std::size_t n = mass.size();
    for (std::size_t i = 0; i < n; ++i) {
        total_own += mass[i] * volumetric(own, i);
        total_smooth += mass[i] * volumetric(smooth, i);
        scale += mass[i] * std::abs(volumetric(own, i));
        total_mass += mass[i];
        // The deviatoric part: each normal strain less the mean of the normals that take the shift.
        const double m_own = volumetric(own, i) / normals, m_smooth = volumetric(smooth, i) / normals;
        for (int c = 0; c < normals; ++c) EXPECT_NEAR(smooth[6 * i + c] - m_smooth, own[6 * i + c] - m_own, 1e-14) << i;
        for (int c = normals; c < 6; ++c) EXPECT_EQ(smooth[6 * i + c], own[6 * i + c]) << i;
    }
    EXPECT_NEAR(total_smooth, total_own, 1e-12 * scale);
    mean_own = total_own / total_mass;
    mean_smooth = total_smooth / total_mass;
    for (std::size_t i = 0; i < n; ++i) {
        spread_own += mass[i] * std::pow(volumetric(own, i) - mean_own, 2);
        spread_smooth += mass[i] * std::pow(volumetric(smooth, i) - mean_smooth, 2);
    }
    EXPECT_LT(spread_smooth, 0.8 * spread_own);
}

}  // namespace

TEST(DilatationSmoothing, KeepsUniformDilatationTheVolumeChangeAndTheDeviatorPlaneStrain) { check(false); }
TEST(DilatationSmoothing, KeepsUniformDilatationTheVolumeChangeAndTheDeviatorAxisymmetric) { check(true); }
