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

// An elastic point (E 20 MPa, nu 0.3, mass 0.7 kg) overlapping a level surface (y = 0,
// normal +y) by kOverlap, moving at `v` (m/s, up +); the surface's nodes moving at `u`.
struct PointOnSurface {
    std::vector<std::unique_ptr<mpm::ConstitutiveModel>> materials;
    mpm::Particles<2> points;
    ContactSurface surface;
    static constexpr double E = 20e6, nu = 0.3, mass = 0.7, half = 0.25 * kCell;
    static constexpr double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));  // P-wave modulus
    PointOnSurface(double v = 0.0, double u = 0.0) {
        materials.push_back(std::make_unique<mpm::LinearElastic>(E, nu));
        const double lengths[2] = {2 * half, 2 * half}, x[2] = {0.5, half - kOverlap};
        points.add(x, mass, 4 * half * half, lengths, 0);
        points.resize_state(materials[0]->num_state());
        points.v[1] = v;
        surface.x = {1.0, 0.0, 0.0, 0.0};
        surface.v = {0.0, u, 0.0, u};
        surface.add_segment(0, 1, SurfaceSide::Other);
    }
};

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
    PointOnSurface at;
    auto& points = at.points;
    const double mass = PointOnSurface::mass, half = PointOnSurface::half;
    const double k = 4.0 * PointOnSurface::M * (4 * half * half) / (4 * half * half);  // the default factor 4, h = 2 half
    for (double margin : {1.0, 0.5}) {
        ContactSettings settings;
        settings.stability_margin = margin;
        PenaltyContact contact(settings);
        contact.compute(points, mpm::ShapeKind::GIMP, at.surface, 1e-6, at.materials);
        EXPECT_NEAR(points.external_force[1], k * kOverlap, 1e-9 * k * kOverlap);
        EXPECT_NEAR(contact.totals().stable_time_step, margin / std::sqrt(k / mass), 1e-12 * margin / std::sqrt(k / mass));
    }
}

// Inside the master's substeps the pair's gap follows the motion: a point moving down at
// v onto a surface rising at u closes its gap by (v + u) tau after tau, so the force per
// substep is k (|g0| + (v + u) tau) on a flat face; the point's force over the step is its
// mean, and the master takes the same impulse (ring 1 here), opposite.
TEST(ContactPenalty, InTheMastersSubstepsTheForceFollowsTheGap) {
    const double v = 0.3, u = 0.2, dt = 1e-5;
    PointOnSurface at(-v, u);
    auto& points = at.points;
    const double k = 4.0 * PointOnSurface::M;
    PenaltyContact contact(ContactSettings{});
    contact.compute(points, mpm::ShapeKind::GIMP, at.surface, dt, at.materials);
    const int substeps = 4;
    const double sub = dt / substeps;
    double impulse_master = 0.0, mean = 0.0;
    for (int s = 0; s < substeps; ++s) {
        const double tau = s * sub;
        const std::vector<double> shift = {0.0, u * tau, 0.0, u * tau};  // the surface risen since t_n
        std::vector<double> nodal(4, 0.0);
        contact.substep_force(points, shift, tau, sub, nodal);
        const double expected = k * (kOverlap + (v + u) * tau);
        EXPECT_NEAR(-(nodal[1] + nodal[3]), expected, 1e-9 * expected) << "substep " << s;
        impulse_master += (nodal[1] + nodal[3]) * sub;
        mean += expected * sub / dt;
    }
    contact.finish_substeps(points, dt);
    EXPECT_NEAR(points.external_force[1], mean, 1e-9 * mean);
    EXPECT_NEAR(points.external_force[1] * dt, -impulse_master, 1e-12 * mean * dt);
}
