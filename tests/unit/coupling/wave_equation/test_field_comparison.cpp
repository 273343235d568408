// Comparison with field records: totals, profile correlation, the band, the statistics,
// and the fit of the reference energy, against hand values and closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/wave_equation/field_comparison.hpp"

using namespace pilempm::coupling;

TEST(FieldComparison, PearsonOfKnownSeries) {
    EXPECT_NEAR(pearson_correlation({1, 2, 3, 4}, {2, 4, 6, 8}), 1.0, 1e-12);
    EXPECT_NEAR(pearson_correlation({1, 2, 3, 4}, {8, 6, 4, 2}), -1.0, 1e-12);
    // x = 1..5, y = 2, 1, 4, 3, 5: r = 8 / sqrt(10 * 10) = 0.8
    EXPECT_NEAR(pearson_correlation({1, 2, 3, 4, 5}, {2, 1, 4, 3, 5}), 0.8, 1e-12);
    EXPECT_TRUE(std::isnan(pearson_correlation({1, 1, 1}, {1, 2, 3})));
}

TEST(FieldComparison, TotalsRatioAndBand) {
    MeasuredDriving m;
    m.depth = {4.0, 4.5, 5.0, 5.5};
    m.blows_per_m = {10, 20, 30, 40};
    m.cumulative_blows = {100, 107.5, 120, 137.5};  // the trapezoid of the blows: 37.5 more
    PredictedDriving p;
    p.depth = {4.0, 4.5, 5.0, 5.5};
    p.blows_per_m = {20, 40, 60, 80};
    const Comparison c = compare_driving(p, m);
    EXPECT_NEAR(c.measured_total, 37.5, 1e-12);
    EXPECT_NEAR(c.predicted_total, 75.0, 1e-12);
    EXPECT_NEAR(c.ratio, 2.0, 1e-12);
    EXPECT_NEAR(c.abs_log_ratio, std::log(2.0), 1e-12);
    EXPECT_NEAR(c.profile_correlation, 1.0, 1e-12);
    PredictedDriving low = p;
    low.blows_per_m = {5, 25, 25, 45};
    // 10 in [5, 20] and 30 in [25, 60]; 20 below [25, 40] and 40 below [45, 80]: 2 of 4
    EXPECT_NEAR(share_inside_band(low, p, m), 0.5, 1e-12);
}

TEST(FieldComparison, StatisticsMedianAndFactor) {
    std::vector<Comparison> c(4);
    const double ratios[] = {1.2, 0.5, 2.0, 1.4};
    const double r[] = {0.9, 0.5, 0.7, 0.8};
    for (int i = 0; i < 4; ++i) {
        c[i].ratio = ratios[i];
        c[i].abs_log_ratio = std::abs(std::log(ratios[i]));
        c[i].profile_correlation = r[i];
    }
    const StudyStatistics s = study_statistics(c);
    EXPECT_EQ(s.locations, 4);
    EXPECT_NEAR(s.median_abs_log_ratio, 0.5 * (std::log(1.4) + std::log(2.0)), 1e-12);
    EXPECT_NEAR(s.share_within_factor_1_5, 0.5, 1e-12);
    EXPECT_NEAR(s.median_profile_correlation, 0.75, 1e-12);
}

TEST(FieldComparison, ReferenceEnergyFitInvertsADecreasingLaw) {
    // blows = k / E: the fit must give E = k / measured to 0.1 %.
    const double k = 3.0e9;
    auto blows = [k](double e) { return k / e; };
    EXPECT_NEAR(fit_reference_energy(blows, 2500.0, 0.3e6, 4.0e6), k / 2500.0, 1e-3 * k / 2500.0);
    // A curved law, blows = 800 + (1 MJ / E)^2 x 1000: 1800 blows at E = 1 MJ.
    int calls = 0;
    auto curved = [&calls](double e) {
        ++calls;
        return 800.0 + 1000.0 * (1e6 / e) * (1e6 / e);
    };
    EXPECT_NEAR(fit_reference_energy(curved, 1800.0, 0.3e6, 4.0e6), 1e6, 1e-3 * 1e6);
    EXPECT_LT(calls, 20);
    // Outside the bracket: its end.
    EXPECT_DOUBLE_EQ(fit_reference_energy(blows, 1.0, 0.3e6, 4.0e6), 4.0e6);
    EXPECT_DOUBLE_EQ(fit_reference_energy(blows, 1e6, 0.3e6, 4.0e6), 0.3e6);
}
