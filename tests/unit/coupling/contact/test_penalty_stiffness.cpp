// The penalty follows the soil's stiffness in its current state: a Cam clay point pressed
// on a flat surface by the same overlap pushes back in proportion to its bulk modulus
// K = v p / kappa, so at four times the mean pressure the normal force is four times as
// large; below the material's reference pressure (100 kPa) the reference stiffness is kept,
// so a point near a free surface still cannot pass through the steel.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "coupling/contact/penalty_contact.hpp"
#include "mpm/materials/modified_cam_clay.hpp"

using namespace pilempm;
using namespace pilempm::coupling;

namespace {

constexpr double kCell = 0.01, kOverlap = 1e-4;  // m

// The normal force (per radian) on one point under isotropic compression p, its domain
// overlapping a level surface by kOverlap.
double normal_force(double p) {
    std::vector<std::unique_ptr<mpm::ConstitutiveModel>> materials;
    materials.push_back(std::make_unique<mpm::ModifiedCamClay>(mpm::CamClayParameters{}));
    mpm::Particles<2> points;
    const double half = 0.25 * kCell, lengths[2] = {2 * half, 2 * half};
    const double x[2] = {0.5, half - kOverlap};  // the surface at y = 0, the soil above it
    points.add(x, 1.0, 4 * half * half, lengths, 0);
    points.resize_state(materials[0]->num_state());
    for (int k = 0; k < 3; ++k) points.stress[k] = -p;
    materials[0]->initialise_state(points.stress.data(), points.state.data());
    ContactSurface surface;
    surface.x = {1.0, 0.0, 0.0, 0.0};  // from x = 1 to 0: the outward normal is +y
    surface.v = {0.0, 0.0, 0.0, 0.0};
    surface.add_segment(0, 1, SurfaceSide::Other);
    PenaltyContact contact(ContactSettings{});
    contact.compute(points, mpm::ShapeKind::GIMP, surface, 1e-6, materials);
    EXPECT_EQ(contact.totals().points_in_contact, 1);
    return points.external_force[1];
}

}  // namespace

TEST(ContactPenalty, StiffensInProportionToTheSoilsBulkModulus) {
    // Cam clay: K = v p / kappa, so the force scales as p (v is the same initial void ratio).
    EXPECT_NEAR(normal_force(800e3) / normal_force(200e3), 4.0, 1e-12);
    EXPECT_GT(normal_force(200e3), 0.0);
}

TEST(ContactPenalty, KeepsTheReferenceStiffnessBelowTheReferencePressure) {
    EXPECT_NEAR(normal_force(10e3) / normal_force(100e3), 1.0, 1e-12);
    EXPECT_NEAR(normal_force(400e3) / normal_force(100e3), 4.0, 1e-12);
}

// The contact's stable step: a point of mass m on a fixed surface is a mass on the spring
// k_n = penalty_factor M V / h^2 (M = E (1 - nu) / ((1 + nu)(1 - 2 nu))), omega = sqrt(k_n / m),
// and the step is stability_margin / omega: halving the margin (the case's cfl) halves it.
TEST(ContactPenalty, ItsStableStepIsTheMarginOverThePointsFrequencyOnItsSpring) {
    const double E = 20e6, nu = 0.3, mass = 0.7, half = 0.25 * kCell;
    std::vector<std::unique_ptr<mpm::ConstitutiveModel>> materials;
    materials.push_back(std::make_unique<mpm::LinearElastic>(E, nu));
    mpm::Particles<2> points;
    const double lengths[2] = {2 * half, 2 * half}, x[2] = {0.5, half - kOverlap};
    points.add(x, mass, 4 * half * half, lengths, 0);
    points.resize_state(materials[0]->num_state());
    ContactSurface surface;
    surface.x = {1.0, 0.0, 0.0, 0.0};
    surface.v = {0.0, 0.0, 0.0, 0.0};
    surface.add_segment(0, 1, SurfaceSide::Other);
    const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
    const double k = 4.0 * M * (4 * half * half) / (4 * half * half);  // the default factor 4, h = 2 half
    for (double margin : {1.0, 0.5}) {
        ContactSettings settings;
        settings.stability_margin = margin;
        PenaltyContact contact(settings);
        contact.compute(points, mpm::ShapeKind::GIMP, surface, 1e-6, materials);
        EXPECT_NEAR(points.external_force[1], k * kOverlap, 1e-9 * k * kOverlap);
        EXPECT_NEAR(contact.totals().stable_time_step, margin / std::sqrt(k / mass), 1e-12 * margin / std::sqrt(k / mass));
    }
}
