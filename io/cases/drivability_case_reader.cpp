#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "fem/mesh/rod_mesh.hpp"
#include "io/cases/drivability_case.hpp"
#include "io/cases/coupled_run_records.hpp"
#include "io/cases/field_records.hpp"
#include "io/yaml/numeric_file.hpp"
#include "io/yaml/yaml_reader.hpp"

namespace pilempm::io {
namespace {

const std::vector<std::string> kAnalyses = {"pile_wave", "drivability", "drivability_study", "mpm", "element_test"};
const std::vector<std::string> kChecks = {"static_push", "bearing_graph_monotonic",
                                          "blow_energy_balance", "danish_formula",
                                          "self_weight_penetration", "calibration_sets", "calibrated_blow_count"};

coupling::SrdMethod method_from(const std::string& name) {
    if (name == "alm_hamre_2001") return coupling::SrdMethod::AlmHamre2001;
    if (name == "stevens_lower_bound") return coupling::SrdMethod::StevensLowerBound;
    if (name == "unified_2020") return coupling::SrdMethod::Unified2020;
    return coupling::SrdMethod::StevensUpperBound;
}

coupling::SoilLayer read_layer(MapReader m, double expected_top) {
    coupling::SoilLayer l;
    l.name = m.text_or("name", "");
    l.top = m.number("top", non_negative("depth below the mudline in m"));
    if (std::abs(l.top - expected_top) > 1e-9) {
        std::ostringstream e, f;
        e << "layers that follow each other without gaps: a top at " << expected_top << " m";
        f << l.top << " m";
        m.fail("top", e.str(), f.str());
    }
    l.bottom = m.number("bottom", {"a depth below the layer's top (" + std::to_string(l.top) + " m)",
                                   [top = l.top](double b) { return b > top; }});
    l.type = m.choice("type", {"sand", "clay"}) == "sand" ? coupling::SoilType::Sand : coupling::SoilType::Clay;
    l.submerged_unit_weight = m.number("submerged_unit_weight", positive("unit weight in N/m^3"));
    if (l.type == coupling::SoilType::Sand) {
        l.relative_density = m.number("relative_density",
                                      in_half_open_range(0.0, 1.5, "a relative density as a fraction"));
        l.friction_angle = m.number_or("friction_angle", 0.0, in_open_range(-1e-12, 60.0, "an angle in degrees"));
        l.interface_friction_angle = m.number("interface_friction_angle",
                                              in_open_range(0.0, 45.0, "an angle in degrees"));
    } else {
        l.undrained_shear_strength = m.number("undrained_shear_strength", positive("strength in Pa"));
        l.undrained_shear_strength_gradient =
            m.number_or("undrained_shear_strength_gradient", 0.0, non_negative("gradient in Pa/m"));
        l.sensitivity = m.number_or("sensitivity", 2.0, {"a sensitivity of at least 1", [](double x) { return x >= 1.0; }});
    }
    m.finish();
    return l;
}

// A file named under `key`, relative to the case file; a missing one names the key.
std::string case_relative_file(MapReader& m, const std::string& key) {
    std::filesystem::path p(m.text_or(key, ""));
    if (p.is_relative()) p = std::filesystem::path(m.file()).parent_path() / p;
    if (!std::filesystem::is_regular_file(p)) m.fail(key, "a readable CSV file", p.string() + " missing");
    return p.string();
}

// A coupled drive's blow_count.csv (depth_bottom_m, blows_per_m, cumulative_blows per
// interval) as a record: each interval's bottom, its last one left out (the drive ended in it).
coupling::MeasuredDriving read_drive_blow_count(MapReader& m, const std::string& key) {
    const std::string path = case_relative_file(m, key);
    const HeaderedCsv t = read_headered_csv(path);
    for (const char* col : {"depth_bottom_m", "blows_per_m", "cumulative_blows"})
        if (t.column(col) < 0) m.fail(key, "a coupled drive's blow_count.csv (no column " + std::string(col) + ")", path);
    coupling::MeasuredDriving d;
    d.depth = t.numbers("depth_bottom_m");
    d.blows_per_m = t.numbers("blows_per_m");
    d.cumulative_blows = t.numbers("cumulative_blows");
    if (d.depth.size() < 3) m.fail(key, "a drive of three depth intervals or more", path);
    for (auto* v : {&d.depth, &d.blows_per_m, &d.cumulative_blows}) v->pop_back();
    return d;
}

void read_cpt_options(MapReader& m, coupling::CptInterpretationOptions& o) {
    o.net_area_ratio = m.number_or("net_area_ratio", 0.8, {"a net area ratio in (0, 1]",
                                                           [](double x) { return x > 0.0 && x <= 1.0; }});
    o.cone_factor = m.number_or("cone_factor", 15.0, positive("cone factor N_kt"));
    o.min_layer_thickness = m.number_or("min_layer_thickness", 1.0, non_negative("thickness in m"));
    o.interface_friction_angle =
        m.number_or("interface_friction_angle", 29.0, in_open_range(0.0, 45.0, "an angle in degrees"));
    o.clay_sensitivity = m.number_or("clay_sensitivity", 2.0, {"a sensitivity of at least 1", [](double x) { return x >= 1.0; }});
    o.sand_clay_boundary = m.number_or("sand_clay_boundary", 2.6, in_open_range(1.0, 4.0, "an I_c value"));
}

// A CPT file with depth_m, qc_MPa, fs_MPa and u2_MPa columns (u2 optional), or a field
// records file with `location`.
coupling::CptSounding read_cpt_sounding(MapReader& m) {
    const std::string path = case_relative_file(m, "file");
    if (m.has("location")) {
        const std::string loc = m.text_or("location", "");
        try {
            return read_field_records(path, {loc}).front().cpt;
        } catch (const CaseError& e) {
            m.fail("location", "a location of " + path + " with a complete record", "'" + loc + "': " + e.what());
        }
    }
    const HeaderedCsv t = read_headered_csv(path);
    coupling::CptSounding c;
    c.depth = t.numbers("depth_m");
    c.qc = t.numbers("qc_MPa");
    c.fs = t.numbers("fs_MPa");
    c.u2 = t.column("u2_MPa") >= 0 ? t.numbers("u2_MPa") : std::vector<double>(c.depth.size(), 0.0);
    for (auto* col : {&c.qc, &c.fs, &c.u2})
        for (double& x : *col) x *= 1e6;
    return c;
}

void read_soil(MapReader m, DrivabilityCase& c) {
    c.soil.water_depth = m.number_or("water_depth", 0.0, non_negative("water depth in m"));
    if (auto cpt = m.optional_map("cpt")) {
        // The soil from the sounding alone: no layers, no q_t record beside it.
        if (m.has("layers")) m.fail("layers", "no layers beside soil.cpt (they are derived from the CPT)");
        if (m.has("cpt_file")) m.fail("cpt_file", "no cpt_file beside soil.cpt");
        read_cpt_options(*cpt, c.cpt_options);
        c.cpt_soil = true;
        if (!c.study_mode) {
            const coupling::CptSounding sounding = read_cpt_sounding(*cpt);
            c.cpt_file = cpt->text_or("file", "");
            try {
                c.cpt_interpretation = coupling::interpret_cpt(sounding, c.cpt_options, c.soil.water_depth);
            } catch (const std::invalid_argument& e) {
                cpt->fail("file", "a usable CPT", e.what());
            }
            c.soil = c.cpt_interpretation.profile;
        } else if (cpt->has("file")) {
            cpt->fail("file", "no file in a study (each location's CPT comes from the records)");
        }
        cpt->finish();
        c.soil.clay_cone_factor = c.cpt_options.cone_factor;
        m.finish();
        return;
    }
    if (c.study_mode) m.fail("cpt", "soil.cpt in a study: each location's soil comes from its CPT");
    double top = 0.0;
    for (auto l : m.maps("layers")) {
        c.soil.layers.push_back(read_layer(l, top));
        top = c.soil.layers.back().bottom;
    }
    if (m.has("cpt_file")) {
        const NumericFile f = read_numeric_file(m, "cpt_file", {"depth_m", "qt_Pa", "fs_Pa"});
        c.cpt_file = f.path;
        c.soil.cpt = {f.columns[0], f.columns[1], f.columns[2]};
    }
    c.soil.clay_cone_factor = m.number_or("clay_cone_factor", 15.0, positive("cone factor N_kt"));
    m.finish();
}

void read_smith(MapReader m, DrivabilityCase& c) {
    auto& s = c.smith;
    s.shaft_quake = m.number_or("shaft_quake", 2.5e-3, positive("quake in m"));
    s.toe_quake = m.number_or("toe_quake", 2.5e-3, positive("quake in m"));
    const bool smith = m.choice_or("damping_law", "smith_viscous", {"smith_viscous", "case"}) == "smith_viscous";
    s.law = smith ? coupling::DampingLaw::SmithViscous : coupling::DampingLaw::Case;
    if (smith) {
        c.sand_shaft_damping = m.number_or("sand_shaft_damping", 0.16, non_negative("Smith damping in s/m"));
        c.clay_shaft_damping = m.number_or("clay_shaft_damping", 0.65, non_negative("Smith damping in s/m"));
        s.toe_damping = m.number_or("toe_damping", 0.50, non_negative("Smith damping in s/m"));
    } else {
        s.shaft_damping = m.number("shaft_damping", non_negative("Case damping factor J_c"));
        s.toe_damping = m.number("toe_damping", non_negative("Case damping factor J_c"));
    }
    m.finish();
}

void read_cases(MapReader& root, DrivabilityCase& c) {
    const std::vector<std::string> methods = {"alm_hamre_2001", "stevens_lower_bound", "stevens_upper_bound",
                                              "unified_2020"};
    if (!root.has("soil_cases")) {
        // The industry's usual three: Stevens lower bound, Alm & Hamre best estimate, and
        // Alm & Hamre x 1.25 as upper bound (their own recommendation).
        c.cases = {{"lower_bound", coupling::SrdMethod::StevensLowerBound, 1.0},
                   {"best_estimate", coupling::SrdMethod::AlmHamre2001, 1.0},
                   {"upper_bound", coupling::SrdMethod::AlmHamre2001, 1.25}};
        return;
    }
    for (auto m : root.maps("soil_cases")) {
        coupling::SoilCase sc;
        sc.name = m.text_or("name", "");
        if (sc.name.empty() || sc.name.find_first_of("/\\ ") != std::string::npos)
            m.fail("name", "a name without spaces or slashes (it names the output file)", "'" + sc.name + "'");
        sc.method = method_from(m.choice("method", methods));
        sc.factor = m.number_or("factor", 1.0, positive("factor on the SRD"));
        m.finish();
        c.cases.push_back(sc);
    }
}

// calibration: the coupled runs (output folders, relative to the case file) the soil case's
// Smith soil is fitted to, and what is fitted.
void read_calibration(MapReader m, DrivabilityCase& c) {
    namespace fs = std::filesystem;
    c.calibration_soil_case = m.text_or("soil_case", "best_estimate");
    if (std::none_of(c.cases.begin(), c.cases.end(), [&c](const auto& k) { return k.name == c.calibration_soil_case; }))
        m.fail("soil_case", "one of the soil cases (its SRD method is calibrated, its factor the start)",
               "'" + c.calibration_soil_case + "'");
    if (c.calibration_soil_case == "calibrated") m.fail("soil_case", "a soil case other than 'calibrated' (the fit's name)");
    std::vector<std::string> names;
    for (auto p : coupling::all_calibration_parameters()) names.push_back(coupling::calibration_parameter_name(p));
    if (m.has("fit")) {
        c.calibration.fit.clear();
        for (const auto& w : m.words("fit", names))
            for (auto p : coupling::all_calibration_parameters())
                if (w == coupling::calibration_parameter_name(p)) c.calibration.fit.push_back(p);
    }
    const int skip = m.integer_or("skip_blows", 1, 0);
    c.calibration.record_weight = m.number_or("record_weight", 1.0, non_negative("weight of the head records' misfit"));
    c.calibration.record_window = m.number_or("record_window", 0.0, non_negative("time in s (0: the pulse and two round trips)"));
    c.calibration.bound = m.number_or("bound", 10.0, {"a factor above 1", [](double x) { return x > 1.0; }});
    c.calibration.regularisation =
        m.number_or("regularisation", 0.01, non_negative("weight of sum ln(factor)^2 (the pull toward the start)"));
    c.calibration.max_evaluations = m.integer_or("max_evaluations", 300, 1);
    const int line = m.line_of("runs");
    const YAML::Node runs = m.raw("runs");
    if (!runs.IsSequence() || runs.size() == 0)
        throw CaseError(m.file(), line, m.path() + ".runs", "a list of output folders of coupled driving runs", describe(runs));
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const std::string where = m.path() + ".runs[" + std::to_string(i) + "]";
        if (!runs[i].IsScalar()) throw CaseError(m.file(), line, where, "a folder", describe(runs[i]));
        fs::path folder(runs[i].Scalar());
        if (folder.is_relative()) folder = fs::path(m.file()).parent_path() / folder;
        c.calibration_targets.push_back(read_coupled_run(folder.string(), skip, m.file(), runs[i].Mark().line + 1, where));
    }
    m.finish();
}

// The hammer energy against depth: a table (depth, energy) or the columns of a driving
// log; energies are fractions of the rated energy, or multiples of `reference_energy` (J).
void read_energy_plan(MapReader m, DrivabilityCase& c) {
    std::vector<double> depth, energy;
    if (m.has("file")) {
        const std::string path = case_relative_file(m, "file");
        const HeaderedCsv t = read_headered_csv(path);
        const std::string dcol = m.text_or("depth_column", "depth_m");
        const std::string ecol = m.text_or("energy_column", "energy_fraction");
        for (const auto& col : {dcol, ecol})
            if (t.column(col) < 0) m.fail(col == dcol ? "depth_column" : "energy_column",
                                          "a column of " + path, "'" + col + "'");
        const std::string loc = m.text_or("location", "");
        const int lc = t.column("location");
        if (!loc.empty() && lc < 0) m.fail("location", "a records file with a location column");
        const auto d = t.numbers(dcol), e = t.numbers(ecol);
        for (std::size_t r = 0; r < d.size(); ++r) {
            if (!loc.empty() && t.rows[r][static_cast<std::size_t>(lc)] != loc) continue;
            if (std::isnan(d[r]) || std::isnan(e[r])) continue;  // not driven there
            depth.push_back(d[r]);
            energy.push_back(e[r]);
        }
        c.energy_plan_source = path + (loc.empty() ? "" : " (" + loc + ")") + ", column " + ecol;
    } else {
        depth = m.numbers("depth", non_negative("depth in m"));
        energy = m.numbers("energy", positive("an energy"));
        c.energy_plan_source = "table in the case file";
    }
    if (depth.size() != energy.size() || depth.empty())
        m.fail("energy", "as many energies as depths, at least one", std::to_string(energy.size()) + " for " +
                                                                        std::to_string(depth.size()) + " depths");
    for (std::size_t i = 1; i < depth.size(); ++i)
        if (!(depth[i] > depth[i - 1])) m.fail("depth", "depths that increase", std::to_string(depth[i]) + " m");
    const double reference = m.number_or("reference_energy", 0.0, non_negative("energy in J"));
    if (reference > 0.0 && !(c.rated_energy > 0.0))
        m.fail("reference_energy", "a hammer with a rated energy (a ram and a drop height)");
    for (double& e : energy) {
        if (reference > 0.0) e *= reference / c.rated_energy;
        if (!(e > 0.0 && e <= 2.0))
            m.fail("energy", "fractions of the rated energy in (0, 2]", std::to_string(e));
    }
    c.energy_plan_depth = depth;
    c.energy_plan_level = energy;
    m.finish();
}

void read_driving(MapReader m, DrivabilityCase& c) {
    const double L = c.length();
    if (!c.study_mode || m.has("final_depth"))
        c.final_depth = m.number("final_depth", {"a depth within the pile length (" + std::to_string(L) + " m)",
                                                 [L](double d) { return d > 0.0 && d < L; }});
    if (!c.study_mode)
        c.start_depth = m.number_or("start_depth", -1.0, {"a depth above the final depth",
                                                          [fd = c.final_depth](double d) { return d >= 0.0 && d < fd; }});
    c.depth_step = m.number_or("depth_step", 0.25, positive("depth step in m"));
    if (m.has("energy_levels"))
        c.energy_levels = m.numbers("energy_levels", in_half_open_range(0.0, 2.0, "a fraction of the hammer energy"));
    if (auto plan = m.optional_map("energy_plan")) {
        if (c.study_mode) plan->fail("file", "no energy plan in a study (it comes from each location's record)");
        read_energy_plan(std::move(*plan), c);
    }
    c.refusal_blow_count = m.number_or("refusal_blow_count", 250.0, positive("blows per 0.25 m"));
    c.hard_driving_blow_count = m.number_or("hard_driving_blow_count", 75.0, positive("blows per 0.25 m"));
    c.max_blows = m.integer_or("max_blows", 8, 2);
    c.steady_tolerance = m.number_or("steady_tolerance", 0.05, in_open_range(0.0, 1.0, "a relative change"));
    c.threads = m.integer_or("threads", 0, 0);
    m.finish();
}

}  // namespace

std::string read_analysis_kind(const std::string& file) {
    MapReader root = load_yaml_file(file);
    return root.choice("analysis", kAnalyses);
}

void read_study(MapReader m, DrivabilityCase& c) {
    DrivabilityStudy& s = c.study;
    s.records = case_relative_file(m, "records");
    if (m.has("locations")) {
        const YAML::Node n = m.raw("locations");
        if (!n.IsSequence() || n.size() == 0) m.fail("locations", "a list of location codes");
        for (const auto& x : n) s.locations.push_back(x.as<std::string>());
    }
    try {
        read_field_records(s.records, s.locations);
    } catch (const CaseError& e) {
        m.fail("records", "a field records file holding the locations", e.what());
    }
    s.stick_up = m.number_or("stick_up", 10.0, non_negative("length in m"));
    s.split_depth = m.number_or("split_depth", 0.0, non_negative("depth in m"));
    s.reference_energy = m.number("reference_energy", positive("energy in J"));
    if (!(c.rated_energy > 0.0)) m.fail("reference_energy", "a hammer with a rated energy (a ram and a drop height)");
    if (auto cal = m.optional_map("calibration")) {
        s.calibration_location = cal->text_or("location", "");
        if (s.calibration_location.empty()) cal->fail("location", "the location the reference energy is fitted on");
        s.calibration_soil_case = cal->text_or("soil_case", "best_estimate");
        s.calibration_low = cal->number("low", positive("energy in J"));
        s.calibration_high = cal->number("high", {"an energy above low", [lo = s.calibration_low](double x) { return x > lo; }});
        cal->finish();
    }
    if (auto band = m.optional_map("band")) {
        s.lower_case = band->text_or("lower", s.lower_case);
        s.upper_case = band->text_or("upper", s.upper_case);
        band->finish();
    }
    m.finish();
}

// The study's soil cases must include those its calibration and band name.
void check_study_cases(MapReader& root, const DrivabilityCase& c) {
    auto has = [&c](const std::string& n) {
        return std::any_of(c.cases.begin(), c.cases.end(), [&n](const auto& k) { return k.name == n; });
    };
    const DrivabilityStudy& s = c.study;
    for (const auto& n : {s.lower_case, s.upper_case, s.calibration_location.empty() ? s.lower_case : s.calibration_soil_case})
        if (!has(n)) root.fail("soil_cases", "a soil case named '" + n + "' (the study's band or calibration uses it)");
}

DrivabilityCase read_drivability_case(const std::string& file) {
    MapReader root = load_yaml_file(file);
    DrivabilityCase c;
    c.study_mode = root.has("analysis") && root.text_or("analysis", "") == "drivability_study";
    read_case_header(root, c, file, c.study_mode ? "drivability_study" : "drivability");
    {
        MapReader pile = root.map("pile");
        if (pile.has("model") && pile.choice("model", {"rod", "axisymmetric"}) != "rod")
            pile.fail("model", "rod (the wave-equation drivability uses the rod pile)", "axisymmetric");
        read_pile_section(std::move(pile), c, c, false);
    }
    read_hammer_section(root.map("hammer"), c, c);
    read_soil(root.map("soil"), c);
    if (auto s = root.optional_map("smith")) read_smith(std::move(*s), c);
    else c.smith.shaft_damping = c.sand_shaft_damping;
    if (auto k = root.optional_map("srd")) {
        c.coefficients.stevens_k_lower = k->number_or("stevens_k_lower", 0.5, positive("earth pressure coefficient"));
        c.coefficients.stevens_k_upper = k->number_or("stevens_k_upper", 0.7, positive("earth pressure coefficient"));
        c.coefficients.alm_hamre_sand_inside = k->number_or("alm_hamre_sand_inside_share", 0.5, non_negative("share"));
        c.coefficients.alm_hamre_sand_outside = k->number_or("alm_hamre_sand_outside_share", 0.5, non_negative("share"));
        c.coefficients.unified_inside_share = k->number_or("unified_inside_share", 1.0, non_negative("share"));
        c.coefficients.unified_clay_shaft_factor = k->number_or("unified_clay_shaft_factor", 1.0, positive("factor F_st"));
        c.coefficients.toe_averaging_diameters =
            k->number_or("toe_averaging_diameters", 1.5, non_negative("half-width of the toe zone in diameters"));
        k->finish();
    }
    read_cases(root, c);
    read_driving(root.map("driving"), c);
    if (c.study_mode) {
        read_study(root.map("study"), c);
        check_study_cases(root, c);
    }
    if (auto cal = root.optional_map("calibration")) {
        if (c.study_mode) cal->fail("runs", "no calibration: section in a drivability_study (its study: calibrates the energy)");
        read_calibration(std::move(*cal), c);
    }
    if (auto b = root.optional_map("bearing_graph")) {
        c.bearing_resistances = b->numbers("resistances", positive("ultimate resistance in N"));
        c.bearing_shaft_fraction = b->number_or("shaft_fraction", 0.5,
                                                {"a fraction from 0 to 1", [](double x) { return x >= 0.0 && x <= 1.0; }});
        c.bearing_penetration = b->number_or("penetration", 0.0, non_negative("penetration in m"));
        b->finish();
    }
    if (auto out = root.optional_map("output")) {
        c.plots = out->boolean_or("plots", true);
        out->finish();
    }
    if (auto v = c.study_mode ? root.optional_map("verification") : std::nullopt) {
        // A study is verified on its statistics against the records.
        auto& s = c.study;
        s.verified_case = v->text_or("soil_case", "best_estimate");
        if (std::none_of(c.cases.begin(), c.cases.end(), [&s](const auto& k) { return k.name == s.verified_case; }))
            v->fail("soil_case", "one of the study's soil cases", "'" + s.verified_case + "'");
        s.max_median_abs_ln_ratio = v->number_or("median_abs_ln_ratio", -1.0, positive("an upper bound of median |ln(predicted/measured)|"));
        s.min_median_profile_correlation =
            v->number_or("median_profile_correlation", -2.0, in_open_range(-1.0, 1.0, "a lower bound of the median r"));
        v->finish();
    } else if (auto v = root.optional_map("verification")) {
        c.verification_checks = v->words("checks", kChecks);
        c.verification_depth = v->number_or("depth", 0.0, non_negative("depth in m"));
        c.observed_self_weight_penetration =
            v->number_or("observed_self_weight_penetration", -1.0, non_negative("depth in m"));
        c.observed_tolerance = v->number_or("observed_tolerance", 0.5, positive("depth tolerance in m"));
        c.calibration_tolerance = v->number_or("calibration_tolerance", 0.1, positive("relative tolerance on the sets"));
        if (std::find(c.verification_checks.begin(), c.verification_checks.end(), "calibration_sets") !=
                c.verification_checks.end() && c.calibration_targets.empty())
            v->fail("checks", "a calibration: section for the calibration_sets check", "none");
        const bool blow_count = std::find(c.verification_checks.begin(), c.verification_checks.end(),
                                          "calibrated_blow_count") != c.verification_checks.end();
        if (blow_count && c.calibration_targets.empty())
            v->fail("checks", "a calibration: section for the calibrated_blow_count check", "none");
        if (blow_count) c.reference_drive = read_drive_blow_count(*v, "reference_blow_count");
        c.blow_count_tolerance = v->number_or("blow_count_tolerance", 0.15, positive("relative tolerance on the blows"));
        if (std::find(c.verification_checks.begin(), c.verification_checks.end(), "self_weight_penetration") !=
                c.verification_checks.end() && c.observed_self_weight_penetration < 0.0)
            v->fail("observed_self_weight_penetration", "the observed depth for the self_weight_penetration check");
        v->finish();
    }
    root.finish();
    return c;
}

coupling::DrivabilitySetup build_drivability_setup(const DrivabilityCase& c) {
    coupling::DrivabilitySetup s;
    const fem::PileGeometry geometry = fem::make_pile_geometry(c.segments, c.taper_ratio);
    s.mesh = fem::mesh_rod(geometry, c.element_size);
    s.steel = c.steel;
    s.outer_diameter = c.segments.back().outer_diameter;
    s.wall_thickness = c.segments.back().wall_thickness;
    double volume = 0.0;
    for (std::size_t i = 1; i < geometry.stations.size(); ++i) {
        const auto &a = geometry.stations[i - 1], &b = geometry.stations[i];
        volume += 0.5 * (geometry.area_at(a.z) + geometry.area_at(b.z)) * (b.z - a.z);
    }
    s.pile_mass = volume * c.steel.density;
    s.soil = c.soil;
    s.coefficients = c.coefficients;
    s.cases = c.cases;
    s.smith = c.smith;
    s.sand_shaft_damping = c.sand_shaft_damping;
    s.clay_shaft_damping = c.clay_shaft_damping;
    s.hammer = c.hammer;
    s.ram_element_size = c.element_size;
    s.hammer_weight = c.hammer_mass * c.gravity * (1.0 - 1025.0 / c.steel.density);
    s.energy_levels = c.energy_levels;
    s.energy_plan_depth = c.energy_plan_depth;
    s.energy_plan_level = c.energy_plan_level;
    s.start_depth = c.start_depth;
    s.final_depth = c.final_depth;
    s.depth_step = c.depth_step;
    s.hard_driving_blow_count = c.hard_driving_blow_count;
    s.driving.max_blows = c.max_blows;
    s.driving.steady_tolerance = c.steady_tolerance;
    s.driving.refusal_blow_count = c.refusal_blow_count;
    s.threads = c.threads;
    s.bearing_resistances = c.bearing_resistances;
    s.bearing_shaft_fraction = c.bearing_shaft_fraction;
    s.bearing_penetration = c.bearing_penetration;
    return s;
}

}  // namespace pilempm::io
