#include "app/jobs/drivability_job.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>

#include "io/writers/terminal_progress.hpp"
#include "app/jobs/verification_runner.hpp"
#include "coupling/wave_equation/drivability_verification.hpp"
#include "io/writers/csv_writer.hpp"
#include "io/cases/drivability_case.hpp"
#include "io/hdf5/hdf5_results.hpp"
#include "io/writers/json_writer.hpp"
#include "io/writers/plots.hpp"
#include "io/writers/staged_directory.hpp"

namespace pilempm::app {

namespace fs = std::filesystem;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

const char* type_name(coupling::SoilType t) { return t == coupling::SoilType::Sand ? "sand" : "clay"; }

// The first case named best_estimate, else the first case: the one the checks use.
const coupling::SoilCase& reference_case(const coupling::DrivabilitySetup& s) {
    for (const auto& c : s.cases)
        if (c.name == "best_estimate") return c;
    return s.cases.front();
}

std::vector<VerificationCheck> run_checks(const io::DrivabilityCase& c, const coupling::DrivabilitySetup& s,
                                          const coupling::DrivabilityResult& r,
                                          const coupling::CalibrationResult* calibration) {
    const double depth = c.verification_depth > 0.0 ? c.verification_depth : s.final_depth;
    const auto& ref = reference_case(s);
    std::vector<VerificationCheck> all;
    auto append = [&all](std::vector<VerificationCheck> v) { all.insert(all.end(), v.begin(), v.end()); };
    for (const auto& name : c.verification_checks) {
        if (name == "static_push") append(coupling::check_static_push(s, ref, depth));
        else if (name == "calibration_sets" && calibration) {
            // The fitted fast path against the coupled model it was fitted to, run by run.
            for (const auto& p : calibration->points) {
                char label[64];
                std::snprintf(label, sizeof label, "calibrated_set_at_%.2fm", p.target.depth);
                all.push_back(make_check(label, p.fast_set_after, p.target.set, c.calibration_tolerance, true,
                                         "the fitted fast path's set against the coupled model's (" + p.target.source + ")"));
            }
        } else if (name == "calibrated_blow_count" && calibration) {
            // The calibrated sheet's blows over the drive's depths against the coupled drive's.
            for (const auto& run : r.runs)
                if (run.soil_case == "calibrated" && run.energy_level == r.runs.front().energy_level) {
                    const auto& m = c.reference_drive;
                    const auto k = coupling::compare_driving(coupling::predicted_from_table(run.table), m);
                    char label[80];
                    std::snprintf(label, sizeof label, "calibrated_blows_%.2f_to_%.2fm", m.depth.front(), m.depth.back());
                    all.push_back(make_check(label, k.predicted_total, k.measured_total, c.blow_count_tolerance, true,
                                             "the calibrated sheet's blows against the coupled drive's"));
                }
        } else if (name == "bearing_graph_monotonic") append(coupling::check_bearing_graph(r.bearing_graph));
        else if (name == "blow_energy_balance") append(coupling::check_blow_energy(s, ref, depth));
        else if (name == "danish_formula") {
            const auto srd = coupling::srd_for_driving(s, ref, depth);
            const auto p = coupling::drive_at_penetration(s.mesh, s.steel, srd, s.smith, s.hammer,
                                                          s.ram_element_size, s.driving);
            append(coupling::check_danish_formula(s, p));
        } else if (name == "self_weight_penetration") {
            for (const auto& run : r.runs)
                if (run.soil_case == ref.name && run.energy_level == r.runs.front().energy_level)
                    all.push_back(make_check(
                        "self_weight_penetration_m", run.self_weight_penetration, c.observed_self_weight_penetration,
                        c.observed_tolerance, false, "submerged pile weight against the " + ref.name + " SRD, observed depth"));
        }
    }
    return all;
}

// `cases`: every run's soil case (the setup's, and the calibrated one where there is one).
io::JsonObject summary_json(const io::DrivabilityCase& c, const coupling::DrivabilitySetup& s,
                            const std::vector<coupling::SoilCase>& cases, const coupling::DrivabilityResult& r) {
    io::JsonObject o;
    o.add("title", c.title).add("case_file", c.file).add("analysis", std::string("drivability"))
        .add("hammer", c.hammer_description)
        .add("units", std::string("depths in m below the mudline, forces in N, stresses in Pa (compression and tension as magnitudes), energy in J"))
        .add("refusal_blow_count", c.refusal_blow_count).add("hard_driving_blow_count", c.hard_driving_blow_count)
        .add("depth_step_m", c.depth_step).add("pile_mass_kg", s.pile_mass)
        .add("qc_correlation", std::string(c.soil.cpt.depth.empty() ? "Baldi et al. (1986), normally consolidated sand: q_c = 157 sigma'_v0^0.55 exp(2.41 D_R) (kPa)"
                                                                    : "CPT record " + c.cpt_file));
    if (c.cpt_soil) {
        o.add("cpt_profile_file", std::string("cpt_profile.csv"))
            .add("cpt_correlations", io::json_lines("correlation", coupling::cpt_correlations(c.cpt_options)))
            .add("cpt_points_smoothed", static_cast<double>(c.cpt_interpretation.smoothed_points));
    }
    if (!s.energy_plan_depth.empty())
        o.add("energy_plan", c.energy_plan_source)
            .add("energy_plan_depth_m", s.energy_plan_depth).add("energy_plan_fraction", s.energy_plan_level);
    if (c.rated_energy > 0.0) o.add("rated_energy_J", c.rated_energy);
    std::vector<io::JsonObject> runs;
    double worst_c = 0.0, worst_t = 0.0;
    for (const auto& run : r.runs) {
        io::JsonObject j;
        j.add("file", run.table.name + ".csv").add("soil_case", run.soil_case).add("energy_level", run.energy_level)
            .add("self_weight_penetration_m", run.self_weight_penetration)
            .add("self_weight_penetration_with_hammer_m", run.self_weight_penetration_with_hammer)
            .add("refusal_depth_m", run.refusal_depth >= 0.0 ? run.refusal_depth : kNaN)
            .add("final_depth_reached_m", run.final_depth_reached).add("total_blows", run.total_blows)
            .add("hard_driving_from_m", run.hard_driving_from >= 0.0 ? run.hard_driving_from : kNaN)
            .add("max_compression_Pa", run.max_compression).add("max_compression_at_depth_m", run.max_compression_depth)
            .add("max_tension_Pa", run.max_tension).add("max_tension_at_depth_m", run.max_tension_depth);
        for (const auto& k : cases)
            if (k.name == run.soil_case)
                j.add("srd_method", std::string(coupling::srd_method_name(k.method))).add("srd_factor", k.factor);
        worst_c = std::max(worst_c, run.max_compression);
        worst_t = std::max(worst_t, run.max_tension);
        runs.push_back(std::move(j));
    }
    o.add("runs", runs).add("worst_compression_Pa", worst_c).add("worst_tension_Pa", worst_t);
    if (r.bearing_graph.rows() > 0) o.add("bearing_graph_file", std::string("bearing_graph.csv"));
    o.add("depth_points", static_cast<double>(r.depth_points)).add("blows_simulated", static_cast<double>(r.blows_simulated))
        .add("wall_time_s", r.wall_time);
    return o;
}

const coupling::SoilCase& named_case(const coupling::DrivabilitySetup& s, const std::string& name) {
    for (const auto& k : s.cases)
        if (k.name == name) return k;
    throw std::logic_error("no soil case " + name);  // the reader checked it
}

io::JsonObject parameters_json(const coupling::FastPathSoil& soil) {
    io::JsonObject o;
    o.add("srd_factor", soil.srd_factor).add("shaft_quake_m", soil.smith.shaft_quake)
        .add("toe_quake_m", soil.smith.toe_quake).add("toe_damping", soil.smith.toe_damping);
    if (soil.smith.law == coupling::DampingLaw::Case) o.add("shaft_damping_case", soil.smith.shaft_damping);
    else o.add("sand_shaft_damping_s_m", soil.sand_shaft_damping).add("clay_shaft_damping_s_m", soil.clay_shaft_damping);
    return o;
}

// The fit, its residuals and the coupled blow counts the plot marks on the sheet.
void add_calibration_json(io::JsonObject& o, const io::DrivabilityCase& c, const coupling::SoilCase& sc,
                          const coupling::CalibrationResult& r) {
    io::JsonObject j;
    std::vector<std::string> fitted, at_bound;
    for (auto p : r.fitted) fitted.push_back(coupling::calibration_parameter_name(p));
    for (auto p : r.at_bound) at_bound.push_back(coupling::calibration_parameter_name(p));
    std::vector<io::JsonObject> points, counts;
    for (const auto& p : r.points) {
        io::JsonObject q;
        q.add("run", p.target.source).add("depth_m", p.target.depth).add("blows", static_cast<double>(p.target.blows))
            .add("coupled_set_m", p.target.set).add("fast_set_before_m", p.fast_set_before)
            .add("fast_set_after_m", p.fast_set_after).add("record_misfit_before", p.record_misfit_before)
            .add("record_misfit_after", p.record_misfit_after);
        points.push_back(std::move(q));
        io::JsonObject b;
        b.add("depth_m", p.target.depth).add("blows_per_0.25m", 0.25 / p.target.set);
        counts.push_back(std::move(b));
    }
    j.add("soil_case", c.calibration_soil_case).add("srd_method", std::string(coupling::srd_method_name(sc.method)))
        .add("fitted", io::json_lines("parameter", fitted)).add("at_bound", io::json_lines("parameter", at_bound))
        .add("before", std::make_shared<io::JsonObject>(parameters_json(r.before)))
        .add("after", std::make_shared<io::JsonObject>(parameters_json(r.after)))
        .add("objective_before", r.objective_before).add("objective_after", r.objective_after)
        .add("objective", std::string("mean over the runs of ln(fast set / coupled set)^2 + record_weight x the head "
                                      "records' relative mean square difference (velocity; force too for a ram-cushion hammer); "
                                      "after the fit, + regularisation x sum of ln(fitted factor)^2"))
        .add("record_weight", c.calibration.record_weight).add("regularisation", c.calibration.regularisation).add("record_window_s", r.record_window)
        .add("compares_force", r.compares_force).add("evaluations", static_cast<double>(r.evaluations))
        .add("converged", r.converged).add("wall_time_s", r.wall_time).add("points", points)
        .add("file", std::string("calibration.csv")).add("records_file", std::string("calibration_records.csv"));
    o.add("calibration", std::make_shared<io::JsonObject>(j)).add("coupled_blow_counts", counts);
}

void print_calibration(const coupling::CalibrationResult& r) {
    std::printf("  calibrated on %zu coupled run(s) (%d evaluations, %.1f s%s): objective %.4g -> %.4g\n", r.points.size(),
                r.evaluations, r.wall_time, r.converged ? "" : ", not converged", r.objective_before, r.objective_after);
    for (auto p : r.fitted)
        std::printf("    %-14s %10.4g -> %.4g%s\n", coupling::calibration_parameter_name(p), r.before.value(p),
                    r.after.value(p),
                    std::find(r.at_bound.begin(), r.at_bound.end(), p) != r.at_bound.end() ? "  (on its bound)" : "");
    std::printf("    %8s %12s %12s %12s %10s %10s\n", "depth", "coupled set", "fast before", "fast after", "rec. before",
                "rec. after");
    for (const auto& p : r.points)
        std::printf("    %6.2f m %9.2f mm %9.2f mm %9.2f mm %10.3f %10.3f\n", p.target.depth, 1e3 * p.target.set,
                    1e3 * p.fast_set_before, 1e3 * p.fast_set_after, p.record_misfit_before, p.record_misfit_after);
}

void print_summary(const io::DrivabilityCase& c, const coupling::DrivabilityResult& r, const fs::path& out) {
    std::printf("%s\n", c.title.c_str());
    std::printf("  %-16s %6s %10s %10s %12s %12s %10s\n", "soil case", "energy", "SWP (m)", "refusal", "total blows",
                "max comp.", "max tens.");
    for (const auto& run : r.runs) {
        char refusal[32];
        if (run.refusal_depth >= 0.0) std::snprintf(refusal, sizeof refusal, "%.2f m", run.refusal_depth);
        else std::snprintf(refusal, sizeof refusal, "none");
        std::printf("  %-16s %5.0f%% %10.2f %10s %12.0f %8.1f MPa %6.1f MPa\n", run.soil_case.c_str(),
                    100 * run.energy_level, run.self_weight_penetration, refusal, run.total_blows,
                    run.max_compression * 1e-6, run.max_tension * 1e-6);
    }
    std::printf("  %ld depth points, %ld blows simulated, wall time %.2f s\n", r.depth_points, r.blows_simulated,
                r.wall_time);
    std::printf("  results in %s\n", out.c_str());
}

}  // namespace

int check_drivability_case(const std::string& file) {
    const io::DrivabilityCase c = io::read_drivability_case(file);
    const coupling::DrivabilitySetup s = io::build_drivability_setup(c);
    std::printf("%s: valid\n", file.c_str());
    std::printf("  title          %s\n", c.title.c_str());
    std::printf("  analysis       wave-equation drivability, %.2f m to %.2f m every %.2f m\n",
                c.start_depth >= 0 ? c.start_depth : 0.0, c.final_depth, c.depth_step);
    if (c.start_depth < 0) std::printf("                 (starting at each soil case's self-weight penetration)\n");
    std::printf("  pile           rod, L = %.2f m, %d elements of %.3g m, mass %.1f t, D = %.3f m, t = %.4f m\n",
                c.length(), s.mesh.num_elements(), c.element_size, s.pile_mass * 1e-3, s.outer_diameter, s.wall_thickness);
    std::printf("  hammer         %s\n", c.hammer_description.c_str());
    std::printf("  soil           %zu layers, water depth %.1f m, q_c %s\n", c.soil.layers.size(), c.soil.water_depth,
                c.soil.cpt.depth.empty() ? "from D_R (Baldi et al. 1986)" : "from the CPT record");
    if (c.cpt_soil) {
        // Derived layers come one per CPT depth: show the sand and clay runs instead.
        std::printf("                 from the CPT %s (%d points smoothed):\n", c.cpt_file.c_str(),
                    c.cpt_interpretation.smoothed_points);
        const auto& L = c.soil.layers;
        for (std::size_t a = 0, b = 0; a < L.size(); a = b) {
            while (b < L.size() && L[b].type == L[a].type) ++b;
            std::printf("                 %6.2f - %6.2f m  %s\n", L[a].top, L[b - 1].bottom, type_name(L[a].type));
        }
    } else {
        for (const auto& l : c.soil.layers)
            std::printf("                 %6.2f - %6.2f m  %s  %s\n", l.top, l.bottom, type_name(l.type), l.name.c_str());
    }
    if (!s.energy_plan_depth.empty())
        std::printf("  energy plan    %zu points from %s, %.0f%% to %.0f%% of the rated energy\n",
                    s.energy_plan_depth.size(), c.energy_plan_source.c_str(),
                    100 * *std::min_element(s.energy_plan_level.begin(), s.energy_plan_level.end()),
                    100 * *std::max_element(s.energy_plan_level.begin(), s.energy_plan_level.end()));
    std::printf("  soil cases     ");
    for (const auto& sc : c.cases)
        std::printf("%s (%s x %.2f)  ", sc.name.c_str(), coupling::srd_method_name(sc.method), sc.factor);
    std::printf("\n  SRD at %.2f m:", c.final_depth);
    for (const auto& sc : c.cases)
        std::printf("  %s %.2f MN", sc.name.c_str(), coupling::srd_for_driving(s, sc, c.final_depth).total() * 1e-6);
    if (!c.calibration_targets.empty()) {
        std::printf("\n  calibration    the %s soil fitted to %zu coupled run(s):", c.calibration_soil_case.c_str(),
                    c.calibration_targets.size());
        for (const auto& t : c.calibration_targets)
            std::printf("\n                 %6.2f m, %d blows, set %.2f mm  (%s)", t.depth, t.blows, 1e3 * t.set,
                        t.source.c_str());
    }
    std::printf("\n  energy levels  %zu, threads %s\n", c.energy_levels.size(),
                c.threads > 0 ? std::to_string(c.threads).c_str() : "all cores");
    return 0;
}

int run_drivability_case(const std::string& file, const fs::path& out_dir, bool quiet) {
    const io::DrivabilityCase c = io::read_drivability_case(file);
    const coupling::DrivabilitySetup setup = io::build_drivability_setup(c);
    io::StagedDirectory staged(out_dir);
    io::TerminalProgress progress("drivability", !quiet);
    auto result = coupling::run_drivability(
        setup, [&progress](long done, long total) { progress.update_count(done, total, "depth points"); });
    progress.done();
    // The calibrated sheet beside the others: the chosen case's soil fitted to the coupled runs.
    std::optional<coupling::CalibrationResult> calibration;
    if (!c.calibration_targets.empty()) {
        const coupling::SoilCase& sc = named_case(setup, c.calibration_soil_case);
        if (!quiet)
            std::fprintf(stderr, "fitting the %s soil to %zu coupled run(s) ...\n", sc.name.c_str(),
                         c.calibration_targets.size());
        calibration = coupling::calibrate_fast_path(setup, sc, c.calibration_targets, c.calibration);
        const auto calibrated = coupling::run_drivability(coupling::with_soil(setup, sc, calibration->after, "calibrated"));
        for (const auto& run : calibrated.runs) result.runs.push_back(run);
        result.depth_points += calibrated.depth_points;
        result.blows_simulated += calibrated.blows_simulated;
        result.wall_time += calibrated.wall_time;
    }

    std::vector<Table> tables;
    for (const auto& run : result.runs) tables.push_back(run.table);
    if (result.bearing_graph.rows() > 0) tables.push_back(result.bearing_graph);
    if (calibration) {
        tables.push_back(coupling::calibration_table(*calibration));
        tables.push_back(coupling::calibration_records_table(*calibration));
    }
    for (const auto& t : tables) io::write_csv(staged.path() / (t.name + ".csv"), t);
    if (c.cpt_soil)
        io::write_csv(staged.path() / "cpt_profile.csv", coupling::cpt_profile_table(c.cpt_interpretation, "cpt_profile"));

    std::vector<coupling::SoilCase> cases = setup.cases;
    if (calibration) {
        const coupling::SoilCase& sc = named_case(setup, c.calibration_soil_case);
        cases.push_back({"calibrated", sc.method, calibration->after.srd_factor});
    }
    io::JsonObject summary = summary_json(c, setup, cases, result);
    if (calibration) add_calibration_json(summary, c, named_case(setup, c.calibration_soil_case), *calibration);
    if (!c.verification_checks.empty()) {
        const auto checks = run_checks(c, setup, result, calibration ? &*calibration : nullptr);
        io::write_json(staged.path() / "verification.json", verification_json(c, checks, io::JsonObject{}));
        if (!quiet)
            for (const auto& k : checks)
                std::printf("  [%s] %-40s computed %-14.6g reference %-14.6g tol %g\n", k.passed ? "pass" : "FAIL",
                            k.name.c_str(), k.computed, k.reference, k.tolerance);
    }
    io::write_results_h5(staged.path() / "results.h5", tables, setup.mesh, {}, {}, {},
                         {{"depth_points", static_cast<double>(result.depth_points)},
                          {"wall_time_s", result.wall_time}},
                         {{"title", c.title}, {"case_file", c.file}, {"analysis", "drivability"}});
    io::write_json(staged.path() / "summary.json", summary);
    if (c.plots) {
        std::string note;
        if (!io::make_plots("plot_drivability.py", staged.path(), note) && !quiet)
            std::fprintf(stderr, "note: %s\n", note.c_str());
    }
    staged.commit();
    if (!quiet) {
        print_summary(c, result, out_dir);
        if (calibration) print_calibration(*calibration);
    }
    return 0;
}

}  // namespace pilempm::app
