#pragma once
// A drivability prediction against a measured driving record: total blows over the driven
// range, the correlation of the blows-per-metre profiles, whether the record lies inside
// the band of two soil cases; the statistics over many locations; and the fit of one
// unknown (the hammer's reference energy) on one location.
#include <functional>
#include <string>
#include <vector>

#include "core/table.hpp"

namespace pilempm::coupling {

// The measured record at the depths driven (blow count recorded), depth increasing.
struct MeasuredDriving {
    std::vector<double> depth, blows_per_m, cumulative_blows;
    double total_blows() const;  // cumulative between the first and last driven depth
    // The record between two depths (both included).
    MeasuredDriving between(double top, double bottom) const;
};

// A predicted blows-per-metre profile at the measured depths (from a drivability table).
struct PredictedDriving {
    std::vector<double> depth, blows_per_m;
};
PredictedDriving predicted_from_table(const Table& drivability_run);  // blows per 0.25 m x 4

struct Comparison {
    double predicted_total = 0.0, measured_total = 0.0;
    double ratio = 0.0;                 // predicted / measured
    double abs_log_ratio = 0.0;         // |ln(predicted / measured)|
    double profile_correlation = 0.0;   // Pearson r of blows per metre at the measured depths
};

// Predicted and measured blows over the same driven range, both by the trapezoidal rule
// for the prediction and by the record's own cumulative count for the measurement.
Comparison compare_driving(const PredictedDriving& p, const MeasuredDriving& m);

// Share of measured depths whose blows per metre lie between two predictions.
double share_inside_band(const PredictedDriving& a, const PredictedDriving& b, const MeasuredDriving& m);

double pearson_correlation(const std::vector<double>& x, const std::vector<double>& y);
double median(std::vector<double> v);

struct StudyStatistics {
    int locations = 0;
    double median_abs_log_ratio = 0.0;
    double share_within_factor_1_5 = 0.0;
    double median_profile_correlation = 0.0;
};
StudyStatistics study_statistics(const std::vector<Comparison>& c);

// The reference energy in [low, high] at which `total_blows(E)` (decreasing in E) equals
// `measured` (ln blows matched to 1e-4, or E to 0.1 %); a bracket end when the match lies
// outside the bracket.
double fit_reference_energy(const std::function<double(double)>& total_blows, double measured, double low,
                            double high);

}  // namespace pilempm::coupling
