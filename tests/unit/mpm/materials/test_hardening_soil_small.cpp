// Hardening soil small (Benz 2007) at the material point: the small-strain secant curve,
// E50 and the Mohr-Coulomb failure deviator in drained triaxial compression (issue 5,
// verification 2), the oedometer calibration of the cap, and finite results at zero and
// tensile stress.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "mpm/materials/element_test.hpp"
#include "mpm/materials/hardening_soil_small.hpp"

using namespace pilempm::mpm;

namespace {

// Seed 001, Table 2, D_R = 99 % (stiffnesses in Pa).
HardeningSoilSmallParameters dense_sand() {
    HardeningSoilSmallParameters p;
    p.E50_ref = 48e6;
    p.Eoed_ref = 48e6;
    p.Eur_ref = 144e6;
    p.nu_ur = 0.2;
    p.G0_ref = 114.4e6;
    p.gamma_07 = 1.2e-4;
    p.m = 0.45;
    p.phi = 38.0;
    p.c = 1e3;
    p.psi = 1.0;
    p.R_f = 0.9;
    return p;
}

// Seed 001, Table 2, D_R = 47 %.
HardeningSoilSmallParameters medium_sand() {
    HardeningSoilSmallParameters p = dense_sand();
    p.E50_ref = 28.2e6;
    p.Eoed_ref = 28.2e6;
    p.Eur_ref = 84.6e6;
    p.G0_ref = 91.6e6;
    p.gamma_07 = 1.53e-4;
    p.m = 0.55;
    p.phi = 34.0;
    p.psi = 0.5;
    return p;
}

std::vector<ElementRecord> drained_triaxial(const HardeningSoilSmall& model, double p0, double eps, int steps) {
    const double s0[6] = {-p0, -p0, -p0, 0, 0, 0};
    std::vector<double> st(model.num_state());
    model.initialise_state(s0, st.data());
    ElementTest test(model, s0, st);
    std::vector<ElementRecord> path{test.record()};
    test.run({ElementLeg::AxialStrain, ElementLeg::LateralStress, eps, steps}, path);
    return path;
}

// E50: the secant q / eps_a where q first reaches half the largest q of the path.
double e50_of(const std::vector<ElementRecord>& path) {
    double qmax = 0.0;
    for (const auto& r : path) qmax = std::max(qmax, r.q);
    for (std::size_t k = 1; k < path.size(); ++k) {
        if (path[k].q >= 0.5 * qmax) {
            const auto &a = path[k - 1], &b = path[k];
            const double eps = a.axial_strain + (0.5 * qmax - a.q) / (b.q - a.q) * (b.axial_strain - a.axial_strain);
            return 0.5 * qmax / eps;
        }
    }
    return 0.0;
}

}  // namespace

TEST(HardeningSoilSmall, StateLayoutAndModuli) {
    const HardeningSoilSmall model(dense_sand());
    EXPECT_EQ(model.num_tensor_state(), 1);
    EXPECT_EQ(model.num_state(), 9);
    EXPECT_STREQ(model.state_name(0), "strain_history_xx");
    EXPECT_STREQ(model.state_name(7), "cap_pressure_Pa");
    const double G0 = 114.4e6, M = G0 * (2.0 * 0.2 / (1.0 - 0.4) + 2.0);
    EXPECT_NEAR(model.p_wave_modulus(), M, 1e-9 * M);
    EXPECT_DOUBLE_EQ(model.shear_modulus(), G0);
    // At sigma'_3 = p_ref the point's modulus is the reference one; it grows with pressure.
    const double s1[6] = {-100e3, -100e3, -100e3, 0, 0, 0}, s4[6] = {-400e3, -400e3, -400e3, 0, 0, 0};
    double st[9] = {};
    EXPECT_NEAR(model.p_wave_modulus_at(s1, st), M, 1e-9 * M);
    EXPECT_GT(model.p_wave_modulus_at(s4, st), 1.8 * M);
    EXPECT_GT(model.cap_alpha(), 0.0);
    EXPECT_GT(model.cap_beta(), 0.0);
}

// (a) With the shear surface far away (pre-hardened state), undrained simple shear is
// elastic: the secant tau / gamma_xy follows G0 / (1 + 0.385 gamma / gamma_0.7) with Benz's
// gamma = (3/2) eps_q = (sqrt 3 / 2) gamma_xy, down to the G_ur floor. m = 0 keeps G0 fixed
// while the principal stresses rotate.
TEST(HardeningSoilSmall, SimpleShearSecantFollowsTheSmallStrainCurve) {
    HardeningSoilSmallParameters p = dense_sand();
    p.m = 0.0;
    const HardeningSoilSmall model(p);
    const double G0 = p.G0_ref, Gur = p.Eur_ref / (2.0 * (1.0 + p.nu_ur)), g07 = p.gamma_07;
    double s[6] = {-100e3, -100e3, -100e3, 0, 0, 0};
    std::vector<double> st(9);
    model.initialise_state(s, st.data());
    st[6] = 1.0;   // shear surface at Mohr-Coulomb,
    st[7] = 1e7;   // cap out of reach
    const int point = 0;
    const double dg = 2e-7;
    double worst = 0.0;
    bool reached_floor = false;
    for (int n = 1; n <= 2500; ++n) {
        const double de[6] = {0, 0, 0, dg, 0, 0};
        model.update(1, &point, de, s, st.data(), 9);
        const double gxy = n * dg, g = std::sqrt(3.0) / 2.0 * gxy;
        const double reference = G0 * model.secant_stress_ratio(g) / g;  // = G0 / (1 + a g / g07) above the floor
        if (st[8] > Gur / G0 + 1e-12) ASSERT_NEAR(reference, G0 / (1.0 + 0.385 * g / g07), 1e-9 * G0);
        else reached_floor = true;
        worst = std::max(worst, std::abs(s[3] / gxy - reference) / reference);
    }
    EXPECT_TRUE(reached_floor);
    EXPECT_LT(worst, 0.005);
    std::printf("simple shear: max |G_s - G_s,Benz| / G_s,Benz = %.3g %%\n", 100.0 * worst);
    // Reversal: the history is wiped and the tangent is back at G0.
    const double back[6] = {0, 0, 0, -dg, 0, 0};
    const double tau = s[3];
    model.update(1, &point, back, s, st.data(), 9);
    EXPECT_NEAR((tau - s[3]) / dg, G0, 0.01 * G0);
    EXPECT_GT(st[8], 0.99);
}

// (a) in triaxial: unloading after primary loading is elastic, and the secant
// dq / (2 d gamma) from the reversal, gamma = eps_a - eps_r, follows the curve.
TEST(HardeningSoilSmall, TriaxialUnloadingSecantFollowsTheSmallStrainCurve) {
    const HardeningSoilSmallParameters p = dense_sand();
    const HardeningSoilSmall model(p);
    const double s0[6] = {-100e3, -100e3, -100e3, 0, 0, 0};
    std::vector<double> st(9);
    model.initialise_state(s0, st.data());
    ElementTest test(model, s0, st);
    std::vector<ElementRecord> load, unload;
    test.run({ElementLeg::AxialStrain, ElementLeg::LateralStress, 0.005, 500}, load);
    test.run({ElementLeg::AxialStrain, ElementLeg::LateralStress, 0.0045, 500}, unload);
    const ElementRecord& rev = load.back();
    auto gamma = [](const ElementRecord& r) { return 1.5 * r.axial_strain - 0.5 * r.volumetric_strain; };
    const double G0 = p.G0_ref;  // sigma'_3 = p_ref throughout
    double worst = 0.0;
    for (const auto& r : unload) {
        const double dgam = gamma(rev) - gamma(r), Gs = (rev.q - r.q) / (2.0 * dgam);
        const double ref = G0 * model.secant_stress_ratio(dgam) / dgam;
        worst = std::max(worst, std::abs(Gs - ref) / ref);
        EXPECT_NEAR(r.state[6], rev.state[6], 1e-12);  // no plastic shear strain
    }
    EXPECT_LT(worst, 0.02);
    std::printf("triaxial unloading: max |G_s - G_s,Benz| / G_s,Benz = %.3g %%\n", 100.0 * worst);
}

// (b), (c): drained triaxial compression at sigma'_3 = p_ref. The cap is moved away (OCR 3)
// so that E50 is the shear hardening's alone; failure at the Mohr-Coulomb deviator
// q_f = 2 sin phi / (1 - sin phi) (sigma'_3 + c cot phi).
TEST(HardeningSoilSmall, DrainedTriaxialE50AndFailure) {
    for (const bool dense : {true, false}) {
        HardeningSoilSmallParameters p = dense ? dense_sand() : medium_sand();
        p.c = 0.0;
        p.ocr = 3.0;
        const HardeningSoilSmall model(p);
        const auto path = drained_triaxial(model, 100e3, 0.1, 4000);
        const double e50 = e50_of(path);
        double qmax = 0.0;
        for (const auto& r : path) qmax = std::max(qmax, r.q);
        const double qf = model.failure_deviator(100e3);
        std::printf("%s: E50 %.4g MPa (ref %.4g, %+.2f %%), q_max %.5g kPa (q_f %.5g, %+.3f %%)\n",
                    dense ? "D_R 99 %" : "D_R 47 %", e50 / 1e6, p.E50_ref / 1e6, 100.0 * (e50 / p.E50_ref - 1.0),
                    qmax / 1e3, qf / 1e3, 100.0 * (qmax / qf - 1.0));
        EXPECT_NEAR(qmax, qf, 0.01 * qf);
        // The small-strain overlay makes the elastic part stiffer than E_ur: E50 lies a
        // little above E50_ref, the more so the larger G0 / G_ur and gamma_0.7.
        if (dense) EXPECT_NEAR(e50, p.E50_ref, 0.02 * p.E50_ref);
        else EXPECT_NEAR(e50, p.E50_ref, 0.04 * p.E50_ref);
        EXPECT_GE(e50, p.E50_ref * 0.999);
    }
}

// The cap's alpha and beta come from a K0nc oedometer: loading one from a K0nc state gives
// Eoed = Eoed_ref (sigma'_1 / p_ref)^m and keeps sigma'_3 / sigma'_1 at K0nc.
TEST(HardeningSoilSmall, OedometerGivesEoedAndK0nc) {
    HardeningSoilSmallParameters p = dense_sand();
    p.c = 0.0;
    const HardeningSoilSmall model(p);
    const double K0 = 1.0 - std::sin(p.phi * M_PI / 180.0);
    const double s0[6] = {-K0 * 100e3, -K0 * 100e3, -100e3, 0, 0, 0};
    std::vector<double> st(9);
    model.initialise_state(s0, st.data());
    ElementTest test(model, s0, st);
    std::vector<ElementRecord> path{test.record()};
    test.run({ElementLeg::AxialStress, ElementLeg::LateralStrainZero, 200e3, 1000}, path);
    // Tangent at the end (well past the small-strain range): Eoed_ref (sigma'_1 / p_ref)^m.
    const auto& a = path[path.size() - 11];
    const auto& b = path.back();
    const double Eoed = (b.axial_stress - a.axial_stress) / (b.axial_strain - a.axial_strain);
    const double Eoed_ref = p.Eoed_ref * std::pow(0.5 * (a.axial_stress + b.axial_stress) / 100e3, p.m);
    const double K = b.lateral_stress / b.axial_stress;
    std::printf("oedometer: Eoed %.4g MPa (ref %.4g), K0 %.4f (K0nc %.4f)\n", Eoed / 1e6, Eoed_ref / 1e6, K, K0);
    EXPECT_NEAR(Eoed, Eoed_ref, 0.01 * Eoed_ref);
    EXPECT_NEAR(K, K0, 0.01 * K0);
}

// A point at zero stress, or pulled into tension, stays finite and admissible.
TEST(HardeningSoilSmall, ZeroAndTensileStressStayFinite) {
    for (const double c : {0.0, 1e3}) {
        HardeningSoilSmallParameters p = dense_sand();
        p.c = c;
        const HardeningSoilSmall model(p);
        double s[6] = {0, 0, 0, 0, 0, 0};
        std::vector<double> st(9);
        model.initialise_state(s, st.data());
        const int point = 0;
        const double incs[4][6] = {{1e-4, 1e-4, 1e-4, 0, 0, 0}, {1e-4, -2e-4, 0, 3e-4, 0, 1e-4},
                                   {-1e-3, -1e-3, -1e-3, 0, 0, 0}, {5e-3, 0, 0, 0, 2e-3, 0}};
        for (int n = 0; n < 40; ++n) {
            model.update(1, &point, incs[n % 4], s, st.data(), 9);
            for (double v : s) ASSERT_TRUE(std::isfinite(v));
            for (double v : st) ASSERT_TRUE(std::isfinite(v));
            ASSERT_TRUE(std::isfinite(model.p_wave_modulus_at(s, st.data())));
            // No principal stress beyond the Mohr-Coulomb apex c cot(phi).
            ASSERT_LE(std::max({s[0], s[1], s[2]}), c / std::tan(p.phi * M_PI / 180.0) + 1e-6 + 1e-3 * std::abs(s[0] + s[1] + s[2]));
        }
    }
}

// The secant curve of an elastic path does not depend on the step size (the tangent is
// integrated exactly along a monotonic increment).
TEST(HardeningSoilSmall, SmallStrainResponseIndependentOfStepSize) {
    HardeningSoilSmallParameters p = dense_sand();
    p.m = 0.0;
    const HardeningSoilSmall model(p);
    double tau[2];
    for (int k = 0; k < 2; ++k) {
        double s[6] = {-100e3, -100e3, -100e3, 0, 0, 0};
        std::vector<double> st(9);
        model.initialise_state(s, st.data());
        st[6] = 1.0;
        st[7] = 1e7;
        const int point = 0, n = k == 0 ? 1 : 1000;
        const double de[6] = {0, 0, 0, 3e-4 / n, 0, 0};
        for (int i = 0; i < n; ++i) model.update(1, &point, de, s, st.data(), 9);
        tau[k] = s[3];
    }
    EXPECT_NEAR(tau[0], tau[1], 1e-9 * std::abs(tau[1]));
}
