#include "coupling/wave_equation/fast_path_calibration.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <stdexcept>

#include "core/optimisation/nelder_mead.hpp"

namespace pilempm::coupling {

const char* calibration_parameter_name(CalibrationParameter p) {
    switch (p) {
        case CalibrationParameter::SrdFactor: return "srd_factor";
        case CalibrationParameter::ShaftQuake: return "shaft_quake";
        case CalibrationParameter::ToeQuake: return "toe_quake";
        case CalibrationParameter::ShaftDamping: return "shaft_damping";
        case CalibrationParameter::ToeDamping: return "toe_damping";
    }
    return "?";
}

std::vector<CalibrationParameter> all_calibration_parameters() {
    return {CalibrationParameter::SrdFactor, CalibrationParameter::ShaftQuake, CalibrationParameter::ToeQuake,
            CalibrationParameter::ShaftDamping, CalibrationParameter::ToeDamping};
}

double FastPathSoil::value(CalibrationParameter p) const {
    switch (p) {
        case CalibrationParameter::SrdFactor: return srd_factor;
        case CalibrationParameter::ShaftQuake: return smith.shaft_quake;
        case CalibrationParameter::ToeQuake: return smith.toe_quake;
        case CalibrationParameter::ShaftDamping:
            return smith.law == DampingLaw::Case ? smith.shaft_damping : sand_shaft_damping;
        case CalibrationParameter::ToeDamping: return smith.toe_damping;
    }
    return 0.0;
}

FastPathSoil starting_soil(const DrivabilitySetup& s, const SoilCase& c) {
    return {c.factor, s.smith, s.sand_shaft_damping, s.clay_shaft_damping};
}

DrivabilitySetup with_soil(const DrivabilitySetup& s, const SoilCase& c, const FastPathSoil& soil,
                           const std::string& name) {
    DrivabilitySetup out = s;
    out.cases = {{name, c.method, soil.srd_factor}};
    out.smith = soil.smith;
    out.sand_shaft_damping = soil.sand_shaft_damping;
    out.clay_shaft_damping = soil.clay_shaft_damping;
    return out;
}

namespace {

// The soil with each fitted parameter `exp(x_i)` times its starting value.
FastPathSoil scaled(const FastPathSoil& start, const std::vector<CalibrationParameter>& fit,
                    const std::vector<double>& x) {
    FastPathSoil s = start;
    for (std::size_t i = 0; i < fit.size(); ++i) {
        const double f = std::exp(x[i]);
        switch (fit[i]) {
            case CalibrationParameter::SrdFactor: s.srd_factor *= f; break;
            case CalibrationParameter::ShaftQuake: s.smith.shaft_quake *= f; break;
            case CalibrationParameter::ToeQuake: s.smith.toe_quake *= f; break;
            case CalibrationParameter::ShaftDamping:
                s.smith.shaft_damping *= f, s.sand_shaft_damping *= f, s.clay_shaft_damping *= f;
                break;
            case CalibrationParameter::ToeDamping: s.smith.toe_damping *= f; break;
        }
    }
    return s;
}

// A record's value at time t, linear between its samples (its first and last beyond).
double sample(const std::vector<double>& time, const std::vector<double>& y, double t) {
    const auto it = std::lower_bound(time.begin(), time.end(), t);
    if (it == time.begin()) return y.front();
    if (it == time.end()) return y.back();
    const std::size_t k = static_cast<std::size_t>(it - time.begin());
    const double w = (t - time[k - 1]) / (time[k] - time[k - 1]);
    return y[k - 1] + w * (y[k] - y[k - 1]);
}

struct Evaluation {
    double set = 0.0, enthru = 0.0;
    HeadRecord record;
};

// The fast path at each target's depth with the soil: the steady set and its last blow.
std::vector<Evaluation> evaluate(const DrivabilitySetup& s, const SoilCase& c, const FastPathSoil& soil,
                                 const std::vector<CalibrationTarget>& targets) {
    const DrivabilitySetup setup = with_soil(s, c, soil, "calibrated");
    std::vector<Evaluation> out(targets.size());
    std::exception_ptr failure;
    const int n = static_cast<int>(targets.size());
#pragma omp parallel for schedule(dynamic, 1) num_threads(std::max(1, s.threads > 0 ? s.threads : n))
    for (int k = 0; k < n; ++k) {
        try {
            const auto srd = srd_for_driving(setup, setup.cases.front(), targets[k].depth);
            const PenetrationResult p = drive_at_penetration(setup.mesh, setup.steel, srd, setup.smith, setup.hammer,
                                                             setup.ram_element_size, setup.driving, &out[k].record);
            out[k].set = p.set;
            out[k].enthru = p.last.enthru;
        } catch (...) {
#pragma omp critical(pilempm_calibration_failure)
            if (!failure) failure = std::current_exception();
        }
    }
    if (failure) std::rethrow_exception(failure);
    return out;
}


}  // namespace

double target_misfit(const CalibrationTarget& t, double fast_set, const HeadRecord& fast, double window,
                     bool compares_force, double record_weight, double* record_misfit) {
    const double set_term = std::log(std::max(fast_set, 1e-6) / t.set);
    // Each record's relative mean square difference; the force's only where it answers
    // the soil (a prescribed pulse's force is the same in both models).
    double dv2 = 0.0, v2 = 0.0, df2 = 0.0, f2 = 0.0;
    const auto& r = t.record;
    for (std::size_t i = 0; i < r.time.size() && r.time[i] <= window; ++i) {
        const double dv = sample(fast.time, fast.velocity, r.time[i]) - r.velocity[i];
        const double df = sample(fast.time, fast.force, r.time[i]) - r.force[i];
        dv2 += dv * dv, v2 += r.velocity[i] * r.velocity[i];
        df2 += df * df, f2 += r.force[i] * r.force[i];
    }
    double rec = v2 > 0.0 ? dv2 / v2 : 0.0;
    if (compares_force) rec = 0.5 * (rec + (f2 > 0.0 ? df2 / f2 : 0.0));
    if (record_misfit) *record_misfit = std::sqrt(rec);
    return set_term * set_term + record_weight * rec;
}

CalibrationResult calibrate_fast_path(const DrivabilitySetup& s, const SoilCase& c,
                                      const std::vector<CalibrationTarget>& targets, const CalibrationOptions& o) {
    if (targets.empty()) throw std::invalid_argument("calibration: no coupled blows to fit");
    for (const auto& t : targets)
        if (!(t.set > 0.0) || t.record.time.empty())
            throw std::invalid_argument("calibration: " + t.source + ": a positive set and a head record expected");
    const auto start_clock = std::chrono::steady_clock::now();
    CalibrationResult r;
    r.fitted = o.fit;
    r.before = starting_soil(s, c);
    r.compares_force = s.hammer.kind == fem::HammerKind::RamCushion;
    const double round_trip = 2.0 * s.mesh.length() / s.steel.wave_speed();
    const double pulse = s.hammer.kind == fem::HammerKind::PrescribedForce ? s.hammer.force.end_time() : 0.0;
    r.record_window = o.record_window > 0.0 ? o.record_window : pulse + 2.0 * round_trip;

    auto objective = [&](const std::vector<Evaluation>& e) {
        double sum = 0.0;
        for (std::size_t k = 0; k < targets.size(); ++k)
            sum += target_misfit(targets[k], e[k].set, e[k].record, r.record_window, r.compares_force, o.record_weight);
        return sum / static_cast<double>(targets.size());
    };
    const double limit = std::log(o.bound);
    auto clamp = [&](std::vector<double> x) {
        for (double& v : x) v = std::clamp(v, -limit, limit);
        return x;
    };
    const auto before = evaluate(s, c, r.before, targets);
    r.objective_before = objective(before);
    NelderMeadResult best{std::vector<double>(o.fit.size(), 0.0), r.objective_before, 1, false};
    if (!o.fit.empty()) {
        auto f = [&](const std::vector<double>& x) {
            const std::vector<double> inside = clamp(x);
            double pull = 0.0;
            for (double v : inside) pull += v * v;
            return objective(evaluate(s, c, scaled(r.before, o.fit, inside), targets)) + o.regularisation * pull;
        };
        best = nelder_mead(f, best.x, std::vector<double>(o.fit.size(), std::log(1.5)),
                           {o.max_evaluations, 1e-6, 1e-3});
        best.x = clamp(best.x);
    }
    r.evaluations = best.evaluations + 1;
    r.converged = best.converged;
    r.after = scaled(r.before, o.fit, best.x);
    for (std::size_t i = 0; i < o.fit.size(); ++i)
        if (std::abs(best.x[i]) >= limit * (1.0 - 1e-9)) r.at_bound.push_back(o.fit[i]);
    const auto after = evaluate(s, c, r.after, targets);
    r.objective_after = best.value;
    for (std::size_t k = 0; k < targets.size(); ++k) {
        CalibrationPoint p;
        p.target = targets[k];
        p.fast_set_before = before[k].set;
        p.fast_set_after = after[k].set;
        p.fast_enthru_after = after[k].enthru;
        target_misfit(targets[k], before[k].set, before[k].record, r.record_window, r.compares_force, o.record_weight,
                      &p.record_misfit_before);
        target_misfit(targets[k], after[k].set, after[k].record, r.record_window, r.compares_force, o.record_weight,
                      &p.record_misfit_after);
        p.fast_before = before[k].record;
        p.fast_after = after[k].record;
        r.points.push_back(std::move(p));
    }
    r.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_clock).count();
    return r;
}

Table calibration_table(const CalibrationResult& r) {
    Table t("calibration", {"depth_m", "coupled_blows", "coupled_set_m", "coupled_blows_per_0.25m",
                            "coupled_enthru_J", "fast_set_before_m", "fast_set_after_m", "fast_blows_per_0.25m_after",
                            "fast_enthru_after_J", "record_misfit_before", "record_misfit_after"});
    for (const auto& p : r.points)
        t.add_row({p.target.depth, static_cast<double>(p.target.blows), p.target.set, 0.25 / p.target.set,
                   p.target.enthru, p.fast_set_before, p.fast_set_after,
                   p.fast_set_after > 0.0 ? 0.25 / p.fast_set_after : HUGE_VAL, p.fast_enthru_after,
                   p.record_misfit_before, p.record_misfit_after});
    return t;
}

Table calibration_records_table(const CalibrationResult& r) {
    Table t("calibration_records", {"depth_m", "time_s", "coupled_force_N", "coupled_velocity_m_s",
                                    "fast_before_force_N", "fast_before_velocity_m_s", "fast_after_force_N",
                                    "fast_after_velocity_m_s"});
    for (const auto& p : r.points) {
        const auto& c = p.target.record;
        const auto &b = p.fast_before, &a = p.fast_after;
        for (std::size_t i = 0; i < c.time.size() && c.time[i] <= r.record_window; ++i) {
            const double time = c.time[i];
            t.add_row({p.target.depth, time, c.force[i], c.velocity[i], sample(b.time, b.force, time),
                       sample(b.time, b.velocity, time), sample(a.time, a.force, time), sample(a.time, a.velocity, time)});
        }
    }
    return t;
}

}  // namespace pilempm::coupling
