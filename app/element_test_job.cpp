#include "app/element_test_job.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "app/verification_runner.hpp"
#include "io/csv_writer.hpp"
#include "io/element_test_case.hpp"
#include "io/json_writer.hpp"
#include "io/plots.hpp"
#include "io/staged_directory.hpp"

namespace fs = std::filesystem;

namespace pilempm::app {

namespace {

using coupling::make_check;
using coupling::VerificationCheck;

struct TestResult {
    const io::ElementTestInput* input;
    std::vector<mpm::ElementRecord> path;
};

Table to_table(const TestResult& r, const mpm::ConstitutiveModel& model) {
    std::vector<std::string> cols = {"axial_strain", "volumetric_strain", "axial_stress_Pa", "lateral_stress_Pa",
                                     "mean_effective_stress_Pa", "deviator_stress_Pa"};
    for (int k = 0; k < model.num_state(); ++k) cols.push_back(model.state_name(k));
    Table t(r.input->name, cols);
    for (const auto& rec : r.path) {
        std::vector<double> row = {rec.axial_strain, rec.volumetric_strain, rec.axial_stress, rec.lateral_stress,
                                   rec.p, rec.q};
        for (int k = 0; k < model.num_state(); ++k) row.push_back(rec.state[k]);
        for (std::size_t c = 0; c < row.size(); ++c) t.data[c].push_back(row[c]);
    }
    return t;
}

const TestResult& first_of(const std::vector<TestResult>& results, const std::string& type, const char* check) {
    for (const auto& r : results)
        if (r.input->type == type) return r;
    throw std::invalid_argument(std::string(check) + " needs a " + type + " test in the case");
}

void require_cam_clay(const io::ElementTestCase& c, const char* check) {
    if (c.material.model != "modified_cam_clay")
        throw std::invalid_argument(std::string(check) + " is the closed form of modified_cam_clay");
}

// The swelling line through the initial state meets the NCL at p_c0: e_N = e0 + lambda ln p_c0
// - kappa ln(p_c0 / p0); the CSL lies (lambda - kappa) ln 2 below the NCL.
std::vector<VerificationCheck> critical_state_drained(const io::ElementTestCase& c, const TestResult& r,
                                                      const std::vector<double>& state0, double p0) {
    require_cam_clay(c, "critical_state_drained");
    const auto& m = c.material;
    const auto& end = r.path.back();
    const double M = m.critical_state_ratio, sr = c.lateral_stress;
    const double pf = 3.0 * sr / (3.0 - M);
    const double eN = state0[1] + m.lambda * std::log(state0[0]) - m.kappa * std::log(state0[0] / p0);
    const double e_cs = eN - (m.lambda - m.kappa) * std::log(2.0) - m.lambda * std::log(end.p);
    return {make_check("drained_final_stress_ratio", end.q / end.p, M, 0.01, true, "q / p' = M at critical state"),
            make_check("drained_final_mean_stress_Pa", end.p, pf, 0.01, true, "p' = 3 sigma'_r / (3 - M)"),
            make_check("drained_final_void_ratio", end.state[1], e_cs, 0.01, true,
                       "e on the CSL: e_N - (lambda - kappa) ln 2 - lambda ln p'")};
}

// At constant volume p_c = p_c0 (p0 / p')^(kappa / (lambda - kappa)), and the path lies on
// the yield surface q^2 = M^2 p' (p_c - p'); it ends at p_c / 2.
std::vector<VerificationCheck> undrained_path(const io::ElementTestCase& c, const TestResult& r,
                                              const std::vector<double>& state0, double p0) {
    require_cam_clay(c, "undrained_path");
    const auto& m = c.material;
    const double M = m.critical_state_ratio, e = m.kappa / (m.lambda - m.kappa);
    // End point: p_c0 (p0 / p)^e = 2 p  ->  p = (p_c0 p0^e / 2)^(1 / (1 + e)).
    const double pf = std::pow(state0[0] * std::pow(p0, e) / 2.0, 1.0 / (1.0 + e));
    double worst = 0.0;
    bool yielded = false;
    for (const auto& rec : r.path) {
        const double pc = state0[0] * std::pow(p0 / rec.p, e);
        if (rec.state[0] > state0[0] * (1.0 + 1e-9)) yielded = true;
        if (yielded) worst = std::max(worst, std::abs(rec.q - M * std::sqrt(std::max(0.0, rec.p * (pc - rec.p)))));
    }
    const auto& end = r.path.back();
    return {make_check("undrained_final_mean_stress_Pa", end.p, pf, 0.01, true, "p' = p_c / 2 at constant volume"),
            make_check("undrained_final_deviator_Pa", end.q, M * pf, 0.01, true, "q = M p'"),
            make_check("undrained_path_max_deviator_error_relative", worst / (M * pf), 0.0, 0.01, false,
                       "max |q - M sqrt(p' (p_c - p'))| / q_f along the yielding path")};
}

}  // namespace

int check_element_test_case(const std::string& file) {
    const io::ElementTestCase c = io::read_element_test_case(file);
    io::make_constitutive_model(c.material);  // parameters validated by the model itself
    std::printf("%s: valid\n  title          %s\n  material       %s\n  tests          %zu\n", file.c_str(),
                c.title.c_str(), c.material.model.c_str(), c.tests.size());
    return 0;
}

int run_element_test_case(const std::string& file, const fs::path& out_dir, bool quiet) {
    const io::ElementTestCase c = io::read_element_test_case(file);
    const auto wall0 = std::chrono::steady_clock::now();
    const auto model = io::make_constitutive_model(c.material);
    // Code convention inside: tension positive; axial = z.
    const double s0[6] = {-c.lateral_stress, -c.lateral_stress, -c.axial_stress, 0, 0, 0};
    std::vector<double> state0(model->num_state(), 0.0);
    model->initialise_state(s0, state0.data());
    const double p0 = (c.axial_stress + 2.0 * c.lateral_stress) / 3.0;

    io::StagedDirectory staged(out_dir);
    std::vector<TestResult> results;
    io::JsonObject summary;
    summary.add("title", c.title).add("case_file", c.file).add("analysis", std::string("element_test"))
        .add("model", c.material.model);
    std::vector<io::JsonObject> tests;
    for (const auto& t : c.tests) {
        mpm::ElementTest test(*model, s0, state0);
        TestResult r{&t, {test.record()}};
        for (const auto& leg : t.legs) test.run(leg, r.path);
        io::write_csv(staged.path() / (t.name + ".csv"), to_table(r, *model));
        const auto& end = r.path.back();
        io::JsonObject o;
        o.add("name", t.name).add("type", t.type).add("file", t.name + ".csv").add("steps", static_cast<double>(r.path.size() - 1))
            .add("final_axial_strain", end.axial_strain).add("final_mean_effective_stress_Pa", end.p)
            .add("final_deviator_stress_Pa", end.q).add("final_volumetric_strain", end.volumetric_strain);
        tests.push_back(o);
        if (!quiet) std::printf("  %-24s %6zu steps  p' %.4g Pa  q %.4g Pa\n", t.name.c_str(), r.path.size() - 1, end.p, end.q);
        results.push_back(std::move(r));
    }
    summary.add("tests", tests).add("wall_time_s", std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count());
    io::write_json(staged.path() / "summary.json", summary);

    bool passed = true;
    if (!c.verification_checks.empty()) {
        std::vector<VerificationCheck> checks;
        for (const auto& name : c.verification_checks) {
            const auto add = name == "critical_state_drained"
                                 ? critical_state_drained(c, first_of(results, "triaxial_drained", name.c_str()), state0, p0)
                                 : undrained_path(c, first_of(results, "triaxial_undrained", name.c_str()), state0, p0);
            checks.insert(checks.end(), add.begin(), add.end());
        }
        io::write_json(staged.path() / "verification.json", verification_json(c, checks, io::JsonObject{}));
        for (const auto& k : checks) {
            passed = passed && k.passed;
            if (!quiet)
                std::printf("  [%s] %-44s computed %-14.6g reference %-14.6g tol %g\n", k.passed ? "pass" : "FAIL",
                            k.name.c_str(), k.computed, k.reference, k.tolerance);
        }
    }
    if (c.plots) {
        std::string note;
        if (!io::make_plots("plot_element_test.py", staged.path(), note) && !quiet) std::printf("  %s\n", note.c_str());
    }
    staged.commit();
    if (!quiet) std::printf("results in %s\n", out_dir.c_str());
    return passed ? 0 : 1;
}

}  // namespace pilempm::app
