#include "coupling/wave_equation/drivability.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace pilempm::coupling {

double self_weight_penetration(const SoilProfile& soil, SrdMethod method, const SrdCoefficients& k,
                               double factor, double d_outer, double wall, double weight,
                               double max_depth, double spacing) {
    auto srd = [&](double p) {
        return compute_srd(soil, method, k, d_outer, wall, p, spacing, factor).total();
    };
    if (srd(max_depth) <= weight) return max_depth;
    double lo = 0.0, hi = max_depth;
    for (int i = 0; i < 60 && hi - lo > 1e-4; ++i) {
        const double mid = 0.5 * (lo + hi);
        (srd(mid) <= weight ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

namespace {

double layer_shaft_damping(const DrivabilitySetup& s, const SoilLayer& l) {
    return l.type == SoilType::Sand ? s.sand_shaft_damping : s.clay_shaft_damping;
}

// Smith-viscous shaft damping by soil type (Case damping has one J_c and needs none). A
// sample's J serves the shaft between it and the sample above, so it is that stretch's
// layer, read at its middle: a sample on a boundary then keeps the layer above.
void assign_shaft_damping(const DrivabilitySetup& s, ResistanceDistribution& r) {
    if (s.smith.law != DampingLaw::SmithViscous) return;
    r.shaft_damping.resize(r.depth.size());
    for (std::size_t i = 0; i < r.depth.size(); ++i) {
        const double z = i == 0 ? r.depth[0] : 0.5 * (r.depth[i - 1] + r.depth[i]);
        r.shaft_damping[i] = layer_shaft_damping(s, s.soil.layer_at(z));
    }
}

}  // namespace

ResistanceDistribution srd_for_driving(const DrivabilitySetup& s, const SoilCase& c, double penetration) {
    ResistanceDistribution r = compute_srd(s.soil, c.method, s.coefficients, s.outer_diameter,
                                           s.wall_thickness, penetration, s.srd_spacing, c.factor);
    assign_shaft_damping(s, r);
    return r;
}

ResistanceDistribution bearing_graph_resistance(const DrivabilitySetup& s, double r_u) {
    ResistanceDistribution r;
    r.penetration = s.bearing_penetration > 0.0 ? s.bearing_penetration : s.final_depth;
    // Uniform shaft, sampled at the mudline, the tip and each boundary where the damping
    // changes, so every stretch of the shaft takes its own layer's J.
    r.depth = {0.0};
    const auto& layers = s.soil.layers;
    for (std::size_t i = 0; i + 1 < layers.size(); ++i) {
        const double b = layers[i].bottom;
        if (s.smith.law == DampingLaw::SmithViscous && b < r.penetration &&
            layer_shaft_damping(s, layers[i]) != layer_shaft_damping(s, layers[i + 1]))
            r.depth.push_back(b);
    }
    r.depth.push_back(r.penetration);
    r.shaft.assign(r.depth.size(), r_u * s.bearing_shaft_fraction / r.penetration);
    r.toe = r_u * (1.0 - s.bearing_shaft_fraction);
    assign_shaft_damping(s, r);
    return r;
}

double planned_energy_level(const DrivabilitySetup& s, double depth, double level) {
    const auto& z = s.energy_plan_depth;
    const auto& e = s.energy_plan_level;
    if (z.empty()) return level;
    if (z.size() != e.size()) throw std::invalid_argument("energy plan: depths and energies differ in number");
    if (depth <= z.front()) return level * e.front();
    if (depth >= z.back()) return level * e.back();
    const std::size_t i = static_cast<std::size_t>(std::upper_bound(z.begin(), z.end(), depth) - z.begin());
    const double w = (depth - z[i - 1]) / (z[i] - z[i - 1]);
    return level * ((1.0 - w) * e[i - 1] + w * e[i]);
}

fem::HammerSpec scaled_hammer(const fem::HammerSpec& h, double level) {
    fem::HammerSpec out = h;
    const double f = std::sqrt(level);
    if (h.kind == fem::HammerKind::RamCushion) out.ram_cushion.impact_velocity *= f;
    else {
        out.force.peak *= f;
        for (double& x : out.force.table_force) x *= f;
    }
    return out;
}

namespace {

struct Task {
    int run;           // index into the runs (case x energy)
    int point;         // depth index
};

Table drivability_table(const std::string& name) {
    return Table(name, {"depth_m", "srd_shaft_N", "srd_toe_N", "srd_total_N", "set_per_blow_m",
                        "blows_per_0.25m", "cumulative_blows", "max_compression_Pa", "max_tension_Pa",
                        "enthru_J", "peak_head_force_N", "blows_simulated", "steady", "refusal", "energy_level"});
}

// Cumulative blows by the trapezoidal rule in depth, and the run's summary figures.
void summarise(DrivabilityRun& run, const std::vector<PenetrationResult>& points,
               const std::vector<double>& levels, double refusal, double hard) {
    double cumulative = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const auto& p = points[i];
        if (i > 0) {
            const auto& q = points[i - 1];
            cumulative += 0.5 * (p.blows_per_quarter_metre + q.blows_per_quarter_metre) *
                          (p.penetration - q.penetration) / 0.25;
        }
        run.table.add_row({p.penetration, p.srd_shaft, p.srd_toe, p.srd_shaft + p.srd_toe, p.set,
                           p.blows_per_quarter_metre, cumulative, p.last.max_compression_stress,
                           p.last.max_tension_stress, p.last.enthru, p.last.peak_head_force,
                           static_cast<double>(p.blows), p.steady ? 1.0 : 0.0, p.refusal ? 1.0 : 0.0, levels[i]});
        if (run.refusal_depth < 0.0) {
            run.final_depth_reached = p.penetration;
            run.total_blows = cumulative;
            if (p.blows_per_quarter_metre > refusal) run.refusal_depth = p.penetration;
        }
        if (run.hard_driving_from < 0.0 && p.blows_per_quarter_metre > hard) run.hard_driving_from = p.penetration;
        if (p.last.max_compression_stress > run.max_compression) {
            run.max_compression = p.last.max_compression_stress;
            run.max_compression_depth = p.penetration;
        }
        if (p.last.max_tension_stress > run.max_tension) {
            run.max_tension = p.last.max_tension_stress;
            run.max_tension_depth = p.penetration;
        }
    }
}

std::string run_name(const std::string& soil_case, double level, bool several_levels) {
    std::string name = "drivability_" + soil_case;
    if (several_levels) name += "_E" + std::to_string(static_cast<int>(std::lround(level * 100)));
    return name;
}

}  // namespace

DrivabilityResult run_drivability(const DrivabilitySetup& s, const DrivabilityProgress& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    if (s.cases.empty() || s.energy_levels.empty()) throw std::invalid_argument("no soil case or energy level");
    DrivabilityResult result;
    const double g = 9.81;
    const double submerged = s.pile_mass * g * (1.0 - 1025.0 / s.steel.density);

    // Runs (soil case x energy level), each with its self-weight penetration and depths.
    std::vector<std::vector<double>> depths;
    for (const auto& c : s.cases) {
        const double swp = self_weight_penetration(s.soil, c.method, s.coefficients, c.factor,
                                                   s.outer_diameter, s.wall_thickness, submerged,
                                                   s.final_depth, s.srd_spacing);
        const double swp_hammer = self_weight_penetration(
            s.soil, c.method, s.coefficients, c.factor, s.outer_diameter, s.wall_thickness,
            submerged + s.hammer_weight, s.final_depth, s.srd_spacing);
        for (double level : s.energy_levels) {
            DrivabilityRun run;
            run.soil_case = c.name;
            run.energy_level = level;
            run.table = drivability_table(run_name(c.name, level, s.energy_levels.size() > 1));
            run.self_weight_penetration = swp;
            run.self_weight_penetration_with_hammer = swp_hammer;
            std::vector<double> d;
            const double start = s.start_depth >= 0.0 ? s.start_depth : swp;
            for (double z = start; z <= s.final_depth + 1e-9; z += s.depth_step) d.push_back(z);
            if (d.empty() || d.back() < s.final_depth - 1e-9) d.push_back(s.final_depth);
            depths.push_back(std::move(d));
            result.runs.push_back(std::move(run));
        }
    }
    std::vector<Task> tasks;
    std::vector<std::vector<PenetrationResult>> points(result.runs.size());
    std::vector<std::vector<double>> levels(result.runs.size());
    const int cases_per_level = static_cast<int>(s.energy_levels.size());
    for (std::size_t r = 0; r < result.runs.size(); ++r) {
        points[r].resize(depths[r].size());
        for (double z : depths[r]) levels[r].push_back(planned_energy_level(s, z, s.energy_levels[r % cases_per_level]));
        for (std::size_t i = 0; i < depths[r].size(); ++i) tasks.push_back({static_cast<int>(r), static_cast<int>(i)});
    }
    long done = 0;
    const long total = static_cast<long>(tasks.size());
    if (s.threads > 0) omp_set_num_threads(s.threads);
    std::exception_ptr failure;
#pragma omp parallel for schedule(dynamic, 1)
    for (long t = 0; t < total; ++t) {
        try {
            const Task task = tasks[t];
            const SoilCase& c = s.cases[task.run / cases_per_level];
            const double level = levels[task.run][task.point];
            const double depth = depths[task.run][task.point];
            const auto srd = srd_for_driving(s, c, depth);
            points[task.run][task.point] = drive_at_penetration(
                s.mesh, s.steel, srd, s.smith, scaled_hammer(s.hammer, level), s.ram_element_size, s.driving);
        } catch (...) {
#pragma omp critical(pilempm_failure)
            if (!failure) failure = std::current_exception();
        }
#pragma omp critical(pilempm_progress)
        {
            ++done;
            if (progress) progress(done, total);
        }
    }
    if (failure) std::rethrow_exception(failure);

    for (std::size_t r = 0; r < result.runs.size(); ++r) {
        summarise(result.runs[r], points[r], levels[r], s.driving.refusal_blow_count, s.hard_driving_blow_count);
        for (const auto& p : points[r]) result.blows_simulated += p.blows;
    }
    result.depth_points = total;

    if (!s.bearing_resistances.empty()) {
        Table bg("bearing_graph", {"energy_level", "ultimate_resistance_N", "set_per_blow_m", "blows_per_0.25m",
                                   "max_compression_Pa", "max_tension_Pa", "enthru_J"});
        std::vector<PenetrationResult> graph(s.energy_levels.size() * s.bearing_resistances.size());
        const long n = static_cast<long>(graph.size());
#pragma omp parallel for schedule(dynamic, 1)
        for (long k = 0; k < n; ++k) {
            const double level = s.energy_levels[k / s.bearing_resistances.size()];
            const double r_u = s.bearing_resistances[k % s.bearing_resistances.size()];
            graph[k] = drive_at_penetration(s.mesh, s.steel, bearing_graph_resistance(s, r_u), s.smith,
                                            scaled_hammer(s.hammer, level), s.ram_element_size, s.driving);
        }
        for (long k = 0; k < n; ++k) {
            const auto& p = graph[k];
            bg.add_row({s.energy_levels[k / s.bearing_resistances.size()],
                        s.bearing_resistances[k % s.bearing_resistances.size()], p.set,
                        p.blows_per_quarter_metre, p.last.max_compression_stress, p.last.max_tension_stress,
                        p.last.enthru});
        }
        result.bearing_graph = std::move(bg);
    }
    result.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return result;
}

}  // namespace pilempm::coupling
