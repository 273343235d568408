#include "app/jobs/element_test_job.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "mpm/materials/checks/element_test_checks.hpp"
#include "app/jobs/verification_runner.hpp"
#include "io/writers/csv_writer.hpp"
#include "io/cases/element_test_case.hpp"
#include "io/writers/json_writer.hpp"
#include "io/writers/plots.hpp"
#include "io/writers/staged_directory.hpp"

namespace fs = std::filesystem;

namespace pilempm::app {

namespace {


Table to_table(const mpm::TestResult& r, const mpm::ConstitutiveModel& model) {
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

}  // namespace

int check_element_test_case(const std::string& file) {
    const io::ElementTestCase c = io::read_element_test_case(file);
    mpm::make_constitutive_model(c.material);  // parameters validated by the model itself
    std::printf("%s: valid\n  title          %s\n  material       %s\n  tests          %zu\n", file.c_str(),
                c.title.c_str(), c.material.model.c_str(), c.tests.size());
    return 0;
}

int run_element_test_case(const std::string& file, const fs::path& out_dir, bool quiet) {
    const io::ElementTestCase c = io::read_element_test_case(file);
    const auto wall0 = std::chrono::steady_clock::now();
    const auto model = mpm::make_constitutive_model(c.material);
    // Code convention inside: tension positive; axial = z.
    const double s0[6] = {-c.lateral_stress, -c.lateral_stress, -c.axial_stress, 0, 0, 0};
    std::vector<double> state0(model->num_state(), 0.0);
    model->initialise_state(s0, state0.data());
    const double p0 = (c.axial_stress + 2.0 * c.lateral_stress) / 3.0;

    io::StagedDirectory staged(out_dir);
    std::vector<mpm::TestResult> results;
    io::JsonObject summary;
    summary.add("title", c.title).add("case_file", c.file).add("analysis", std::string("element_test"))
        .add("model", c.material.model);
    std::vector<io::JsonObject> tests;
    for (const auto& t : c.tests) {
        std::vector<double> start = state0;
        if (t.void_ratio > 0.0)
            for (int k = 0; k < model->num_state(); ++k)
                if (std::string(model->state_name(k)) == "void_ratio") start[k] = t.void_ratio;
        mpm::ElementTest test(*model, s0, start);
        mpm::TestResult r{&t, {test.record()}};
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
        const mpm::ElementTestContext ctx{c, *model, results, state0, p0};
        for (const auto& name : c.verification_checks) {
            const auto add = mpm::element_test_checks(name, ctx);
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
