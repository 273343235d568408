// Wave-equation drivability on Smith soil: statics, energy, monotonic trends.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/wave_equation/driving.hpp"
#include "fem/mesh/pile_geometry.hpp"
#include "fem/mesh/rod_mesh.hpp"

using namespace pilempm;
using namespace pilempm::coupling;
using namespace pilempm::fem;

namespace {
const fem::LinearElasticSteel kSteel{210e9, 0.3, 7850.0};

// 20 m of a 30 m pile in the ground: shaft friction growing linearly with depth
// (20 kN/m at the mudline to 80 kN/m at the toe) and a toe resistance.
ResistanceDistribution linear_srd(double scale) {
    ResistanceDistribution r;
    r.penetration = 20.0;
    r.depth = {0.0, 20.0};
    r.shaft = {20e3 * scale, 80e3 * scale};
    r.toe = 600e3 * scale;
    return r;
}

fem::PileMesh pile_mesh() {
    return fem::mesh_rod(fem::make_pile_geometry({{30.0, 0.6, 0.0125}}), 0.5);
}

HammerSpec hammer() {
    HammerSpec h;
    h.kind = HammerKind::RamCushion;
    h.ram_cushion.ram.mass = 3000.0;
    h.ram_cushion.impact_velocity = std::sqrt(2.0 * 9.81 * 1.0);
    h.ram_cushion.hammer_cushion = CushionSpec{2e9, 0.8};
    h.ram_cushion.helmet_mass = 500.0;
    return h;
}
}  // namespace

TEST(ResistanceDistribution, IntegratesLinearSamplesExactly) {
    const auto r = linear_srd(1.0);
    EXPECT_NEAR(r.shaft_total(), 0.5 * (20e3 + 80e3) * 20.0, 1e-6);
    EXPECT_NEAR(r.shaft_between(5.0, 10.0), 5.0 * (35e3 + 50e3) / 2.0, 1e-6);
}

TEST(ResistanceDistribution, DashpotSumsJTimesResistanceStretchByStretch) {
    // 20 + 3 d kN/m; J = 0.1 s/m down to 8 m, 0.5 s/m below. From 5 to 10 m by hand:
    // 0.1 x (60 + 1.5 (64 - 25)) kN + 0.5 x (40 + 1.5 (100 - 64)) kN = 11.85 + 47 kN s/m.
    ResistanceDistribution r;
    r.penetration = 20.0;
    r.depth = {0.0, 8.0, 20.0};
    r.shaft = {20e3, 44e3, 80e3};
    r.shaft_damping = {0.1, 0.1, 0.5};
    EXPECT_NEAR(r.shaft_dashpot_between(5.0, 10.0, 9.9), 58.85e3, 1e-6);
    r.shaft_damping = {0.3, 0.3, 0.3};  // one J: exactly J x R_u, as without samples
    EXPECT_EQ(r.shaft_dashpot_between(5.0, 10.0, 9.9), 0.3 * r.shaft_between(5.0, 10.0));
}

TEST(SmithSoil, CarriesTheWholeDistribution) {
    fem::ExplicitPile pile(pile_mesh(), kSteel, {});
    const auto r = linear_srd(1.0);
    const SmithSoil soil = make_smith_soil(pile, r, {}, 1e6);
    EXPECT_NEAR(soil.total_ultimate(), r.total(), 1e-9 * r.total());
}

TEST(Driving, SlowPushReproducesTheStaticResistance) {
    fem::ExplicitPile pile(pile_mesh(), kSteel, {});
    const auto r = linear_srd(1.0);
    SmithSoil soil = make_smith_soil(pile, r, {}, 1e6);
    soil.attach_dashpots(pile);
    const double capacity = static_push_capacity(pile, soil, 2e-3, 0.03);
    EXPECT_NEAR(capacity, r.total(), 0.01 * r.total());
}

TEST(Driving, OneBlowConservesEnergy) {
    fem::ExplicitPile pile(pile_mesh(), kSteel, {});
    SmithSoil soil = make_smith_soil(pile, linear_srd(1.0), {}, 1e6);
    soil.attach_dashpots(pile);
    const BlowOutcome b = simulate_blow(pile, soil, hammer(), 0.5, {});
    EXPECT_LT(b.energy_error(), 0.01);
    EXPECT_GT(b.set, 0.0);
    EXPECT_GT(b.energy_soil_plastic, 0.0);
}

TEST(Driving, SetFallsAsResistanceRises) {
    double previous = 1e9;
    for (double scale : {0.5, 1.0, 2.0, 4.0}) {
        const auto r = drive_at_penetration(pile_mesh(), kSteel, linear_srd(scale), {}, hammer(), 0.5, {});
        EXPECT_LT(r.set, previous) << "scale " << scale;
        previous = r.set;
    }
}
