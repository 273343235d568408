// Issue 13, verification 1: a block of material points on a plate inclined at theta (the
// plate level, gravity turned by theta smoothly once the block has settled), in contact
// through the penalty with Coulomb friction mu. Sliding (tan theta > mu): the block's
// acceleration is g (sin theta - mu cos theta) within 1 %, on two grids. Sticking (tan theta < mu): it stays put. The plate is the
// contact's general master surface, held: the FE side of the contact is test 3's.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "coupling/contact/penalty_contact.hpp"
#include "mpm/setup/model_setup.hpp"
#include "mpm/solver/mpm_solver.hpp"

using namespace pilempm;
using namespace pilempm::coupling;

namespace {

constexpr double kG = 9.81, kPlate = 0.5, kDensity = 2000.0;

struct Slide {
    double acceleration;  // fitted over the second half of the run, m/s^2
    double travel;        // m
    double penetration_over_cell;
};

Slide slide(double theta_deg, double mu, double h) {
    const double theta = theta_deg * std::numbers::pi / 180.0;
    mpm::MpmModel<2> m;
    m.grid.origin = {0.0, 0.0};
    m.grid.spacing = {h, h};
    m.grid.cells = {static_cast<int>(std::lround(2.0 / h)), static_cast<int>(std::lround(1.0 / h))};
    m.grid.allocate();
    m.shape = mpm::ShapeKind::GIMP;
    m.gravity = {0.0, -kG * std::cos(theta)};
    m.materials.push_back(std::make_unique<mpm::LinearElastic>(50.0e6, 0.3));
    mpm::fill_region<2>(m.grid, m.particles, [](const double* x) { return x[0] > 0.3 && x[0] < 0.7 && x[1] > kPlate && x[1] < kPlate + 0.2; },
                        2, kDensity, 0, false);
    // Starts in equilibrium across the plate: sigma_y from the normal part of its weight.
    mpm::apply_k0_stress<2>(m.particles, kPlate + 0.2, kG * std::cos(theta), [](double) { return kDensity; },
                            [](double) { return 0.0; });
    // The plate, x from 2 down to 0 so that its outward normal is +y.
    ContactSurface plate;
    const int n = static_cast<int>(std::lround(2.0 / h));
    for (int i = 0; i <= n; ++i) {
        plate.x.push_back(2.0 - i * h);
        plate.x.push_back(kPlate);
        plate.v.push_back(0.0);
        plate.v.push_back(0.0);
        if (i > 0) plate.add_segment(i - 1, i, SurfaceSide::Other);
    }
    ContactSettings settings;
    settings.friction = mu;
    PenaltyContact contact(settings);
    mpm::MpmSolver<2> soil(m);
    // The contact's step (its penalty's stability) where shorter than the soil's.
    contact.compute(m.particles, m.shape, plate, soil.stable_time_step(), m.materials);
    const double dt = std::min(soil.stable_time_step(), contact.totals().stable_time_step), end = 0.4;
    // First the block settles on the plate under the normal part of its weight (damped),
    // as a geostatic stage would; then the plate tilts.
    m.local_damping = 0.7;
    for (double t = 0.0; t < 0.1; t += dt) {
        contact.compute(m.particles, m.shape, plate, dt, m.materials);
        soil.step(dt);
    }
    m.local_damping = 0.0;
    std::fill(m.particles.v.begin(), m.particles.v.end(), 0.0);
    // The tilt comes on smoothly over 0.1 s (a sudden one would overshoot the interface's
    // static shear, the block ringing on the contact's spring and its own shear stiffness).
    const double ramp = 0.1;
    auto centre_x = [&] {
        double s = 0.0;
        for (std::size_t i = 0; i < m.particles.size(); ++i) s += m.particles.mass[i] * m.particles.x[2 * i];
        return s / soil.total_mass();
    };
    const double start = centre_x();
    // Least-squares slope of the mean velocity over t in [end / 2, end].
    double st = 0.0, sv = 0.0, stt = 0.0, stv = 0.0, count = 0.0, penetration = 0.0;
    for (double t = 0.0; t < end; t += dt) {
        const double on = t < ramp ? std::pow(std::sin(0.5 * std::numbers::pi * t / ramp), 2) : 1.0;
        m.gravity = {on * kG * std::sin(theta), -kG * std::cos(theta)};
        contact.compute(m.particles, m.shape, plate, dt, m.materials);
        soil.step(dt);
        penetration = std::max(penetration, contact.totals().max_penetration);
        if (t + dt >= 0.5 * end) {
            const double v = soil.momentum()[0] / soil.total_mass();
            const double tt = t + dt;
            st += tt, sv += v, stt += tt * tt, stv += tt * v, count += 1.0;
        }
    }
    const double slope = (count * stv - st * sv) / (count * stt - st * st);
    return {slope, centre_x() - start, penetration / h};
}

}  // namespace

TEST(ContactSlidingBlock, SlidesAtGTimesSinMinusMuCos) {
    const double theta = 30.0, mu = 0.3;
    const double exact = kG * (std::sin(theta * std::numbers::pi / 180.0) - mu * std::cos(theta * std::numbers::pi / 180.0));
    for (const double h : {0.05, 0.025}) {
        const Slide s = slide(theta, mu, h);
        std::printf("  h %.3f m: acceleration %.5f m/s^2 against %.5f (%+.3f %%), penetration %.4f h\n", h,
                    s.acceleration, exact, 100.0 * (s.acceleration / exact - 1.0), s.penetration_over_cell);
        EXPECT_NEAR(s.acceleration / exact, 1.0, 0.01);
        EXPECT_LT(s.penetration_over_cell, 0.01);
    }
}

TEST(ContactSlidingBlock, SticksWhenTanThetaIsBelowMu) {
    const Slide s = slide(30.0, 0.7, 0.05);
    // Sliding freely, it would have gone 0.5 g sin(theta) (0.4 - 0.05 s)^2 = 0.30 m.
    std::printf("  travel %.3e m, acceleration %.3e m/s^2\n", s.travel, s.acceleration);
    EXPECT_LT(std::abs(s.travel), 1e-3 * 0.30);
    EXPECT_LT(std::abs(s.acceleration), 1e-3 * kG);
}
