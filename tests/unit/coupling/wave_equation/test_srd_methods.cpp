// SRD soil model: Alm & Hamre (2001) and Stevens et al. (1982) unit values against the
// spec's test vectors, the soil profile (stress, CPT, Baldi), and compute_srd's sampling.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "coupling/wave_equation/soil_profile.hpp"
#include "coupling/wave_equation/srd_methods.hpp"

using namespace pilempm::coupling;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kKpa = 1e3;

// Relative comparison: the spec prints its vectors to 4-6 significant figures.
void expect_rel(double actual, double expected, double tol = 1e-4) {
    EXPECT_NEAR(actual, expected, tol * std::abs(expected)) << "expected " << expected;
}

SoilLayer sand(double top, double bottom, double gamma, double dr, double delta) {
    SoilLayer l;
    l.top = top;
    l.bottom = bottom;
    l.type = SoilType::Sand;
    l.submerged_unit_weight = gamma;
    l.relative_density = dr;
    l.interface_friction_angle = delta;
    l.name = "sand";
    return l;
}

SoilLayer clay(double top, double bottom, double gamma, double su, double su_gradient,
               double sensitivity) {
    SoilLayer l;
    l.top = top;
    l.bottom = bottom;
    l.type = SoilType::Clay;
    l.submerged_unit_weight = gamma;
    l.undrained_shear_strength = su;
    l.undrained_shear_strength_gradient = su_gradient;
    l.sensitivity = sensitivity;
    l.name = "clay";
    return l;
}

SoilProfile uniform_dense_sand() {
    SoilProfile s;
    s.layers = {sand(0.0, 50.0, 10e3, 0.8, 29.0)};
    return s;
}

// Dense sand over a firm clay: the unit friction jumps at 8 m.
SoilProfile sand_over_clay() {
    SoilProfile s;
    s.water_depth = 30.0;
    s.layers = {sand(0.0, 8.0, 10e3, 0.75, 28.0), clay(8.0, 40.0, 8e3, 60e3, 2e3, 2.5)};
    return s;
}

// Midpoint rule with n steps on the unit friction of the spec, straight from the profile.
double reference_alm_hamre_shaft(const SoilProfile& soil, const SrdCoefficients& k, double d_outer,
                                 double d_inner, double p, int n) {
    const double h = p / n;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double z = (i + 0.5) * h;
        const SoilLayer& l = soil.layer_at(z);
        const double sigma = soil.vertical_effective_stress(z);
        const double qt = soil.cone_resistance(z);
        if (l.type == SoilType::Sand) {
            const double f = alm_hamre_sand_shaft_friction(qt, sigma, l.interface_friction_angle, z,
                                                           p, k.atmospheric_pressure);
            sum +=
                f * kPi * (k.alm_hamre_sand_outside * d_outer + k.alm_hamre_sand_inside * d_inner);
        } else {
            const double f =
                alm_hamre_clay_shaft_friction(qt, soil.sleeve_friction(z), sigma, z, p);
            sum +=
                f * kPi * (k.alm_hamre_clay_outside * d_outer + k.alm_hamre_clay_inside * d_inner);
        }
    }
    return sum * h;
}

}  // namespace

// ---- Alm & Hamre (2001), spec 1.6 ------------------------------------------------------

TEST(SrdAlmHamre, SandTestVectors) {
    const double qc = 15e6, sigma = 100e3, delta = 28.0, pa = 101.325e3;
    const double f_tip = alm_hamre_sand_shaft_friction(qc, sigma, delta, 30.0, 30.0, pa);
    const double f_far = alm_hamre_sand_shaft_friction(qc, sigma, delta, 30.0, 2030.0, pa);
    const double f_20 = alm_hamre_sand_shaft_friction(qc, sigma, delta, 20.0, 30.0, pa);
    expect_rel(f_tip, 105.098 * kKpa);
    expect_rel(f_far, 21.020 * kKpa);  // f_s,res = 0.2 f_s,i
    expect_rel(f_20, 39.209 * kKpa);
    expect_rel(0.5 * f_tip, 52.549 * kKpa);
    expect_rel(0.5 * f_20, 19.604 * kKpa);
    // The decay over h = 10 m gives back the shape factor k = sqrt(150) / 80.
    const double k = -std::log((f_20 - f_far) / (f_tip - f_far)) / 10.0;
    expect_rel(k, 0.153093);
    expect_rel(alm_hamre_sand_shaft_friction(qc, sigma, delta, 30.0, 30.0, 100e3), 105.278 * kKpa);
}

TEST(SrdAlmHamre, ClayTestVectors) {
    const double qt = 1.5e6, fs = 0.2e6, sigma = 100e3;
    const double f_tip = alm_hamre_clay_shaft_friction(qt, fs, sigma, 30.0, 30.0);
    const double f_far = alm_hamre_clay_shaft_friction(qt, fs, sigma, 30.0, 5030.0);
    const double f_20 = alm_hamre_clay_shaft_friction(qt, fs, sigma, 20.0, 30.0);
    expect_rel(f_tip, 200.0 * kKpa);
    expect_rel(f_far, 5.775 * kKpa);
    expect_rel(f_20, 125.464 * kKpa);
    const double k = -std::log((f_20 - f_far) / (f_tip - f_far)) / 10.0;
    expect_rel(k, 0.0484123);
}

TEST(SrdAlmHamre, EndBearingTestVectors) {
    expect_rel(alm_hamre_sand_end_bearing(15e6, 100e3), 6129.157 * kKpa);
    expect_rel(alm_hamre_clay_end_bearing(1.5e6), 900.0 * kKpa);
}

TEST(SrdAlmHamre, ClayResidualClippedToZeroAndToInitial) {
    // q_t / sigma'_v0 = 500 > 400: the residual bracket is negative, clipped to 0.
    EXPECT_EQ(alm_hamre_clay_shaft_friction(5e6, 100e3, 10e3, 0.0, 1e4), 0.0);
    // A residual above the sleeve friction is clipped to f_s,i: no degradation left.
    expect_rel(alm_hamre_clay_shaft_friction(1.5e6, 2e3, 100e3, 0.0, 30.0), 2e3, 1e-12);
}

TEST(SrdAlmHamre, SeabedStressIsGuarded) {
    // sigma'_v0 = 0 at the mudline: the 1 kPa guard keeps every value finite.
    EXPECT_TRUE(std::isfinite(alm_hamre_sand_shaft_friction(2e6, 0.0, 28.0, 0.0, 5.0, 100e3)));
    EXPECT_TRUE(std::isfinite(alm_hamre_clay_shaft_friction(0.3e6, 5e3, 0.0, 0.0, 5.0)));
    expect_rel(alm_hamre_sand_end_bearing(2e6, 0.0), alm_hamre_sand_end_bearing(2e6, 1e3), 1e-12);
}

TEST(SrdAlmHamre, FrictionFatigueDecreasesWithPenetration) {
    double sand_prev = 1e300, clay_prev = 1e300;
    for (double p = 10.0; p <= 40.0; p += 1.0) {
        const double fs = alm_hamre_sand_shaft_friction(15e6, 100e3, 28.0, 10.0, p, 100e3);
        const double fc = alm_hamre_clay_shaft_friction(1.5e6, 0.2e6, 100e3, 10.0, p);
        EXPECT_LT(fs, sand_prev) << "p = " << p;
        EXPECT_LT(fc, clay_prev) << "p = " << p;
        sand_prev = fs;
        clay_prev = fc;
    }
    // The same through compute_srd: the friction at 5 m falls as the tip goes down.
    const SoilProfile soil = uniform_dense_sand();
    double prev = 1e300;
    for (double p = 6.0; p <= 30.0; p += 2.0) {
        const auto r = compute_srd(soil, SrdMethod::AlmHamre2001, {}, 2.0, 0.05, p, 0.5);
        EXPECT_LT(r.shaft_per_metre_at(5.0), prev) << "p = " << p;
        prev = r.shaft_per_metre_at(5.0);
    }
}

// ---- API RP2A sand limits, spec 3.1 ---------------------------------------------------

TEST(SrdApiSand, ExactAtTableRows) {
    const double rows[5][4] = {{15, 47.8e3, 8, 1.9e6},
                               {20, 67.0e3, 12, 2.9e6},
                               {25, 81.3e3, 20, 4.8e6},
                               {30, 95.7e3, 40, 9.6e6},
                               {35, 114.8e3, 50, 12.0e6}};
    for (const auto& row : rows) {
        const ApiSandLimits lim = api_sand_limits(row[0]);
        expect_rel(lim.limiting_friction, row[1], 1e-12);
        expect_rel(lim.bearing_factor, row[2], 1e-12);
        expect_rel(lim.limiting_bearing, row[3], 1e-12);
    }
}

TEST(SrdApiSand, LinearMidwayAndClampedOutside) {
    const ApiSandLimits mid = api_sand_limits(27.5);
    expect_rel(mid.limiting_friction, 88.5e3, 1e-12);
    expect_rel(mid.bearing_factor, 30.0, 1e-12);
    expect_rel(mid.limiting_bearing, 7.2e6, 1e-12);
    const ApiSandLimits q = api_sand_limits(16.25);  // a quarter of the first interval
    expect_rel(q.limiting_friction, 47.8e3 + 0.25 * 19.2e3, 1e-12);
    EXPECT_EQ(api_sand_limits(10.0).limiting_friction, 47.8e3);
    EXPECT_EQ(api_sand_limits(40.0).bearing_factor, 50.0);
    EXPECT_EQ(api_sand_limits(40.0).limiting_bearing, 12.0e6);
}

// ---- Soil profile ---------------------------------------------------------------------

TEST(SoilProfile, BaldiTestVectors) {
    expect_rel(baldi_cone_resistance(0.4, 100e3), 5183.0 * kKpa);
    expect_rel(baldi_cone_resistance(0.6, 100e3), 8392.0 * kKpa);
    expect_rel(baldi_cone_resistance(0.8, 100e3), 13590.0 * kKpa);
}

TEST(SoilProfile, TwoLayerEffectiveStressByHand) {
    SoilProfile s;
    s.layers = {sand(0.0, 5.0, 9e3, 0.5, 28.0), sand(5.0, 20.0, 10.5e3, 0.8, 30.0)};
    EXPECT_EQ(s.vertical_effective_stress(0.0), 0.0);
    expect_rel(s.vertical_effective_stress(3.0), 3.0 * 9e3, 1e-12);
    expect_rel(s.vertical_effective_stress(5.0), 5.0 * 9e3, 1e-12);
    expect_rel(s.vertical_effective_stress(12.0), 45e3 + 7.0 * 10.5e3, 1e-12);
    // Below the last layer it extends downward.
    expect_rel(s.vertical_effective_stress(26.0), 45e3 + 21.0 * 10.5e3, 1e-12);
    EXPECT_EQ(s.layer_at(4.999).relative_density, 0.5);
    EXPECT_EQ(s.layer_at(5.0).relative_density, 0.8);  // [top, bottom)
    EXPECT_EQ(s.layer_at(100.0).relative_density, 0.8);
    // No CPT: Baldi with the stress of that depth.
    expect_rel(s.cone_resistance(12.0), baldi_cone_resistance(0.8, 118.5e3), 1e-12);
    EXPECT_EQ(s.sleeve_friction(12.0), 0.0);
}

TEST(SoilProfile, RejectsEmptyAndNonContiguousLayers) {
    SoilProfile s;
    EXPECT_THROW(s.layer_at(1.0), std::invalid_argument);
    EXPECT_THROW(s.vertical_effective_stress(1.0), std::invalid_argument);
    s.layers = {sand(0.0, 5.0, 9e3, 0.5, 28.0), sand(6.5, 20.0, 10e3, 0.8, 30.0)};
    try {
        s.vertical_effective_stress(10.0);
        FAIL() << "a gap between layers must throw";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("5 m"), std::string::npos) << e.what();
    }
    s.layers = {sand(1.0, 5.0, 9e3, 0.5, 28.0)};  // not from the mudline
    EXPECT_THROW(s.layer_at(2.0), std::invalid_argument);
}

TEST(SoilProfile, CptRecordThenBaldiBelowIt) {
    SoilProfile s;
    s.layers = {sand(0.0, 30.0, 10e3, 0.6, 28.0)};
    s.cpt.depth = {0.0, 2.0, 6.0};
    s.cpt.qt = {1e6, 5e6, 9e6};
    s.cpt.fs = {10e3, 30e3, 50e3};
    EXPECT_TRUE(s.has_cpt_at(0.0));
    EXPECT_TRUE(s.has_cpt_at(6.0));
    EXPECT_FALSE(s.has_cpt_at(6.01));
    expect_rel(s.cone_resistance(1.0), 3e6, 1e-12);
    expect_rel(s.cone_resistance(4.0), 7e6, 1e-12);
    expect_rel(s.cone_resistance(6.0), 9e6, 1e-12);
    expect_rel(s.sleeve_friction(5.0), 45e3, 1e-12);
    expect_rel(s.cone_resistance(8.0), baldi_cone_resistance(0.6, 80e3), 1e-12);
    EXPECT_EQ(s.sleeve_friction(8.0), 0.0);
}

TEST(SoilProfile, ClayCorrelationsWithoutCpt) {
    const SoilProfile s = sand_over_clay();
    const double z = 12.0;
    const double su = 60e3 + 4.0 * 2e3;
    const double sigma_eff = 8.0 * 10e3 + 4.0 * 8e3;
    expect_rel(s.undrained_shear_strength(z), su, 1e-12);
    expect_rel(s.vertical_effective_stress(z), sigma_eff, 1e-12);
    // Total stress: effective plus hydrostatic sea water from the sea surface.
    const double u0 = 1025.0 * 9.81 * (30.0 + z);
    expect_rel(s.cone_resistance(z), 15.0 * su + sigma_eff + u0, 1e-12);
    expect_rel(s.sleeve_friction(z), su / 2.5, 1e-12);
}

// ---- compute_srd ----------------------------------------------------------------------

TEST(SrdCompute, MethodNames) {
    EXPECT_STREQ(srd_method_name(SrdMethod::AlmHamre2001), "alm_hamre_2001");
    EXPECT_STREQ(srd_method_name(SrdMethod::StevensLowerBound), "stevens_lower_bound");
    EXPECT_STREQ(srd_method_name(SrdMethod::StevensUpperBound), "stevens_upper_bound");
}

TEST(SrdCompute, SamplesAtMostSpacingApartWithDoubleSamplesAtBoundaries) {
    const SoilProfile soil = sand_over_clay();
    const auto r = compute_srd(soil, SrdMethod::AlmHamre2001, {}, 2.0, 0.05, 20.0, 0.7);
    ASSERT_EQ(r.depth.size(), r.shaft.size());
    EXPECT_EQ(r.penetration, 20.0);
    EXPECT_EQ(r.depth.front(), 0.0);
    EXPECT_EQ(r.depth.back(), 20.0);
    int at_boundary = 0;
    for (std::size_t i = 0; i < r.depth.size(); ++i) {
        if (r.depth[i] == 8.0) ++at_boundary;
        if (i > 0) {
            EXPECT_GE(r.depth[i], r.depth[i - 1]);
            EXPECT_LE(r.depth[i] - r.depth[i - 1], 0.7 + 1e-12);
        }
    }
    ASSERT_EQ(at_boundary, 2);
    // Sand above, clay below: the two values at 8 m differ.
    const auto it = std::find(r.depth.begin(), r.depth.end(), 8.0);
    const std::size_t i = static_cast<std::size_t>(it - r.depth.begin());
    EXPECT_GT(std::abs(r.shaft[i] - r.shaft[i + 1]), 0.1 * r.shaft[i]);
}

TEST(SrdCompute, ShaftMatchesFineNumericalIntegration) {
    const SoilProfile soil = sand_over_clay();
    const SrdCoefficients k;
    const double d_outer = 2.0, wall = 0.05, p = 20.0;
    SrdDetails det;
    const auto r = compute_srd(soil, SrdMethod::AlmHamre2001, k, d_outer, wall, p, 0.5, 1.0, &det);
    const double reference =
        reference_alm_hamre_shaft(soil, k, d_outer, d_outer - 2 * wall, p, 40000);
    EXPECT_NEAR(r.shaft_total(), reference, 0.005 * reference);
    expect_rel(det.shaft_outside + det.shaft_inside, r.shaft_total(), 1e-12);
    EXPECT_FALSE(det.plugged);
    // Toe: clay end bearing at the tip on the steel annulus.
    const double annulus = kPi * (d_outer * d_outer - 1.9 * 1.9) / 4.0;
    expect_rel(r.toe, alm_hamre_clay_end_bearing(soil.cone_resistance(p)) * annulus, 1e-12);
    expect_rel(det.toe, r.toe, 1e-12);
}

TEST(SrdCompute, SandEndBearingUsesTipValues) {
    const SoilProfile soil = uniform_dense_sand();
    const double p = 15.0, annulus = kPi * (2.0 * 2.0 - 1.9 * 1.9) / 4.0;
    const auto r = compute_srd(soil, SrdMethod::AlmHamre2001, {}, 2.0, 0.05, p, 0.5);
    const double q =
        alm_hamre_sand_end_bearing(soil.cone_resistance(p), soil.vertical_effective_stress(p));
    expect_rel(r.toe, q * annulus, 1e-12);
}

TEST(SrdCompute, TotalGrowsWithPenetrationInDenseSand) {
    const SoilProfile soil = uniform_dense_sand();
    double prev = 0.0;
    for (double p = 1.0; p <= 40.0; p += 1.0) {
        const auto r = compute_srd(soil, SrdMethod::AlmHamre2001, {}, 2.0, 0.05, p, 0.5);
        EXPECT_GT(r.total(), prev) << "p = " << p;
        prev = r.total();
    }
}

TEST(SrdCompute, FactorScalesShaftToeAndDetails) {
    const SoilProfile soil = sand_over_clay();
    SrdDetails d1, d2;
    const auto r1 =
        compute_srd(soil, SrdMethod::StevensUpperBound, {}, 2.0, 0.05, 15.0, 0.5, 1.0, &d1);
    const auto r2 =
        compute_srd(soil, SrdMethod::StevensUpperBound, {}, 2.0, 0.05, 15.0, 0.5, 1.25, &d2);
    expect_rel(r2.shaft_total(), 1.25 * r1.shaft_total(), 1e-12);
    expect_rel(r2.toe, 1.25 * r1.toe, 1e-12);
    expect_rel(d2.shaft_outside, 1.25 * d1.shaft_outside, 1e-12);
}

TEST(SrdCompute, TipOnBoundaryShaftFromUpperLayerToeFromLower) {
    const SoilProfile soil = sand_over_clay();
    const SrdCoefficients k;
    SrdDetails det;
    const auto r =
        compute_srd(soil, SrdMethod::StevensLowerBound, k, 1.0, 0.025, 8.0, 0.5, 1.0, &det);
    const double f_sand = k.stevens_k_lower * 80e3 * std::tan(28.0 * kPi / 180.0);
    const double perimeter = kPi * (1.0 + (det.plugged ? 0.0 : 0.95));
    expect_rel(r.shaft.back(), f_sand * perimeter, 1e-12);
    const double area = det.plugged ? kPi / 4.0 : kPi * (1.0 - 0.95 * 0.95) / 4.0;
    expect_rel(r.toe, 9.0 * 60e3 * area, 1e-12);
}

TEST(SrdCompute, RejectsBadInputs) {
    const SoilProfile soil = uniform_dense_sand();
    EXPECT_THROW(compute_srd(soil, SrdMethod::AlmHamre2001, {}, 2.0, 0.05, 10.0, 0.0),
                 std::invalid_argument);
    EXPECT_THROW(compute_srd(soil, SrdMethod::AlmHamre2001, {}, 2.0, 1.5, 10.0, 0.5),
                 std::invalid_argument);
    EXPECT_THROW(compute_srd(soil, SrdMethod::AlmHamre2001, {}, 2.0, 0.05, -1.0, 0.5),
                 std::invalid_argument);
    EXPECT_THROW(compute_srd(SoilProfile{}, SrdMethod::AlmHamre2001, {}, 2.0, 0.05, 10.0, 0.5),
                 std::invalid_argument);
}

// ---- Stevens et al. (1982), spec 2 ------------------------------------------------------

TEST(SrdStevens, SandFrictionFollowsApiTableAndCap) {
    // With K = 0.8 the spec 3.3 vectors apply: 46.19 kPa at 100 kPa, capped 95.7 at 250 kPa.
    SoilProfile soil;
    soil.layers = {sand(0.0, 40.0, 10e3, 0.8, 30.0)};
    SrdCoefficients k;
    k.stevens_k_lower = 0.8;
    SrdDetails det;
    const auto r =
        compute_srd(soil, SrdMethod::StevensLowerBound, k, 1.0, 0.025, 30.0, 0.5, 1.0, &det);
    const double perimeter = kPi * (1.0 + (det.plugged ? 0.0 : 0.95));
    expect_rel(r.shaft_per_metre_at(10.0) / perimeter, 46.19e3);
    expect_rel(r.shaft_per_metre_at(25.0) / perimeter, 95.7e3, 1e-12);
    const double area = det.plugged ? kPi / 4.0 : kPi * (1.0 - 0.95 * 0.95) / 4.0;
    expect_rel(r.toe, std::min(40.0 * 300e3, 9.6e6) * area, 1e-12);
}

TEST(SrdStevens, ClayBoundsRemouldedAndIntact) {
    SoilProfile soil;
    soil.layers = {clay(0.0, 30.0, 8e3, 50e3, 0.0, 2.5)};
    SrdDetails lo, up;
    const auto rl =
        compute_srd(soil, SrdMethod::StevensLowerBound, {}, 1.0, 0.025, 2.0, 0.25, 1.0, &lo);
    const auto ru =
        compute_srd(soil, SrdMethod::StevensUpperBound, {}, 1.0, 0.025, 2.0, 0.25, 1.0, &up);
    // A 2 m pile: the inside friction stays below 9 s_u on the plug, both bounds core.
    ASSERT_FALSE(lo.plugged);
    ASSERT_FALSE(up.plugged);
    const double perimeter = kPi * 1.95, annulus = kPi * (1.0 - 0.95 * 0.95) / 4.0;
    expect_rel(rl.shaft_per_metre_at(1.0), 20e3 * perimeter, 1e-12);
    expect_rel(ru.shaft_per_metre_at(1.0), 50e3 * perimeter, 1e-12);
    expect_rel(rl.toe, 9.0 * 50e3 * annulus, 1e-12);
    expect_rel(ru.toe, rl.toe, 1e-12);
}

TEST(SrdStevens, ShortPileCoresLongPilePlugs) {
    SoilProfile soil;
    soil.layers = {sand(0.0, 60.0, 10e3, 0.6, 25.0)};
    const double d_outer = 1.0, d_inner = 0.95;
    const double plug_area = kPi * d_inner * d_inner / 4.0;
    const double annulus = kPi * (d_outer * d_outer - d_inner * d_inner) / 4.0;

    SrdDetails shortp;
    const auto rs =
        compute_srd(soil, SrdMethod::StevensLowerBound, {}, d_outer, 0.025, 5.0, 0.5, 1.0, &shortp);
    EXPECT_FALSE(shortp.plugged);
    const double q_short = rs.toe / annulus;
    EXPECT_LT(shortp.shaft_inside, q_short * plug_area);
    expect_rel(shortp.shaft_inside, shortp.shaft_outside * d_inner / d_outer, 1e-12);

    SrdDetails longp;
    const auto rl =
        compute_srd(soil, SrdMethod::StevensLowerBound, {}, d_outer, 0.025, 40.0, 0.5, 1.0, &longp);
    EXPECT_TRUE(longp.plugged);
    EXPECT_EQ(longp.shaft_inside, 0.0);
    const double q_long = rl.toe / (plug_area + annulus);
    const double inside_if_coring = longp.shaft_outside * d_inner / d_outer;
    EXPECT_GT(inside_if_coring, q_long * plug_area);
    // The plugged total is the smaller one.
    const double coring_total = longp.shaft_outside + inside_if_coring + q_long * annulus;
    EXPECT_LT(rl.total(), coring_total);
    expect_rel(rl.shaft_total(), longp.shaft_outside, 1e-12);
}

// ---- Lehane et al. (2020), the "unified" CPT method ------------------------------------

// The worked example of OpenSees' TzSandCPT / QbSandCPT documentation (Gulf of Mexico
// site A, checked there against the UWA online calculator): q_c = 39 928 kPa,
// sigma'_v = 203.8 kPa, D = 2.44 m, t = 44.5 mm, h = 40 m: tau_f = 84.3 kPa in
// compression; q_p = 50 MPa: q_b0.1 = 7.629 MPa.
TEST(SrdUnified, PublishedWorkedExample) {
    const double d = 2.44, di = 2.44 - 2 * 0.0445, dcpt = 0.0357;
    const double are = unified_effective_area_ratio(d, di, dcpt);
    expect_rel(are, 0.08577, 1e-3);
    expect_rel(unified_sand_shaft_friction(39928 * kKpa, 203.8 * kKpa, 29.0, 40.0, d, are, dcpt), 84.3 * kKpa, 1e-3);
    expect_rel(unified_sand_base(50e6, are), 7.629e6, 1e-3);
    // Closed-ended: A_re = 1 (no inner diameter).
    EXPECT_DOUBLE_EQ(unified_effective_area_ratio(d, 0.0, dcpt), 1.0);
    // Clay: 0.07 q_t max(1, h/D*)^-0.25, D* = sqrt(D^2 - D_i^2).
    const double dstar = std::sqrt(d * d - di * di);
    expect_rel(unified_clay_shaft_friction(2e6, 10 * dstar, d, di, 1.0), 0.07 * 2e6 * std::pow(10.0, -0.25), 1e-12);
    expect_rel(unified_clay_shaft_friction(2e6, 0.5 * dstar, d, di, 0.5), 0.5 * 0.07 * 2e6, 1e-12);
}

namespace {

// Uniform sand with a CPT of constant q_c over 0..40 m.
SoilProfile uniform_cpt_sand(double qc) {
    SoilProfile s = uniform_dense_sand();
    s.cpt.depth = {0.0, 40.0};
    s.cpt.qt = {qc, qc};
    s.cpt.fs = {0.1e6, 0.1e6};
    return s;
}

}  // namespace

TEST(SrdUnified, ToeAverageOfAStepIsItsMean) {
    SoilProfile s = uniform_dense_sand();
    s.cpt.depth = {0.0, 10.0, 10.0 + 1e-6, 40.0};
    s.cpt.qt = {10e6, 10e6, 30e6, 30e6};
    s.cpt.fs = {0.1e6, 0.1e6, 0.1e6, 0.1e6};
    // +- 1.5 D of a 2 m pile about the step: half at 10 MPa, half at 30 MPa.
    expect_rel(average_cone_resistance(s, 10.0, 3.0), 20e6, 2e-3);
    // Clipped at the mudline: 0..4 m, all 10 MPa.
    expect_rel(average_cone_resistance(s, 1.0, 3.0), 10e6, 1e-9);
}

TEST(SrdUnified, CoringOrPluggedWhicheverResistsLess) {
    const double qc = 30e6, d = 2.48, wall = 0.055, di = d - 2 * wall;
    const SoilProfile s = uniform_cpt_sand(qc);
    const double annulus = kPi / 4 * (d * d - di * di), gross = kPi / 4 * d * d;
    const double are = unified_effective_area_ratio(d, di, 0.0357);
    // No inner friction: coring (annulus x q_c = 0.419 m^2 q_c) resists less than the plug
    // ((0.12 + 0.38 A_re) q_c over 4.83 m^2 = 0.75 m^2 q_c).
    SrdCoefficients k;
    k.unified_inside_share = 0.0;
    SrdDetails a;
    const auto coring = compute_srd(s, SrdMethod::Unified2020, k, d, wall, 20.0, 0.1, 1.0, &a);
    EXPECT_FALSE(a.plugged);
    expect_rel(coring.toe, annulus * qc, 1e-9);
    EXPECT_DOUBLE_EQ(a.shaft_inside, 0.0);
    // Inner friction as large as the outer: the plugged base governs.
    k.unified_inside_share = 1.0;
    SrdDetails b;
    const auto plugged = compute_srd(s, SrdMethod::Unified2020, k, d, wall, 20.0, 0.1, 1.0, &b);
    EXPECT_TRUE(b.plugged);
    expect_rel(plugged.toe, (0.12 + 0.38 * are) * qc * gross, 1e-9);
    expect_rel(b.shaft_outside, a.shaft_outside, 1e-12);
    EXPECT_LT(b.toe, a.toe + b.shaft_outside * di / d);  // it was the smaller mode
    EXPECT_STREQ(srd_method_name(SrdMethod::Unified2020), "unified_2020");
}
