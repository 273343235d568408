// Modified Cam clay in element tests against the closed-form critical-state solutions
// (issue 5, verification 3): drained and undrained triaxial compression from a normally
// consolidated isotropic state, and the slopes of isotropic and oedometric compression.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mpm/materials/element_test.hpp"
#include "mpm/materials/modified_cam_clay.hpp"

using namespace pilempm::mpm;

namespace {

// Fontainebleau-like parameters of seed 002 (lambda, kappa, e0), M for phi_cs = 35 deg.
CamClayParameters seed_parameters() {
    CamClayParameters p;
    p.lambda = 0.15;
    p.kappa = 0.013;
    const double s = std::sin(35.0 * M_PI / 180.0);
    p.M = 6.0 * s / (3.0 - s);
    p.poisson_ratio = 0.3;
    p.void_ratio = 0.62;
    p.ocr = 1.0;
    return p;
}

struct TestPath {
    std::vector<ElementRecord> path;
    double p0, e0;
};

TestPath run_from_isotropic(const ModifiedCamClay& model, double p0, const ElementLeg& leg) {
    const double s0[6] = {-p0, -p0, -p0, 0, 0, 0};
    std::vector<double> st(2);
    model.initialise_state(s0, st.data());
    ElementTest test(model, s0, st);
    TestPath r{{}, p0, st[1]};
    test.run(leg, r.path);
    return r;
}

}  // namespace

TEST(ModifiedCamClay, DrainedTriaxialEndsOnTheCriticalStateLine) {
    const ModifiedCamClay model(seed_parameters());
    const double M = model.parameters().M, lambda = 0.15, kappa = 0.013, p0 = 150e3;
    const TestPath r = run_from_isotropic(model, p0, {ElementLeg::AxialStrain, ElementLeg::LateralStress, 0.6, 6000});
    const ElementRecord& end = r.path.back();
    // Constant cell pressure: p = p0 + q / 3, so at q = M p, p = 3 p0 / (3 - M).
    EXPECT_NEAR(end.q / end.p, M, 0.01 * M);
    EXPECT_NEAR(end.p, 3.0 * p0 / (3.0 - M), 0.01 * 3.0 * p0 / (3.0 - M));
    // CSL: e = e_N - (lambda - kappa) ln 2 - lambda ln p, e_N from the NCL through (p0, e0).
    const double eN = r.e0 + lambda * std::log(p0);
    const double e_cs = eN - (lambda - kappa) * std::log(2.0) - lambda * std::log(end.p);
    EXPECT_NEAR(end.state[1], e_cs, 0.01 * e_cs);
    // The drained path is the straight line of slope 3 in q - p'.
    for (const auto& rec : r.path) ASSERT_NEAR(rec.p - p0, rec.q / 3.0, 1e-6 * p0);
}

TEST(ModifiedCamClay, UndrainedTriaxialFollowsTheClosedFormPath) {
    const ModifiedCamClay model(seed_parameters());
    const double M = model.parameters().M, lambda = 0.15, kappa = 0.013, p0 = 150e3;
    const TestPath r = run_from_isotropic(model, p0, {ElementLeg::AxialStrain, ElementLeg::Undrained, 0.3, 3000});
    const double L = (lambda - kappa) / lambda;
    const double pf = p0 * std::pow(0.5, L), qf = M * pf;
    const ElementRecord& end = r.path.back();
    EXPECT_NEAR(end.p, pf, 0.01 * pf);
    EXPECT_NEAR(end.q, qf, 0.01 * qf);
    EXPECT_NEAR(end.state[1], r.e0, 1e-9);  // no volume change: e constant
    // At constant volume p_c = p0 (p0 / p)^(kappa / (lambda - kappa)) and the stress stays
    // on the yield surface: q^2 = M^2 p (p_c - p).
    double worst = 0.0;
    for (const auto& rec : r.path) {
        const double pc = p0 * std::pow(p0 / rec.p, kappa / (lambda - kappa));
        worst = std::max(worst, std::abs(rec.q - M * std::sqrt(rec.p * (pc - rec.p))) / qf);
    }
    EXPECT_LT(worst, 0.01);
}

TEST(ModifiedCamClay, IsotropicAndOedometricCompressionSlopes) {
    const ModifiedCamClay model(seed_parameters());
    // Isotropic: loading along the NCL (slope lambda in e - ln p'), unloading along kappa.
    {
        const double s0[6] = {-100e3, -100e3, -100e3, 0, 0, 0};
        std::vector<double> st(2);
        model.initialise_state(s0, st.data());
        ElementTest test(model, s0, st);
        std::vector<ElementRecord> load, unload;
        test.run({ElementLeg::AxialStress, ElementLeg::LateralStressEqualsAxial, 400e3, 400}, load);
        test.run({ElementLeg::AxialStress, ElementLeg::LateralStressEqualsAxial, 200e3, 400}, unload);
        const double lam = -(load.back().state[1] - st[1]) / std::log(400.0 / 100.0);
        const double kap = -(unload.back().state[1] - load.back().state[1]) / std::log(200.0 / 400.0);
        EXPECT_NEAR(lam, 0.15, 0.01 * 0.15);
        EXPECT_NEAR(kap, 0.013, 0.01 * 0.013);
    }
    // Oedometer from a K0-NC state: the e - ln sigma'_v slope tends to lambda.
    {
        const double K0 = 1.0 - std::sin(35.0 * M_PI / 180.0);
        const double s0[6] = {-K0 * 100e3, -K0 * 100e3, -100e3, 0, 0, 0};
        std::vector<double> st(2);
        model.initialise_state(s0, st.data());
        ElementTest test(model, s0, st);
        std::vector<ElementRecord> path;
        test.run({ElementLeg::AxialStress, ElementLeg::LateralStrainZero, 1600e3, 1600}, path);
        const auto& a = path[path.size() / 2];
        const auto& b = path.back();
        const double slope = -(b.state[1] - a.state[1]) / std::log(b.axial_stress / a.axial_stress);
        EXPECT_NEAR(slope, 0.15, 0.01 * 0.15);
    }
}

// A point at zero stress (a free surface, a separated grain) stays finite.
TEST(ModifiedCamClay, ZeroStressStaysFinite) {
    const ModifiedCamClay model(seed_parameters());
    double s[6] = {0, 0, 0, 0, 0, 0};
    double st[2];
    model.initialise_state(s, st);
    const int point = 0;
    for (double de : {1e-3, -1e-3, 2e-3, 0.0}) {
        const double d[6] = {de, -0.5 * de, 0.3 * de, 1e-3, 0, 0};
        model.update(1, &point, d, s, st, 2);
        for (double x : s) ASSERT_TRUE(std::isfinite(x));
        ASSERT_TRUE(std::isfinite(st[0]) && std::isfinite(st[1]));
    }
}

// The bounding cone (peak_friction_angle), as subloading Cam clay's: the ellipse runs through
// the origin, so a drained extension from OCR 8 reaches tension in the model as published;
// bounded by the Matsuoka-Nakai cone of 40 deg, no step passes 6 sin 40 / (3 + sin 40) (the
// closed form at extension) and no stress is tensile.
TEST(ModifiedCamClay, PeakConeBoundsTheStressAndExcludesTension) {
    auto extension = [](double peak) {
        CamClayParameters p = seed_parameters();
        p.ocr = 8.0;
        p.peak_friction_angle = peak;
        return run_from_isotropic(ModifiedCamClay(p), 150e3,
                                  {ElementLeg::AxialStrain, ElementLeg::LateralStress, -0.3, 3000}).path;
    };
    double least_free = 1e300;
    for (const auto& r : extension(0.0)) least_free = std::min(least_free, r.axial_stress);
    EXPECT_LT(least_free, 0.0) << "the unbounded model reaches tension on this path";
    const double s = std::sin(40.0 * M_PI / 180.0), Me = 6.0 * s / (3.0 + s);
    double most = 0.0, least = 1e300;
    for (const auto& r : extension(40.0)) {
        most = std::max(most, std::abs(r.q) / r.p);
        least = std::min(least, r.axial_stress);
    }
    EXPECT_LE(most, Me * (1.0 + 1e-9));
    EXPECT_GT(least, 0.0);
}
