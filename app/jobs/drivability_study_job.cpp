#include "app/jobs/drivability_study_job.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "app/jobs/verification_runner.hpp"
#include "coupling/wave_equation/field_comparison.hpp"
#include "io/cases/drivability_study_setup.hpp"
#include "io/writers/csv_writer.hpp"
#include "io/writers/json_writer.hpp"
#include "io/writers/plots.hpp"
#include "io/writers/staged_directory.hpp"
#include "io/writers/terminal_progress.hpp"

namespace pilempm::app {

namespace fs = std::filesystem;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

struct LocationResult {
    io::StudyLocation location;
    coupling::DrivabilityResult result;
    std::vector<coupling::Comparison> comparisons;  // one per soil case
    std::vector<coupling::Comparison> above, below; // the same above and below study.split_depth
    double in_band = kNaN;                          // share of depths inside the band
};

const coupling::DrivabilityRun& run_of(const coupling::DrivabilityResult& r, const std::string& soil_case) {
    for (const auto& run : r.runs)
        if (run.soil_case == soil_case) return run;
    throw std::logic_error("no run for soil case " + soil_case);
}

// The reference energy at which the calibration location's predicted blows match its record.
double calibrate(const io::DrivabilityCase& c, const std::vector<io::FieldRecord>& all, double& measured,
                 double& predicted) {
    const auto& s = c.study;
    const auto it = std::find_if(all.begin(), all.end(), [&s](const auto& r) { return r.location == s.calibration_location; });
    const io::FieldRecord r = it != all.end() ? *it : io::read_field_records(s.records, {s.calibration_location}).front();
    io::StudyLocation l = io::build_study_location(c, r, s.reference_energy);
    l.setup.cases.erase(std::remove_if(l.setup.cases.begin(), l.setup.cases.end(),
                                       [&s](const auto& k) { return k.name != s.calibration_soil_case; }),
                        l.setup.cases.end());
    measured = l.measured.total_blows();
    auto blows = [&](double energy) {
        io::set_reference_energy(l, c, energy);
        const auto result = coupling::run_drivability(l.setup);
        return coupling::compare_driving(coupling::predicted_from_table(result.runs.front().table), l.measured)
            .predicted_total;
    };
    const double e = coupling::fit_reference_energy(blows, measured, s.calibration_low, s.calibration_high);
    predicted = blows(e);
    return e;
}

LocationResult run_location(const io::DrivabilityCase& c, const io::FieldRecord& r, double reference_energy) {
    LocationResult out;
    out.location = io::build_study_location(c, r, reference_energy);
    out.result = coupling::run_drivability(out.location.setup);
    std::vector<coupling::PredictedDriving> predicted;
    for (const auto& sc : out.location.setup.cases) {
        predicted.push_back(coupling::predicted_from_table(run_of(out.result, sc.name).table));
        const auto& m = out.location.measured;
        out.comparisons.push_back(coupling::compare_driving(predicted.back(), m));
        if (c.study.split_depth > 0.0) {
            out.above.push_back(coupling::compare_driving(predicted.back(), m.between(0.0, c.study.split_depth)));
            out.below.push_back(coupling::compare_driving(predicted.back(), m.between(c.study.split_depth, 1e9)));
        }
    }
    auto index = [&](const std::string& n) {
        for (std::size_t k = 0; k < out.location.setup.cases.size(); ++k)
            if (out.location.setup.cases[k].name == n) return k;
        throw std::logic_error("no soil case " + n);
    };
    out.in_band = coupling::share_inside_band(predicted[index(c.study.lower_case)],
                                              predicted[index(c.study.upper_case)], out.location.measured);
    return out;
}

// Measured and predicted blows per metre (and SRD, energy) at the measured depths.
Table location_table(const io::DrivabilityCase& c, const LocationResult& l) {
    std::vector<std::string> cols = {"depth_m", "measured_blows_per_m", "measured_cumulative_blows",
                                     "normalised_hammer_energy", "hammer_energy_J"};
    const auto& cases = l.location.setup.cases;
    for (const auto& sc : cases) {
        cols.push_back("predicted_blows_per_m_" + sc.name);
        cols.push_back("predicted_cumulative_blows_" + sc.name);
        cols.push_back("srd_total_N_" + sc.name);
    }
    Table t("location_" + l.location.record.location, cols);
    const auto& m = l.location.measured;
    const auto& rec = l.location.record;
    for (std::size_t k = 0; k < cols.size(); ++k) t.data[k].resize(m.depth.size(), kNaN);
    for (std::size_t i = 0; i < m.depth.size(); ++i) {
        t.data[0][i] = m.depth[i];
        t.data[1][i] = m.blows_per_m[i];
        t.data[2][i] = m.cumulative_blows[i] - m.cumulative_blows.front();
        t.data[3][i] = rec.normalised_energy[i];
        t.data[4][i] = coupling::planned_energy_level(l.location.setup, m.depth[i], 1.0) * c.rated_energy;
    }
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const Table& run = run_of(l.result, cases[k].name).table;
        const auto p = coupling::predicted_from_table(run);
        const auto srd_col = std::find(run.columns.begin(), run.columns.end(), "srd_total_N") - run.columns.begin();
        const auto& srd = run.data[static_cast<std::size_t>(srd_col)];
        double cumulative = 0.0;
        for (std::size_t i = 0; i < m.depth.size() && i < p.depth.size(); ++i) {
            if (i > 0) cumulative += 0.5 * (p.blows_per_m[i] + p.blows_per_m[i - 1]) * (p.depth[i] - p.depth[i - 1]);
            t.data[5 + 3 * k][i] = p.blows_per_m[i];
            t.data[6 + 3 * k][i] = cumulative;
            t.data[7 + 3 * k][i] = srd[i];
        }
    }
    return t;
}

io::JsonObject statistics_json(const coupling::StudyStatistics& s) {
    io::JsonObject o;
    o.add("locations", static_cast<double>(s.locations))
        .add("median_abs_ln_predicted_over_measured", s.median_abs_log_ratio)
        .add("share_within_factor_1_5", s.share_within_factor_1_5)
        .add("median_profile_correlation", s.median_profile_correlation);
    return o;
}

}  // namespace

int check_drivability_study_case(const std::string& file) {
    const io::DrivabilityCase c = io::read_drivability_case(file);
    const auto records = io::read_field_records(c.study.records, c.study.locations);
    std::printf("%s: valid\n", file.c_str());
    std::printf("  title          %s\n", c.title.c_str());
    std::printf("  records        %s: %zu locations\n", c.study.records.c_str(), records.size());
    std::printf("  hammer         %s; reference energy %.0f kJ%s\n", c.hammer_description.c_str(),
                c.study.reference_energy * 1e-3,
                c.study.calibration_location.empty() ? "" : (", fitted on " + c.study.calibration_location).c_str());
    std::printf("  soil cases     ");
    for (const auto& sc : c.cases)
        std::printf("%s (%s x %.2f)  ", sc.name.c_str(), coupling::srd_method_name(sc.method), sc.factor);
    std::printf("\n");
    long points = 0;
    for (const auto& r : records) {
        const io::StudyLocation l = io::build_study_location(c, r, c.study.reference_energy);
        points += static_cast<long>(r.driven_depth.size());
        std::printf("  %-4s D %.2f m, toe wall %.0f mm, pile %.1f m, driven %.1f-%.1f m, %zu CPT depths (%d smoothed)\n",
                    r.location.c_str(), r.diameter, r.toe_wall * 1e3, r.final_penetration + c.study.stick_up, r.driven_depth.front(),
                    r.driven_depth.back(), r.cpt.depth.size(), l.cpt.smoothed_points);
    }
    std::printf("  about %ld depth points x %zu soil cases\n", points, c.cases.size());
    return 0;
}

int run_drivability_study_case(const std::string& file, const fs::path& out_dir, bool quiet) {
    const auto t0 = std::chrono::steady_clock::now();
    const io::DrivabilityCase c = io::read_drivability_case(file);
    const auto& s = c.study;
    const auto records = io::read_field_records(s.records, s.locations);
    io::StagedDirectory staged(out_dir);
    fs::create_directories(staged.path() / "locations");

    double reference = s.reference_energy, cal_measured = kNaN, cal_predicted = kNaN;
    if (!s.calibration_location.empty()) {
        if (!quiet) std::fprintf(stderr, "fitting the reference energy on %s ...\n", s.calibration_location.c_str());
        reference = calibrate(c, records, cal_measured, cal_predicted);
    }

    io::TerminalProgress progress("study", !quiet);
    std::vector<LocationResult> results;
    long depth_points = 0;
    for (std::size_t i = 0; i < records.size(); ++i) {
        results.push_back(run_location(c, records[i], reference));
        depth_points += results.back().result.depth_points;
        progress.update_count(static_cast<long>(i + 1), static_cast<long>(records.size()), "locations");
    }
    progress.done();

    // One row per location and soil case; the statistics leave the calibration location out.
    Table study("study", {"predicted_total_blows", "measured_total_blows", "predicted_over_measured",
                          "abs_ln_ratio", "profile_correlation", "share_inside_band", "first_driven_depth_m",
                          "last_driven_depth_m", "self_weight_penetration_with_hammer_m", "calibration_location"});
    std::vector<std::vector<std::string>> text(3);
    std::vector<std::vector<coupling::Comparison>> per_case(c.cases.size()), above(c.cases.size()),
        below(c.cases.size());
    std::vector<double> band;
    for (const auto& l : results) {
        const auto& rec = l.location.record;
        const bool cal = rec.location == s.calibration_location;
        for (std::size_t k = 0; k < c.cases.size(); ++k) {
            const auto& cmp = l.comparisons[k];
            const auto& run = run_of(l.result, c.cases[k].name);
            study.add_row({cmp.predicted_total, cmp.measured_total, cmp.ratio, cmp.abs_log_ratio,
                           cmp.profile_correlation, l.in_band, rec.driven_depth.front(), rec.driven_depth.back(),
                           run.self_weight_penetration_with_hammer, cal ? 1.0 : 0.0});
            text[0].push_back(rec.location);
            text[1].push_back(c.cases[k].name);
            text[2].push_back(coupling::srd_method_name(c.cases[k].method));
            if (cal) continue;
            per_case[k].push_back(cmp);
            if (s.split_depth > 0.0) {
                above[k].push_back(l.above[k]);
                below[k].push_back(l.below[k]);
            }
        }
        if (!cal) band.push_back(l.in_band);
        io::write_csv(staged.path() / "locations" / (rec.location + ".csv"), location_table(c, l));
        io::write_csv(staged.path() / "locations" / (rec.location + "_cpt.csv"),
                      coupling::cpt_profile_table(l.location.cpt, rec.location + "_cpt"));
    }
    io::write_csv(staged.path() / "study.csv", study, {"location", "soil_case", "srd_method"}, text);

    Table stats("statistics", {"locations", "median_abs_ln_ratio", "share_within_factor_1_5",
                               "median_profile_correlation", "median_share_inside_band",
                               "median_abs_ln_ratio_above_split", "median_abs_ln_ratio_below_split",
                               "median_profile_correlation_below_split"});
    std::vector<std::vector<std::string>> stat_text(2);
    std::vector<io::JsonObject> stat_json;
    for (std::size_t k = 0; k < c.cases.size(); ++k) {
        const auto st = coupling::study_statistics(per_case[k]);
        const auto up = coupling::study_statistics(above[k]), down = coupling::study_statistics(below[k]);
        stats.add_row({static_cast<double>(st.locations), st.median_abs_log_ratio, st.share_within_factor_1_5,
                       st.median_profile_correlation, coupling::median(band), up.median_abs_log_ratio,
                       down.median_abs_log_ratio, down.median_profile_correlation});
        stat_text[0].push_back(c.cases[k].name);
        stat_text[1].push_back(coupling::srd_method_name(c.cases[k].method));
        io::JsonObject j = statistics_json(st);
        if (s.split_depth > 0.0)
            j.add("split_depth_m", s.split_depth).add("above_split", std::make_shared<io::JsonObject>(statistics_json(up)))
                .add("below_split", std::make_shared<io::JsonObject>(statistics_json(down)));
        j.add("soil_case", c.cases[k].name).add("srd_method", std::string(coupling::srd_method_name(c.cases[k].method)))
            .add("srd_factor", c.cases[k].factor);
        stat_json.push_back(std::move(j));
    }
    io::write_csv(staged.path() / "statistics.csv", stats, {"soil_case", "srd_method"}, stat_text);
    std::vector<VerificationCheck> checks;
    for (std::size_t k = 0; k < c.cases.size(); ++k) {
        if (c.cases[k].name != s.verified_case) continue;
        const auto st = coupling::study_statistics(per_case[k]);
        const std::string who = " of " + s.verified_case + " over " + std::to_string(st.locations) + " locations";
        if (s.max_median_abs_ln_ratio > 0.0)
            checks.push_back(make_check("median_abs_ln_ratio", st.median_abs_log_ratio, 0.0, s.max_median_abs_ln_ratio,
                                        false, "median |ln(predicted / measured total blows)|" + who + ", at most"));
        if (s.min_median_profile_correlation > -1.0) {
            auto r = make_check("median_profile_correlation", st.median_profile_correlation,
                                s.min_median_profile_correlation, 0.0, false,
                                "median Pearson r of blows per metre" + who + ", at least");
            r.at_least = true;
            r.passed = st.median_profile_correlation >= s.min_median_profile_correlation;
            checks.push_back(r);
        }
    }
    if (!checks.empty()) io::write_json(staged.path() / "verification.json", verification_json(c, checks, {}));

    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    io::JsonObject o;
    o.add("title", c.title).add("case_file", c.file).add("analysis", std::string("drivability_study"))
        .add("records", s.records).add("hammer", c.hammer_description).add("rated_energy_J", c.rated_energy)
        .add("reference_energy_J", reference).add("stick_up_m", s.stick_up)
        .add("units", std::string("depths in m below the seabed, blows per metre, energies in J"));
    if (!s.calibration_location.empty()) {
        io::JsonObject cal;
        cal.add("location", s.calibration_location).add("soil_case", s.calibration_soil_case)
            .add("measured_total_blows", cal_measured).add("predicted_total_blows", cal_predicted)
            .add("bracket_J", std::vector<double>{s.calibration_low, s.calibration_high});
        o.add("calibration", std::make_shared<io::JsonObject>(cal));
    }
    o.add("cpt_correlations", io::json_lines("correlation", coupling::cpt_correlations(c.cpt_options))).add("band", s.lower_case + " .. " + s.upper_case)
        .add("median_share_inside_band", coupling::median(band)).add("statistics", stat_json)
        .add("locations", static_cast<double>(results.size())).add("depth_points", static_cast<double>(depth_points))
        .add("wall_time_s", wall);
    io::write_json(staged.path() / "summary.json", o);
    if (c.plots) {
        std::string note;
        if (!io::make_plots("plot_drivability_study.py", staged.path(), note) && !quiet)
            std::fprintf(stderr, "note: %s\n", note.c_str());
    }
    staged.commit();
    if (!quiet) {
        std::printf("%s\n  reference energy %.0f kJ%s; %zu locations, %ld depth points, wall time %.1f s\n",
                    c.title.c_str(), reference * 1e-3,
                    s.calibration_location.empty() ? "" : (" (fitted on " + s.calibration_location + ")").c_str(),
                    results.size(), depth_points, wall);
        std::printf("  %-16s %-20s %10s %12s %9s", "soil case", "method", "median|ln|", "within x1.5", "median r");
        if (s.split_depth > 0.0) std::printf("   median|ln| above / below %.1f m", s.split_depth);
        std::printf("\n");
        for (std::size_t k = 0; k < c.cases.size(); ++k) {
            const auto st = coupling::study_statistics(per_case[k]);
            std::printf("  %-16s %-20s %10.3f %11.0f%% %9.2f", c.cases[k].name.c_str(),
                        coupling::srd_method_name(c.cases[k].method), st.median_abs_log_ratio,
                        100 * st.share_within_factor_1_5, st.median_profile_correlation);
            if (s.split_depth > 0.0)
                std::printf("   %10.3f / %.3f", coupling::study_statistics(above[k]).median_abs_log_ratio,
                            coupling::study_statistics(below[k]).median_abs_log_ratio);
            std::printf("\n");
        }
        std::printf("  median share of depths inside %s .. %s: %.0f%%\n  results in %s\n", s.lower_case.c_str(),
                    s.upper_case.c_str(), 100 * coupling::median(band), out_dir.c_str());
    }
    return 0;
}

}  // namespace pilempm::app
