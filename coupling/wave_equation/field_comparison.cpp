#include "coupling/wave_equation/field_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace pilempm::coupling {

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

int column_of(const Table& t, const std::string& name) {
    for (std::size_t c = 0; c < t.columns.size(); ++c)
        if (t.columns[c] == name) return static_cast<int>(c);
    throw std::invalid_argument("table " + t.name + " has no column " + name);
}

// p's blows per metre at depth z (linear between its depths, NaN outside them).
double at_depth(const PredictedDriving& p, double z) {
    if (p.depth.empty() || z < p.depth.front() - 1e-9 || z > p.depth.back() + 1e-9) return kNaN;
    const auto it = std::lower_bound(p.depth.begin(), p.depth.end(), z - 1e-9);
    const std::size_t i = static_cast<std::size_t>(it - p.depth.begin());
    if (std::abs(p.depth[i] - z) <= 1e-9 || i == 0) return p.blows_per_m[i];
    const double w = (z - p.depth[i - 1]) / (p.depth[i] - p.depth[i - 1]);
    return (1.0 - w) * p.blows_per_m[i - 1] + w * p.blows_per_m[i];
}

}  // namespace

double MeasuredDriving::total_blows() const {
    if (cumulative_blows.size() < 2) return 0.0;
    return cumulative_blows.back() - cumulative_blows.front();
}

MeasuredDriving MeasuredDriving::between(double top, double bottom) const {
    MeasuredDriving m;
    for (std::size_t i = 0; i < depth.size(); ++i)
        if (depth[i] >= top - 1e-9 && depth[i] <= bottom + 1e-9) {
            m.depth.push_back(depth[i]);
            m.blows_per_m.push_back(blows_per_m[i]);
            m.cumulative_blows.push_back(cumulative_blows[i]);
        }
    return m;
}

PredictedDriving predicted_from_table(const Table& t) {
    const auto& z = t.data[static_cast<std::size_t>(column_of(t, "depth_m"))];
    const auto& b = t.data[static_cast<std::size_t>(column_of(t, "blows_per_0.25m"))];
    PredictedDriving p;
    p.depth = z;
    for (double x : b) p.blows_per_m.push_back(4.0 * x);
    return p;
}

Comparison compare_driving(const PredictedDriving& p, const MeasuredDriving& m) {
    Comparison c;
    c.measured_total = m.total_blows();
    std::vector<double> pred, meas;
    for (std::size_t i = 0; i < m.depth.size(); ++i) {
        pred.push_back(at_depth(p, m.depth[i]));
        meas.push_back(m.blows_per_m[i]);
        if (i > 0) c.predicted_total += 0.5 * (pred[i] + pred[i - 1]) * (m.depth[i] - m.depth[i - 1]);
    }
    c.ratio = c.measured_total > 0.0 ? c.predicted_total / c.measured_total : kNaN;
    c.abs_log_ratio = c.ratio > 0.0 ? std::abs(std::log(c.ratio)) : kNaN;
    c.profile_correlation = pearson_correlation(pred, meas);
    return c;
}

double share_inside_band(const PredictedDriving& a, const PredictedDriving& b, const MeasuredDriving& m) {
    if (m.depth.empty()) return kNaN;
    int inside = 0;
    for (std::size_t i = 0; i < m.depth.size(); ++i) {
        const double x = at_depth(a, m.depth[i]), y = at_depth(b, m.depth[i]);
        if (m.blows_per_m[i] >= std::min(x, y) && m.blows_per_m[i] <= std::max(x, y)) ++inside;
    }
    return static_cast<double>(inside) / static_cast<double>(m.depth.size());
}

double pearson_correlation(const std::vector<double>& x, const std::vector<double>& y) {
    if (x.size() != y.size() || x.size() < 2) return kNaN;
    double mx = 0.0, my = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        mx += x[i];
        my += y[i];
    }
    mx /= static_cast<double>(x.size());
    my /= static_cast<double>(y.size());
    double sxy = 0.0, sxx = 0.0, syy = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sxy += (x[i] - mx) * (y[i] - my);
        sxx += (x[i] - mx) * (x[i] - mx);
        syy += (y[i] - my) * (y[i] - my);
    }
    return sxx > 0.0 && syy > 0.0 ? sxy / std::sqrt(sxx * syy) : kNaN;
}

double median(std::vector<double> v) {
    v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
    if (v.empty()) return kNaN;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

StudyStatistics study_statistics(const std::vector<Comparison>& c) {
    StudyStatistics s;
    s.locations = static_cast<int>(c.size());
    std::vector<double> logs, r;
    int within = 0;
    for (const auto& k : c) {
        logs.push_back(k.abs_log_ratio);
        r.push_back(k.profile_correlation);
        if (k.abs_log_ratio <= std::log(1.5)) ++within;
    }
    s.median_abs_log_ratio = median(logs);
    s.median_profile_correlation = median(r);
    s.share_within_factor_1_5 = c.empty() ? kNaN : static_cast<double>(within) / static_cast<double>(c.size());
    return s;
}

double fit_reference_energy(const std::function<double(double)>& total_blows, double measured, double low,
                            double high) {
    if (!(low > 0.0 && high > low)) throw std::invalid_argument("fit_reference_energy: need 0 < low < high");
    // More energy, fewer blows: the match is bracketed when blows(low) >= measured >= blows(high).
    if (total_blows(high) >= measured) return high;
    if (total_blows(low) <= measured) return low;
    // Illinois (modified regula falsi) on ln blows against ln E, which is close to a line:
    // a few runs of the location instead of the dozen bisection needs.
    double a = std::log(low), b = std::log(high);
    double fa = std::log(total_blows(low) / measured), fb = std::log(total_blows(high) / measured);
    int side = 0;
    for (int it = 0; it < 60 && b - a > 1e-3; ++it) {
        const double x = (a * fb - b * fa) / (fb - fa);
        const double fx = std::log(total_blows(std::exp(x)) / measured);
        if (std::abs(fx) < 1e-4) return std::exp(x);
        if (fx > 0.0) {  // too many blows: the energy is higher
            a = x, fa = fx;
            if (side == 1) fb *= 0.5;
            side = 1;
        } else {
            b = x, fb = fx;
            if (side == -1) fa *= 0.5;
            side = -1;
        }
    }
    return std::exp(0.5 * (a + b));
}

}  // namespace pilempm::coupling
