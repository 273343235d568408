// Subloading Cam clay with the Matsuoka-Nakai critical state (issue 5, verification 4):
// (a) on the normal surface (OCR 1) with a circular critical state surface it is modified
// Cam clay, and with a very large a an overconsolidated test approaches MCC too; (b) the
// elastic-plastic transition from OCR 2 and 4 is smooth, plastic from the first step, rho
// falls monotonically towards 0; (c) q / p' at critical state is 6 sin phi / (3 -+ sin phi)
// in compression and extension. Plus the surface itself, the gradient, set-up, zero stress.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <vector>

#include "io/cases/material_input.hpp"
#include "mpm/materials/element_test.hpp"
#include "mpm/materials/modified_cam_clay.hpp"
#include "mpm/materials/subloading_cam_clay.hpp"

using namespace pilempm::mpm;

namespace {

const double kSinPhi = std::sin(35.0 * M_PI / 180.0);
const double kMc = 6.0 * kSinPhi / (3.0 - kSinPhi), kMe = 6.0 * kSinPhi / (3.0 + kSinPhi);

// Seed 002, Fontainebleau NE34: lambda 0.15, kappa 0.013, phi_cs 35 deg, e0 0.62, nu 0.3, a 2000.
SubloadingCamClayParameters seed_parameters(double ocr = 1.0,
                                            CriticalStateSurface surface = CriticalStateSurface::MatsuokaNakai) {
    SubloadingCamClayParameters p;
    p.lambda = 0.15;
    p.kappa = 0.013;
    p.friction_angle = 35.0;
    p.surface = surface;
    p.poisson_ratio = 0.3;
    p.void_ratio = 0.62;
    p.ocr = ocr;
    p.a = 2000.0;
    return p;
}

CamClayParameters mcc_parameters(double ocr) {
    CamClayParameters p;
    p.lambda = 0.15;
    p.kappa = 0.013;
    p.M = kMc;
    p.poisson_ratio = 0.3;
    p.void_ratio = 0.62;
    p.ocr = ocr;
    return p;
}

struct TestPath {
    std::vector<ElementRecord> path;
    std::vector<double> state0;
};

TestPath run_from_isotropic(const ConstitutiveModel& model, double p0, const std::vector<ElementLeg>& legs) {
    const double s0[6] = {-p0, -p0, -p0, 0, 0, 0};
    TestPath r;
    r.state0.resize(model.num_state());
    model.initialise_state(s0, r.state0.data());
    ElementTest test(model, s0, r.state0);
    r.path.push_back(test.record());
    for (const auto& leg : legs) test.run(leg, r.path);
    return r;
}

// Largest difference of p' and q between two paths of the same steps, relative to max |q|.
double path_difference(const std::vector<ElementRecord>& a, const std::vector<ElementRecord>& b) {
    double qmax = 0.0, worst = 0.0;
    for (const auto& r : b) qmax = std::max(qmax, std::abs(r.q));
    for (std::size_t k = 0; k < a.size(); ++k)
        worst = std::max({worst, std::abs(a[k].q - b[k].q), std::abs(a[k].p - b[k].p)});
    return worst / qmax;
}

// Tangent dq / d eps_a of each step, and the largest change between consecutive steps
// relative to the first tangent.
double largest_tangent_jump(const std::vector<ElementRecord>& path, std::size_t last) {
    std::vector<double> Et;
    for (std::size_t k = 1; k <= last; ++k)
        Et.push_back((path[k].q - path[k - 1].q) / (path[k].axial_strain - path[k - 1].axial_strain));
    double jump = 0.0;
    for (std::size_t k = 1; k < Et.size(); ++k) jump = std::max(jump, std::abs(Et[k] - Et[k - 1]));
    return jump / Et.front();
}

const ElementLeg drained(double strain, int steps) { return {ElementLeg::AxialStrain, ElementLeg::LateralStress, strain, steps}; }
const ElementLeg undrained(double strain, int steps) { return {ElementLeg::AxialStrain, ElementLeg::Undrained, strain, steps}; }

}  // namespace

// The Matsuoka-Nakai cone: I1 I2 / I3 = (9 - sin^2) / (1 - sin^2) at every Lode angle, and
// the triaxial values exactly.
TEST(SubloadingCamClay, CriticalStateRatioIsTheMatsuokaNakaiCone) {
    const SubloadingCamClay model(seed_parameters());
    const double k = (9.0 - kSinPhi * kSinPhi) / (1.0 - kSinPhi * kSinPhi);
    EXPECT_NEAR(model.critical_state_ratio_at(1.0), kMc, 1e-12);
    EXPECT_NEAR(model.critical_state_ratio_at(-1.0), kMe, 1e-12);
    for (int i = 0; i <= 40; ++i) {
        const double c = -1.0 + i / 20.0, theta = std::acos(c) / 3.0, eta = model.critical_state_ratio_at(c);
        double sg[3];  // principal, compression positive, p' = 1
        for (int j = 0; j < 3; ++j) sg[j] = 1.0 + 2.0 * eta / 3.0 * std::cos(theta - 2.0 * M_PI * j / 3.0);
        const double I1 = sg[0] + sg[1] + sg[2], I2 = sg[0] * sg[1] + sg[1] * sg[2] + sg[2] * sg[0];
        ASSERT_NEAR(I1 * I2 / (sg[0] * sg[1] * sg[2]), k, 1e-9 * k) << "cos 3theta = " << c;
    }
    // From a stress: triaxial extension (axial z unloaded), tension positive.
    const double te[6] = {-120e3, -120e3, -60e3, 0, 0, 0}, tc[6] = {-60e3, -60e3, -120e3, 0, 0, 0};
    EXPECT_NEAR(model.critical_state_ratio(te), kMe, 1e-10);
    EXPECT_NEAR(model.critical_state_ratio(tc), kMc, 1e-10);
    const SubloadingCamClay dp(seed_parameters(1.0, CriticalStateSurface::DruckerPrager));
    EXPECT_NEAR(dp.critical_state_ratio(te), kMc, 1e-12);
}

// The flow direction (with the Lode term of M) is the gradient of the subloading surface.
TEST(SubloadingCamClay, FlowDirectionIsTheGradientOfTheSurface) {
    const SubloadingCamClay model(seed_parameters(2.0));
    const double s[6] = {-90e3, -130e3, -170e3, 20e3, -15e3, 8e3};
    double st[4];
    model.initialise_state(s, st);
    double n[6];
    model.flow_direction(s, st, n);
    for (int i = 0; i < 6; ++i) {
        double sp[6], sm[6];
        std::copy(s, s + 6, sp);
        std::copy(s, s + 6, sm);
        const double h = 1.0;  // Pa
        sp[i] += h;
        sm[i] -= h;
        // A Voigt shear stress stands for two tensor components: the engineering form.
        const double fd = (model.yield_function(sp, st[0], st[2]) - model.yield_function(sm, st[0], st[2])) / (2.0 * h);
        EXPECT_NEAR(n[i], fd, 1e-6 * 170e3) << "component " << i;
    }
}

TEST(SubloadingCamClay, InitialStateFromTheOverconsolidationRatio) {
    const double s[6] = {-0.45 * 150e3, -0.45 * 150e3, -150e3, 0, 0, 0};  // K0 = 0.45
    for (double ocr : {1.0, 4.0}) {
        const SubloadingCamClay model(seed_parameters(ocr));
        double st[4];
        model.initialise_state(s, st);
        const double ps = model.subloading_size(s);
        EXPECT_NEAR(st[0], ocr * ps, 1e-9 * ps);
        EXPECT_NEAR(st[2], (0.15 - 0.013) * std::log(ocr), 1e-12);
        EXPECT_NEAR(model.yield_function(s, st[0], st[2]), 0.0, 1e-9 * ps * ps);  // on the subloading surface
        EXPECT_EQ(st[1], 0.62);
        EXPECT_STREQ(model.state_name(2), "subloading_rho");
    }
}

// (a) rho = 0 and a circular critical state surface: modified Cam clay, drained and
// undrained compression and undrained extension, within 1 %. (Drained extension from the NC
// state first unloads inside the surface, where the models differ by design: below.)
TEST(SubloadingCamClay, OnTheNormalSurfaceItIsModifiedCamClay) {
    const SubloadingCamClay sub(seed_parameters(1.0, CriticalStateSurface::DruckerPrager));
    const ModifiedCamClay mcc(mcc_parameters(1.0));
    const double p0 = 150e3;
    for (const auto& legs : {std::vector<ElementLeg>{drained(0.8, 8000)}, std::vector<ElementLeg>{undrained(0.3, 3000)},
                             std::vector<ElementLeg>{undrained(-0.3, 3000)}}) {
        const TestPath a = run_from_isotropic(sub, p0, legs), b = run_from_isotropic(mcc, p0, legs);
        const double diff = path_difference(a.path, b.path);
        RecordProperty("path_difference", std::to_string(diff));
        EXPECT_LT(diff, 0.01) << "leg to " << legs[0].axial_target;
        const auto& end = a.path.back();
        EXPECT_NEAR(std::abs(end.q) / end.p, kMc, 0.01 * kMc);
        EXPECT_NEAR(end.state[1], b.path.back().state[1], 0.01 * b.path.back().state[1]);
        EXPECT_NEAR(end.state[2], 0.0, 1e-6);
    }
    // The drained compression ends on the CSL: e_N - (lambda - kappa) ln 2 - lambda ln p'.
    const TestPath d = run_from_isotropic(sub, p0, {drained(0.8, 8000)});
    const auto& end = d.path.back();
    const double e_cs = 0.62 + 0.15 * std::log(p0) - (0.15 - 0.013) * std::log(2.0) - 0.15 * std::log(end.p);
    EXPECT_NEAR(end.state[1], e_cs, 0.01 * e_cs);
    EXPECT_NEAR(end.p, 3.0 * p0 / (3.0 - kMc), 0.01 * 3.0 * p0 / (3.0 - kMc));
}

// (a) With a very large a the subloading effect dies within a hair of the normal surface:
// overconsolidated tests (and drained extension from OCR 1) approach modified Cam clay.
TEST(SubloadingCamClay, LargeSubloadingParameterApproachesModifiedCamClay) {
    for (double ocr : {1.0, 2.0, 4.0}) {
        auto par = seed_parameters(ocr, CriticalStateSurface::DruckerPrager);
        par.a = 1e7;
        const SubloadingCamClay sub(par);
        const ModifiedCamClay mcc(mcc_parameters(ocr));
        for (const auto& legs : {std::vector<ElementLeg>{drained(0.4, 4000)}, std::vector<ElementLeg>{drained(-0.3, 3000)},
                                 std::vector<ElementLeg>{undrained(0.3, 3000)}}) {
            const TestPath a = run_from_isotropic(sub, 150e3, legs), b = run_from_isotropic(mcc, 150e3, legs);
            const double diff = path_difference(a.path, b.path);
            RecordProperty("large_a_difference", std::to_string(diff));
            EXPECT_LT(diff, 0.01) << "OCR " << ocr << ", leg to " << legs[0].axial_target;
        }
    }
}

// (b) From OCR 2 and 4 the tangent dq / d eps_a changes smoothly from the first step (no
// jump above 2 % of the initial tangent between steps of 1e-4 axial strain, and half the
// jump with half the step: continuous), plastic strain from the first step, rho falling
// monotonically towards 0; modified Cam clay jumps at first yield whatever the step.
TEST(SubloadingCamClay, SmoothElasticPlasticTransitionWhenOverconsolidated) {
    for (double ocr : {2.0, 4.0}) {
        const SubloadingCamClay sub(seed_parameters(ocr));
        const TestPath r = run_from_isotropic(sub, 150e3, {drained(0.3, 3000)});
        const double jump = largest_tangent_jump(r.path, 1000);  // the first 10 % strain
        RecordProperty("tangent_jump_ocr" + std::to_string(int(ocr)), std::to_string(jump));
        EXPECT_LT(jump, 0.02) << "OCR " << ocr;
        const TestPath fine = run_from_isotropic(sub, 150e3, {drained(0.3, 6000)});
        EXPECT_LT(largest_tangent_jump(fine.path, 2000), 0.6 * jump) << "OCR " << ocr;
        EXPECT_GT(r.path[1].state[3], 0.0);  // plastic strain in the first step
        for (std::size_t k = 1; k < r.path.size(); ++k)
            ASSERT_LE(r.path[k].state[2], r.path[k - 1].state[2] + 1e-12) << "OCR " << ocr << " step " << k;
        EXPECT_LT(r.path.back().state[2], 0.01 * r.state0[2]);
        const ModifiedCamClay mcc(mcc_parameters(ocr));
        const TestPath m = run_from_isotropic(mcc, 150e3, {drained(0.3, 3000)});
        const double mcc_jump = largest_tangent_jump(m.path, 1000);
        RecordProperty("mcc_tangent_jump_ocr" + std::to_string(int(ocr)), std::to_string(mcc_jump));
        EXPECT_GT(mcc_jump, 0.2) << "MCC, OCR " << ocr;
        const TestPath mfine = run_from_isotropic(mcc, 150e3, {drained(0.3, 6000)});
        EXPECT_GT(largest_tangent_jump(mfine.path, 2000), 0.2) << "MCC, OCR " << ocr;
    }
}

// (c) Matsuoka-Nakai: drained and undrained compression and extension end at
// q / p' = 6 sin phi / (3 -+ sin phi), within 1 %.
TEST(SubloadingCamClay, CriticalStateInCompressionAndExtension) {
    for (double ocr : {1.0, 4.0}) {
        const SubloadingCamClay model(seed_parameters(ocr));
        const auto tc = run_from_isotropic(model, 150e3, {drained(0.8, 8000)}).path.back();
        const auto te = run_from_isotropic(model, 150e3, {drained(-0.4, 4000)}).path.back();
        const auto uc = run_from_isotropic(model, 150e3, {undrained(0.3, 3000)}).path.back();
        const auto ue = run_from_isotropic(model, 150e3, {undrained(-0.3, 3000)}).path.back();
        EXPECT_NEAR(tc.q / tc.p, kMc, 0.01 * kMc) << "OCR " << ocr;
        EXPECT_NEAR(-te.q / te.p, kMe, 0.01 * kMe) << "OCR " << ocr;
        EXPECT_NEAR(uc.q / uc.p, kMc, 0.01 * kMc) << "OCR " << ocr;
        EXPECT_NEAR(-ue.q / ue.p, kMe, 0.01 * kMe) << "OCR " << ocr;
        EXPECT_NEAR(te.p, 3.0 * 150e3 / (3.0 + kMe), 0.01 * 150e3) << "OCR " << ocr;
    }
}

// Oedometer from the K0 state of seed 002 (K0 0.45, sigma'_v 150 kPa): the loading slope in
// e - ln sigma'_v tends to lambda; unloading starts elastic (slope kappa in e - ln p', no
// plastic strain); reloading is plastic from its first step.
TEST(SubloadingCamClay, OedometerLoadingUnloadingReloading) {
    const SubloadingCamClay model(seed_parameters());
    const double s0[6] = {-0.45 * 150e3, -0.45 * 150e3, -150e3, 0, 0, 0};
    std::vector<double> st(4);
    model.initialise_state(s0, st.data());
    ElementTest test(model, s0, st);
    std::vector<ElementRecord> load, unload, reload;
    test.run({ElementLeg::AxialStress, ElementLeg::LateralStrainZero, 1600e3, 1600}, load);
    test.run({ElementLeg::AxialStress, ElementLeg::LateralStrainZero, 400e3, 1200}, unload);
    test.run({ElementLeg::AxialStress, ElementLeg::LateralStrainZero, 1600e3, 1200}, reload);
    const auto& a = load[load.size() / 2];
    const auto& b = load.back();
    const double slope = -(b.state[1] - a.state[1]) / std::log(b.axial_stress / a.axial_stress);
    RecordProperty("ncl_slope", std::to_string(slope));
    EXPECT_NEAR(slope, 0.15, 0.01 * 0.15);
    const auto& u = unload[50];
    EXPECT_NEAR(u.state[3], b.state[3], 1e-12);  // no plastic strain on the first unloading steps
    const double kap = -(u.state[1] - b.state[1]) / std::log(u.p / b.p);
    EXPECT_NEAR(kap, 0.013, 0.01 * 0.013);
    EXPECT_GT(reload[0].state[3], unload.back().state[3]);  // plastic at once on reloading
    // Back at 1600 kPa the loop has densified the soil a little (e below the NCL by rho, p_c
    // above its first-loading value), as subloading models do (cyclic densification).
    const double gap = b.state[1] - reload.back().state[1];
    RecordProperty("reload_e_gap", std::to_string(gap));
    EXPECT_GT(gap, 0.0);
    EXPECT_LT(gap, 0.1 * (load.front().state[1] - b.state[1]));
    EXPECT_GT(reload.back().state[2], 0.0);
}

// Cyclic undrained loading of a normally consolidated point: plastic strain on every
// reloading, so p' keeps falling cycle after cycle (MCC is elastic inside after the first).
TEST(SubloadingCamClay, CyclicUndrainedLoadingAccumulatesPorePressure) {
    const SubloadingCamClay model(seed_parameters());
    std::vector<ElementLeg> legs;
    for (int c = 0; c < 4; ++c) {
        legs.push_back(undrained(0.002, 200));
        legs.push_back(undrained(-0.002, 200));
    }
    const TestPath r = run_from_isotropic(model, 150e3, legs);
    double last = 150e3;
    for (std::size_t c = 1; c <= 4; ++c) {
        const double p = r.path[400 * c].p;  // the end of each cycle
        EXPECT_LT(p, last) << "cycle " << c;
        last = p;
    }
    for (const auto& rec : r.path) ASSERT_TRUE(std::isfinite(rec.p) && std::isfinite(rec.q));
}

// A general 3D strain increment in one update against the same in 1000: the substepping
// controls the error (what is left, ~1e-3 at OCR 4, is the void ratio held over the update,
// as in modified Cam clay); the stress ends on the subloading surface.
TEST(SubloadingCamClay, OneLargeIncrementMatchesManySmallOnes) {
    for (double ocr : {1.0, 4.0}) {
        const SubloadingCamClay model(seed_parameters(ocr));
        const double s0[6] = {-60e3, -80e3, -100e3, 10e3, -5e3, 3e3};
        const double d[6] = {3e-3, -1e-3, -6e-3, 4e-3, -2e-3, 1e-3};
        double sa[6], sb[6], sta[4], stb[4], dn[6];
        std::copy(s0, s0 + 6, sa);
        std::copy(s0, s0 + 6, sb);
        model.initialise_state(s0, sta);
        model.initialise_state(s0, stb);
        const int point = 0, n = 1000;
        model.update(1, &point, d, sa, sta, 4);
        for (int i = 0; i < 6; ++i) dn[i] = d[i] / n;
        for (int k = 0; k < n; ++k) model.update(1, &point, dn, sb, stb, 4);
        double err = 0.0, scale = 0.0;
        for (int i = 0; i < 6; ++i) {
            err = std::max(err, std::abs(sa[i] - sb[i]));
            scale = std::max(scale, std::abs(sb[i]));
        }
        EXPECT_LT(err / scale, 2e-3) << "OCR " << ocr;
        EXPECT_NEAR(sta[0], stb[0], 1e-3 * stb[0]);
        EXPECT_NEAR(sta[2], stb[2], 2e-3 * std::max(stb[2], 0.01));
        EXPECT_NEAR(model.yield_function(sa, sta[0], sta[2]), 0.0, 1e-5 * sta[0] * sta[0]);
    }
}

// A point at zero stress (a free surface, a separated grain) stays finite.
TEST(SubloadingCamClay, ZeroStressStaysFinite) {
    for (auto surface : {CriticalStateSurface::MatsuokaNakai, CriticalStateSurface::DruckerPrager}) {
        const SubloadingCamClay model(seed_parameters(1.0, surface));
        double s[6] = {0, 0, 0, 0, 0, 0};
        double st[4];
        model.initialise_state(s, st);
        EXPECT_TRUE(std::isfinite(model.p_wave_modulus_at(s, st)));
        const int point = 0;
        for (double de : {1e-3, -1e-3, 2e-3, 0.0, -5e-3, 5e-3}) {
            const double d[6] = {de, -0.5 * de, 0.3 * de, 1e-3, 0, -2e-4};
            model.update(1, &point, d, s, st, 4);
            for (double x : s) ASSERT_TRUE(std::isfinite(x));
            for (double x : st) ASSERT_TRUE(std::isfinite(x));
            ASSERT_TRUE(std::isfinite(model.p_wave_modulus_at(s, st)));
        }
    }
}

// Case-file keys: subloading_a is required, the surface is one of two names.
TEST(SubloadingCamClay, MaterialKeysAreValidated) {
    auto read = [](const std::string& text) {
        return pilempm::io::read_material(pilempm::io::MapReader(YAML::Load(text), "material", "case.yaml"), false);
    };
    const std::string base = "{model: subloading_cam_clay, lambda: 0.15, kappa: 0.013, friction_angle: 35.0, "
                             "poisson_ratio: 0.3, void_ratio: 0.62, ocr: 4.0";
    const auto m = read(base + ", subloading_a: 2000.0}");
    EXPECT_EQ(m.subloading_a, 2000.0);
    EXPECT_EQ(m.critical_state_surface, "matsuoka_nakai");
    EXPECT_EQ(pilempm::mpm::make_constitutive_model(m)->name(), "subloading_cam_clay");
    auto message = [&](const std::string& text) {
        try {
            read(text);
        } catch (const std::exception& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message(base + "}").find("subloading_a"), std::string::npos) << message(base + "}");
    EXPECT_NE(message(base + ", subloading_a: -1.0}").find("subloading_a"), std::string::npos);
    const std::string bad = base + ", subloading_a: 2000.0, critical_state_surface: mohr_coulomb}";
    EXPECT_NE(message(bad).find("critical_state_surface"), std::string::npos) << message(bad);
    EXPECT_EQ(read(base + ", subloading_a: 10.0, critical_state_surface: drucker_prager}").critical_state_surface,
              "drucker_prager");
    EXPECT_EQ(m.peak_friction_angle, 0.0) << "no bound unless asked";
    EXPECT_EQ(read(base + ", subloading_a: 2000.0, peak_friction_angle: 40.0}").peak_friction_angle, 40.0);
    const std::string below = base + ", subloading_a: 2000.0, peak_friction_angle: 30.0}";  // under phi_cs
    EXPECT_NE(message(below).find("peak_friction_angle"), std::string::npos) << message(below);
}

// The bounding cone (peak_friction_angle): the subloading surface runs through the origin,
// so a drained extension from OCR 4 of the model as published peaks beyond any frictional
// cone, its axial stress tensile. Bounded by the Matsuoka-Nakai cone of phi_peak, no step of
// the same test passes 6 sin phi_peak / (3 + sin phi_peak) (the closed form at extension)
// nor carries tension; with phi_peak above phi_cs the peak does rise above M_e of phi_cs.
TEST(SubloadingCamClay, PeakConeBoundsTheStressAndExcludesTension) {
    auto extension = [](double peak) {
        SubloadingCamClayParameters p = seed_parameters(4.0);
        p.peak_friction_angle = peak;
        return run_from_isotropic(SubloadingCamClay(p), 150e3, {drained(-0.4, 4000)}).path;
    };
    auto least_axial = [](const std::vector<ElementRecord>& path) {
        double least = 1e300;
        for (const auto& r : path) least = std::min(least, r.axial_stress);
        return least;
    };
    auto largest_ratio = [](const std::vector<ElementRecord>& path) {
        double most = 0.0;
        for (const auto& r : path) most = std::max(most, std::abs(r.q) / r.p);
        return most;
    };
    EXPECT_LT(least_axial(extension(0.0)), 0.0) << "the unbounded model reaches tension on this path";
    for (double peak : {35.0, 45.0}) {
        const double s = std::sin(peak * M_PI / 180.0), Me_peak = 6.0 * s / (3.0 + s);
        const auto path = extension(peak);
        EXPECT_LE(largest_ratio(path), Me_peak * (1.0 + 1e-9)) << "phi_peak " << peak;
        EXPECT_GT(least_axial(path), 0.0) << "phi_peak " << peak;
        if (peak > 35.0) EXPECT_GT(largest_ratio(path), 1.05 * kMe) << "a peak above the critical state";
    }
}

// The return onto the cone keeps p' and the Lode angle (an isochoric potential g = q): a
// stress far outside the cone in a general direction, given no strain, lands on the cone at
// its own p' and cos 3theta, and the plastic strain counts the deviator's drop.
TEST(SubloadingCamClay, ReturnToThePeakConeKeepsPressureAndLodeAngle) {
    SubloadingCamClayParameters par = seed_parameters(1.0);
    par.peak_friction_angle = 40.0;
    const SubloadingCamClay model(par);
    const double start[6] = {-120e3, -10e3, -35e3, 30e3, -5e3, 8e3};  // I1 I2 / I3 far above k
    double s[6], state[4];
    std::copy(start, start + 6, s);
    model.initialise_state(s, state);
    const double zero[6] = {0, 0, 0, 0, 0, 0};
    const int point = 0;
    model.update(1, &point, zero, s, state, 4);
    auto invariants = [](const double* t, double& p, double& q, double& c) {
        p = -(t[0] + t[1] + t[2]) / 3.0;
        double d[6] = {t[0] + p, t[1] + p, t[2] + p, t[3], t[4], t[5]};
        const double J2 = 0.5 * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + d[3] * d[3] + d[4] * d[4] + d[5] * d[5];
        const double J3 = d[0] * (d[1] * d[2] - d[4] * d[4]) - d[3] * (d[3] * d[2] - d[4] * d[5]) + d[5] * (d[3] * d[4] - d[1] * d[5]);
        q = std::sqrt(3.0 * J2);
        c = -13.5 * J3 / (q * q * q);
    };
    double p0, q0, c0, p1, q1, c1;
    invariants(start, p0, q0, c0);
    invariants(s, p1, q1, c1);
    // Matsuoka-Nakai on the returned stress, principal-free: I1 I2 / I3 = (9 - sin^2) / (1 - sin^2).
    const double a = -s[0], b = -s[1], cc = -s[2], xy = -s[3], yz = -s[4], zx = -s[5];  // of -sigma
    const double I1 = a + b + cc, I2 = a * b + b * cc + cc * a - xy * xy - yz * yz - zx * zx;
    const double I3 = a * (b * cc - yz * yz) - xy * (xy * cc - yz * zx) + zx * (xy * yz - b * zx);
    const double sn = std::sin(40.0 * M_PI / 180.0);
    EXPECT_NEAR(I1 * I2 / I3, (9.0 - sn * sn) / (1.0 - sn * sn), 1e-6 * (9.0 - sn * sn) / (1.0 - sn * sn));
    EXPECT_NEAR(p1, p0, 1e-9 * p0);
    EXPECT_NEAR(c1, c0, 1e-9);
    EXPECT_LT(q1, q0);
    EXPECT_GT(state[3], 0.0);
}
