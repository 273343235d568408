// CPT interpretation: Robertson & Cabal unit weight and Robertson's I_c against hand and
// independent (bisection) values, the zone boundaries, stresses from the unit weights,
// and the smoothing of thin spurious layers.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "coupling/wave_equation/cpt_interpretation.hpp"

using namespace pilempm::coupling;

namespace {

constexpr double kMpa = 1e6;

// A sounding every 0.5 m from 0.5 m: sand-like (q_c 20 MPa, R_f 0.5 %) except where
// `clay(z)` holds (q_c 1.5 MPa, f_s 40 kPa: I_c about 3.1).
template <class Pred>
CptSounding sounding(double bottom, Pred clay) {
    CptSounding c;
    for (double z = 0.5; z <= bottom + 1e-9; z += 0.5) {
        const bool k = clay(z);
        c.depth.push_back(z);
        c.qc.push_back(k ? 1.5 * kMpa : 20.0 * kMpa);
        c.fs.push_back(k ? 0.04 * kMpa : 0.1 * kMpa);
        c.u2.push_back(k ? 0.3 * kMpa : 0.01 * kMpa * z);
    }
    return c;
}

}  // namespace

TEST(CptInterpretation, UnitWeightOfRobertsonAndCabal) {
    // q_t = 10 MPa, f_s = 0.1 MPa: R_f = 1 % (log 0), log10(q_t / p_a) = 2:
    // gamma / gamma_w = 0.36 * 2 + 1.236 = 1.956.
    EXPECT_NEAR(robertson_cabal_unit_weight(10 * kMpa, 0.1 * kMpa, 10.05e3, 100e3), 1.956 * 10.05e3, 1e-9);
    // R_f = 0.1 %: 0.27 * (-1) more.
    EXPECT_NEAR(robertson_cabal_unit_weight(10 * kMpa, 0.01 * kMpa, 10.0e3, 100e3), (1.956 - 0.27) * 10.0e3, 1e-9);
}

TEST(CptInterpretation, BehaviourIndexMatchesAnIndependentBisection) {
    // References: n solved by bisection on n = 0.381 I_c(n) + 0.05 sigma'/p_a - 0.15 (Python).
    const BehaviourIndex a = robertson_behaviour_index(10 * kMpa, 0.05 * kMpa, 200e3, 100e3, 100e3);
    EXPECT_NEAR(a.ic, 1.745703616, 1e-6);
    EXPECT_NEAR(a.n, 0.565113078, 1e-6);
    const BehaviourIndex b = robertson_behaviour_index(1.5 * kMpa, 0.04 * kMpa, 300e3, 150e3, 100e3);
    EXPECT_NEAR(b.ic, 3.102684859, 1e-6);  // clay-like: n = 1
    EXPECT_DOUBLE_EQ(b.n, 1.0);
    const BehaviourIndex c = robertson_behaviour_index(25 * kMpa, 0.15 * kMpa, 150e3, 70e3, 100e3);
    EXPECT_NEAR(c.ic, 1.420868348, 1e-6);
}

TEST(CptInterpretation, ZonesFollowTheIcBoundaries) {
    EXPECT_EQ(robertson_zone(1.2), 7);
    EXPECT_EQ(robertson_zone(1.31), 6);
    EXPECT_EQ(robertson_zone(2.04), 6);
    EXPECT_EQ(robertson_zone(2.3), 5);
    EXPECT_EQ(robertson_zone(2.7), 4);
    EXPECT_EQ(robertson_zone(3.0), 3);
    EXPECT_EQ(robertson_zone(3.7), 2);
}

TEST(CptInterpretation, StressesIntegrateTheUnitWeights) {
    const CptSounding s = sounding(10.0, [](double) { return false; });
    const CptInterpretationOptions o;
    const CptInterpretation c = interpret_cpt(s, o, 30.0);
    // Trapezoid of the points' own unit weights, the first reading standing for the top.
    double sigma = c.points[0].unit_weight * 0.5;
    for (std::size_t i = 1; i < c.points.size(); ++i)
        sigma += 0.5 * (c.points[i].unit_weight + c.points[i - 1].unit_weight) * 0.5;
    EXPECT_NEAR(c.points.back().sigma_v0, sigma, 1e-9 * sigma);
    EXPECT_NEAR(c.points.back().sigma_v0_eff, sigma - o.water_unit_weight * 10.0, 1e-9 * sigma);
    // The profile: one contiguous layer per reading, gamma' = gamma - gamma_w, and the
    // effective stress it integrates matches the points' at their depths.
    ASSERT_EQ(c.profile.layers.size(), s.depth.size());
    EXPECT_DOUBLE_EQ(c.profile.layers.front().top, 0.0);
    for (std::size_t i = 1; i < c.profile.layers.size(); ++i)
        EXPECT_DOUBLE_EQ(c.profile.layers[i].top, c.profile.layers[i - 1].bottom);
    EXPECT_NEAR(c.profile.layers[3].submerged_unit_weight, c.points[3].unit_weight - o.water_unit_weight, 1e-9);
    EXPECT_NEAR(c.profile.vertical_effective_stress(10.0), c.points.back().sigma_v0_eff,
                0.01 * c.points.back().sigma_v0_eff);
    EXPECT_EQ(c.profile.water_depth, 30.0);
    // q_t = q_c + (1 - a) u_2
    EXPECT_NEAR(c.points[3].qt, s.qc[3] + 0.2 * s.u2[3], 1e-6);
}

TEST(CptInterpretation, ThinSpuriousLayersAreSmoothedAway) {
    // One clay-like reading at 5 m in sand (0.5 m thick, below the 1 m minimum) joins the
    // sand; a 2.5 m clay layer from 7.5 m stays clay.
    const CptSounding s = sounding(15.0, [](double z) {
        return std::abs(z - 5.0) < 1e-9 || (z > 7.4 && z < 9.6);
    });
    const CptInterpretation c = interpret_cpt(s, CptInterpretationOptions{}, 0.0);
    EXPECT_EQ(c.smoothed_points, 1);
    EXPECT_TRUE(c.points[9].clay_like);             // 5.0 m as read
    EXPECT_EQ(c.points[9].type, SoilType::Sand);    // and after smoothing
    for (std::size_t i = 14; i <= 18; ++i) EXPECT_EQ(c.points[i].type, SoilType::Clay) << c.points[i].depth;
    EXPECT_EQ(c.profile.layer_at(8.0).type, SoilType::Clay);
    // s_u = (q_t - sigma_v0) / N_kt in the clay
    const CptPoint& p = c.points[16];
    EXPECT_NEAR(p.su, (p.qt - p.sigma_v0) / 15.0, 1e-6);
    EXPECT_NEAR(c.profile.undrained_shear_strength(p.depth), p.su, 1e-6);
    // With no minimum thickness the single reading stays clay.
    CptInterpretationOptions keep;
    keep.min_layer_thickness = 0.0;
    EXPECT_EQ(interpret_cpt(s, keep, 0.0).points[9].type, SoilType::Clay);
}

TEST(CptInterpretation, BadSoundingsAreRefused) {
    CptSounding s = sounding(3.0, [](double) { return false; });
    s.depth[2] = s.depth[1];
    EXPECT_THROW(interpret_cpt(s, CptInterpretationOptions{}, 0.0), std::invalid_argument);
    CptSounding t = sounding(3.0, [](double) { return false; });
    t.fs.pop_back();
    EXPECT_THROW(interpret_cpt(t, CptInterpretationOptions{}, 0.0), std::invalid_argument);
}

TEST(CptInterpretation, NamesEveryCorrelation) {
    const auto lines = cpt_correlations(CptInterpretationOptions{});
    std::string all;
    for (const auto& l : lines) all += l + "\n";
    for (const char* name : {"Robertson & Cabal (2010)", "Robertson 2009", "Baldi", "Kulhawy & Mayne", "N_kt"})
        EXPECT_NE(all.find(name), std::string::npos) << name;
}
