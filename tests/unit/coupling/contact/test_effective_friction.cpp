// Friction on a saturated soil's points is Coulomb's on the effective normal force: a layer
// of points pressed into a plate and slid along it, with an excess pore pressure p, is held
// back by mu (N - p A) (A the points' face on the plate, N the normal force), by none once
// p A reaches N (the interface liquefied), and by more under suction (p < 0).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "coupling/contact/penalty_contact.hpp"
#include "mpm/setup/model_setup.hpp"
#include "mpm/solver/mpm_solver.hpp"

using namespace pilempm;
using namespace pilempm::coupling;

namespace {

struct Forces {
    double normal, tangential, area;  // N, N, m^2 (per unit thickness: plane strain)
};

// Points on cells of h over a plate at y = 0.5 that they overlap by h / 20, sliding along +x.
Forces slide(double pore_pressure) {
    const double h = 0.05, plate = 0.5;
    mpm::MpmModel<2> m;
    m.grid.origin = {0.0, 0.0};
    m.grid.spacing = {h, h};
    m.grid.cells = {40, 20};
    m.grid.allocate();
    m.shape = mpm::ShapeKind::GIMP;
    m.materials.push_back(std::make_unique<mpm::LinearElastic>(50.0e6, 0.3));
    mpm::fill_region<2>(m.grid, m.particles, [&](const double* x) { return x[0] > 0.5 && x[0] < 1.5 && x[1] > plate && x[1] < plate + h; },
                        2, 2000.0, 0, false);
    auto& p = m.particles;
    p.pore_pressure.assign(p.size(), pore_pressure);
    for (std::size_t i = 0; i < p.size(); ++i) p.x[2 * i + 1] -= h / 20.0, p.v[2 * i] = 1.0;
    ContactSurface s;
    for (int i = 0; i <= 40; ++i) {
        s.x.push_back(2.0 - i * h), s.x.push_back(plate);  // outward normal +y
        s.v.push_back(0.0), s.v.push_back(0.0);
        if (i > 0) s.add_segment(i - 1, i, SurfaceSide::Other);
    }
    ContactSettings settings;
    settings.friction = 0.5;
    PenaltyContact contact(settings);
    contact.compute(p, m.shape, s, 1.0, m.materials);  // a long step: the tangential spring slips
    Forces f{0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (p.external_force[2 * i + 1] == 0.0) continue;
        f.normal += p.external_force[2 * i + 1];
        f.tangential -= p.external_force[2 * i];
        f.area += p.volume[i] / (h / 2.0);  // two points a cell: each h / 2 thick
    }
    return f;
}

}  // namespace

TEST(ContactEffectiveFriction, CoulombActsOnTheNormalForceLessThePorePressure) {
    const Forces dry = slide(0.0);
    ASSERT_GT(dry.normal, 0.0);
    EXPECT_NEAR(dry.area, 1.0, 1e-9);  // the layer's bottom points over 1 m of plate
    EXPECT_NEAR(dry.tangential, 0.5 * dry.normal, 1e-9 * dry.normal);
    const double p = 0.4 * dry.normal / dry.area;  // 40 % of the normal stress
    const Forces wet = slide(p);
    EXPECT_NEAR(wet.normal, dry.normal, 1e-9 * dry.normal);  // the push is the mixture's
    EXPECT_NEAR(wet.tangential, 0.5 * (wet.normal - p * wet.area), 1e-9 * dry.normal);
    EXPECT_EQ(slide(1.2 * dry.normal / dry.area).tangential, 0.0);  // liquefied: no grip
    EXPECT_NEAR(slide(-p).tangential, 0.5 * (dry.normal + p * dry.area), 1e-9 * dry.normal);
}

