// Hypoplasticity (von Wolffersdorff 1996) with intergranular strain (Niemunis & Herle
// 1997), issue 5, verification 1, at the model level: isotropic compression from the
// loosest state follows e_i(p); the stiffness on a strain reversal is m_R times the
// hypoelastic L, after a 90 degree turn m_T times; a point at zero or tensile stress stays
// finite; and the stable-time-step modulus bounds the response.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mpm/materials/element_test.hpp"
#include "mpm/materials/hypoplastic.hpp"

using namespace pilempm::mpm;

namespace {

// Schlabendorfer sand (seed 000).
HypoplasticParameters schlabendorfer(bool igs) {
    HypoplasticParameters p;
    p.intergranular_strain = igs;
    return p;
}

// One update of one point with the strain increment de (engineering shear).
void step(const Hypoplastic& m, const double* de, double* s, std::vector<double>& st) {
    const int idx = 0;
    m.update(1, &idx, de, s, st.data(), m.num_state());
}

double ddot(const double* a, const double* b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + 2.0 * (a[3] * b[3] + a[4] * b[4] + a[5] * b[5]);
}

}  // namespace

TEST(Hypoplastic, IsotropicCompressionFromTheLoosestStateFollowsBauersLaw) {
    HypoplasticParameters par = schlabendorfer(false);
    const double p0 = 50e3;
    Hypoplastic probe(par);
    par.void_ratio = probe.e_i(p0 + par.p_t);
    const Hypoplastic model(par);
    const double s0[6] = {-p0, -p0, -p0, 0, 0, 0};
    std::vector<double> st(model.num_state());
    model.initialise_state(s0, st.data());
    ElementTest test(model, s0, st);
    ElementLeg leg;
    leg.axial = ElementLeg::AxialStress;
    leg.lateral = ElementLeg::LateralStressEqualsAxial;
    leg.axial_target = 10e6;
    leg.steps = 1000;
    std::vector<ElementRecord> path;
    test.run(leg, path);
    double worst = 0.0;
    for (const auto& r : path) worst = std::max(worst, std::abs(r.state.back() - model.e_i(r.p + par.p_t)) / r.state.back());
    EXPECT_LT(worst, 1e-4);  // issue asks 1 %; the integration does better
    EXPECT_LT(path.back().state.back(), 0.65);  // and it did compress (e_i(10 MPa) = 0.59)
}

// After monotonic compression (delta fully mobilised), a reversed increment meets m_R L and
// a 90 degree turn m_T L; L is measured from the model without intergranular strain as
// (dT(d) - dT(-d)) / 2, which removes the N |D| part.
TEST(Hypoplastic, IntergranularStrainRaisesTheStiffnessByMrOnReversalAndMtOnATurn) {
    const HypoplasticParameters par = schlabendorfer(true);
    const Hypoplastic igs(par);
    const Hypoplastic plain(schlabendorfer(false));
    Hypoplastic::Point pt{{-100e3, -100e3, -150e3, 0, 0, 0}, {0, 0, 0, 0, 0, 0}, 0.7};
    // Build up delta along axial compression: delta -> -R_max e_zz.
    const double dz[6] = {0, 0, -1e-5, 0, 0, 0};
    double dT[6], dd[6];
    for (int k = 0; k < 1000; ++k) {
        igs.rate(pt, dz, dT, dd);
        for (int i = 0; i < 6; ++i) pt.delta[i] += dd[i];
    }
    EXPECT_NEAR(std::sqrt(ddot(pt.delta, pt.delta)), par.R_max, 1e-3 * par.R_max);
    auto L_of = [&](const double* d, double* out) {
        double a[6], b[6], g[6], minus[6];
        for (int i = 0; i < 6; ++i) minus[i] = -d[i];
        plain.rate(pt, d, a, g);
        plain.rate(pt, minus, b, g);
        for (int i = 0; i < 6; ++i) out[i] = 0.5 * (a[i] - b[i]);
    };
    const double reverse[6] = {0, 0, 1e-7, 0, 0, 0};
    double LD[6];
    L_of(reverse, LD);
    igs.rate(pt, reverse, dT, dd);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(dT[i], par.m_R * LD[i], 1e-9 * std::abs(par.m_R * LD[2])) << i;
    // A shear increment is orthogonal to delta: m_T L.
    const double turn[6] = {0, 0, 0, 1e-7, 0, 0};
    L_of(turn, LD);
    igs.rate(pt, turn, dT, dd);
    EXPECT_NEAR(dT[3], par.m_T * LD[3], 1e-9 * std::abs(par.m_T * LD[3]));
    // Continued loading at rho = 1 is plain hypoplasticity (L + N |D|).
    double plainT[6];
    plain.rate(pt, dz, plainT, dd);
    igs.rate(pt, dz, dT, dd);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(dT[i], plainT[i], 1e-3 * std::abs(plainT[2])) << i;
}

TEST(Hypoplastic, PointAtZeroOrTensileStressStaysFinite) {
    for (bool igs : {false, true}) {
        for (double p_t : {0.0, 1e3}) {
            HypoplasticParameters par = schlabendorfer(igs);
            par.p_t = p_t;
            const Hypoplastic model(par);
            double s[6] = {0, 0, 0, 0, 0, 0};
            std::vector<double> st(model.num_state());
            model.initialise_state(s, st.data());
            const double pull[6] = {1e-3, 1e-3, 1e-3, 2e-3, 0, 0}, push[6] = {-1e-4, -1e-4, -2e-4, 0, 1e-4, 0};
            for (int k = 0; k < 50; ++k) step(model, pull, s, st);
            for (int i = 0; i < 6; ++i) EXPECT_TRUE(std::isfinite(s[i]));
            EXPECT_LE(-(s[0] + s[1] + s[2]) / 3.0 + p_t, 1.0 + 1e-9);  // at the floor p_s = p_min
            for (int k = 0; k < 50; ++k) step(model, push, s, st);
            for (int i = 0; i < 6; ++i) EXPECT_TRUE(std::isfinite(s[i]));
            // Compression builds up again, slowly: the stiffness grows as p_s^(1 - n) from p_min.
            EXPECT_GT(-(s[0] + s[1] + s[2]) / 3.0 + p_t, 100.0) << igs << " " << p_t;
            EXPECT_TRUE(std::isfinite(model.p_wave_modulus_at(s, st.data())));
        }
    }
}

// The stable-step modulus at a point bounds its uniaxial-strain tangent in either direction.
TEST(Hypoplastic, PointModulusBoundsTheUniaxialTangent) {
    for (bool igs : {false, true}) {
        const Hypoplastic model(schlabendorfer(igs));
        for (double sign : {-1.0, 1.0}) {
            double s[6] = {-100e3, -100e3, -100e3, 0, 0, 0};
            std::vector<double> st(model.num_state());
            model.initialise_state(s, st.data());
            const double M = model.p_wave_modulus_at(s, st.data());
            const double de[6] = {0, 0, sign * 1e-7, 0, 0, 0};
            const double before = s[2];
            step(model, de, s, st);
            // The secant over the step may exceed the tangent at its start by O(step).
            EXPECT_LE(std::abs(s[2] - before) / 1e-7, M * (1.0 + 1e-3)) << igs << " " << sign;
            EXPECT_GT(std::abs(s[2] - before) / 1e-7, 0.1 * M);
        }
    }
}
