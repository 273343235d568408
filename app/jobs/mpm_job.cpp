#include "app/jobs/mpm_job.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>

#include "app/jobs/verification_runner.hpp"
#include "core/table.hpp"
#include "coupling/driver/stage_driver.hpp"
#include "io/cases/mpm_case.hpp"
#include "io/cases/mpm_run_builder.hpp"
#include "io/hdf5/run_checkpoint.hpp"
#include "io/writers/csv_writer.hpp"
#include "io/writers/json_writer.hpp"
#include "io/writers/mpm_run_output.hpp"
#include "io/writers/staged_directory.hpp"
#include "mpm/analysis/granular_collapse.hpp"
#include "mpm/verification/mpm_checks.hpp"

namespace pilempm::app {

namespace fs = std::filesystem;

namespace {

// The case's quasi-static stages run again with no output: used to rerun a case with
// another shape function for the stress-noise comparison.
template <int D>
io::MpmRun<D> run_quietly(const io::MpmCase& c) {
    io::MpmRun<D> run = io::build_mpm_run<D>(c);
    for (const auto& st : run.stages)
        if (!st.quasi_static) throw std::invalid_argument("stress_noise reruns quasi-static stages only");
    coupling::StageDriver<D> driver(run.model, run.stages, run.loads, run.settings);
    driver.run();
    return run;
}

std::string fingerprint(const io::MpmCase& c) {
    return c.file + "|" + std::to_string(c.dimension) + "|" + std::to_string(c.cells[0]) + "x" +
           std::to_string(c.cells[1]) + "x" + std::to_string(c.cells[2]) + "|" + std::to_string(c.stages.size());
}

template <int D>
int run_dimension(const io::MpmCase& c, const fs::path& out_dir, bool quiet, bool resume) {
    const auto wall0 = std::chrono::steady_clock::now();
    io::MpmRun<D> run = io::build_mpm_run<D>(c);
    auto& m = run.model;
    io::StagedDirectory staged(out_dir, resume);
    io::RunCheckpoint restored;
    if (resume) {
        const fs::path file = staged.path() / "checkpoint.h5";
        if (!staged.adopted() || !fs::exists(file))
            throw std::runtime_error("nothing to resume: no checkpoint in " + staged.incomplete_path().string());
        restored = io::read_run_checkpoint<D>(file, m.particles);
        if (restored.case_fingerprint != fingerprint(c))
            throw std::runtime_error("the checkpoint in " + staged.incomplete_path().string() + " belongs to another case");
        if (!quiet)
            std::fprintf(stderr, "resuming at stage %d, t = %g s, step %ld\n", restored.driver.stage + 1, restored.time,
                         restored.steps);
    }
    io::MpmRunOutput<D> output(staged, io::state_names(m), fingerprint(c), quiet);
    coupling::StageDriver<D> driver(m, run.stages, run.loads, run.settings, &output);
    driver.add_recorder(std::make_unique<coupling::EnergyRecorder<D>>());
    driver.add_recorder(std::make_unique<coupling::ReactionRecorder<D>>(run.reaction_nodes));
    driver.add_recorder(std::make_unique<coupling::ProbeRecorder<D>>(run.probe_points));
    if (resume) {
        output.adopt_snapshots(restored.snapshot_times);
        driver.resume(restored.driver, restored.time, restored.steps, restored.absorbed_energy, restored.history);
    }
    const coupling::StopRequest stop(!resume);
    if (driver.run(&stop) == coupling::StageDriver<D>::Outcome::Stopped) {
        std::fprintf(stderr, "pilempm: interrupted; resume with --resume (checkpoint kept in %s)\n",
                     staged.incomplete_path().c_str());
        return 130;
    }
    const auto& solver = driver.solver();
    const Table& history = driver.history();
    const long resumed_steps = resume ? restored.steps : 0;
    output.finish();
    io::write_csv(staged.path() / "history.csv", history);
    if constexpr (D == 2) {
        // A collapse's final deposit, one row per grid column, for comparison with profiles.
        if (std::find(c.verification_checks.begin(), c.verification_checks.end(), "granular_runout") !=
            c.verification_checks.end()) {
            const auto thickness = mpm::deposit_profile(m);
            Table profile("deposit_profile", {c.axisymmetric ? "r_centre_m" : "x_centre_m", "thickness_m"});
            for (std::size_t k = 0; k < thickness.size(); ++k)
                profile.add_row({m.grid.coordinate(0, static_cast<int>(k)) + 0.5 * m.grid.spacing[0], thickness[k]});
            io::write_csv(staged.path() / "deposit_profile.csv", profile);
        }
    }

    io::JsonObject summary;
    summary.add("title", c.title).add("case_file", c.file).add("analysis", std::string("mpm"))
        .add("dimension", static_cast<double>(D))
        .add("geometry", std::string(D == 3 ? "3d" : c.axisymmetric ? "axisymmetric" : "plane_strain"))
        .add("material_points", static_cast<double>(m.particles.size()))
        .add("grid_nodes", static_cast<double>(m.grid.num_nodes())).add("steps", static_cast<double>(solver.steps()))
        .add("simulated_time_s", solver.time());
    {
        // Throughput of this invocation (a resumed run counts only the steps it took).
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
        const double steps_here = static_cast<double>(solver.steps() - resumed_steps);
        summary.add("wall_time_s", wall)
            .add("particle_steps_per_s", wall > 0.0 ? steps_here * static_cast<double>(m.particles.size()) / wall : 0.0);
    }
    {
        // Where the material ended up: run-out, heave and settlement read off the extent.
        std::vector<double> lo(D, 1e300), hi(D, -1e300);
        for (std::size_t i = 0; i < m.particles.size(); ++i)
            for (int d = 0; d < D; ++d) {
                lo[d] = std::min(lo[d], m.particles.x[D * i + d]);
                hi[d] = std::max(hi[d], m.particles.x[D * i + d]);
            }
        summary.add("extent_min_m", lo).add("extent_max_m", hi);
    }
    if (!c.verification_checks.empty()) {
        const mpm::MpmCheckContext context{c.verification_checks, c.verification, c.gravity,
                                           c.materials.front().density};
        auto checks = mpm::run_mpm_verification<D>(context, m, run.x0, history);
        if (std::find(c.verification_checks.begin(), c.verification_checks.end(), "stress_noise") !=
            c.verification_checks.end()) {
            io::MpmCase linear = c;
            linear.shape = mpm::ShapeKind::Linear;
            const io::MpmRun<D> reference = run_quietly<D>(linear);
            const double noise = mpm::stress_noise<D>(context, m, run.x0);
            const double noise_linear = mpm::stress_noise<D>(context, reference.model, reference.x0);
            auto k = make_check("stress_noise_over_linear", noise / noise_linear, 0.0, 1.0, false,
                                          "RMS error of the vertical stress against the linear-shape-function run");
            k.passed = noise < noise_linear;
            checks.push_back(k);
            summary.add("stress_noise_rms_relative", noise).add("stress_noise_rms_relative_linear", noise_linear);
        }
        io::write_json(staged.path() / "verification.json", verification_json(c, checks, io::JsonObject{}));
        if (!quiet)
            for (const auto& k : checks)
                std::printf("  [%s] %-40s computed %-14.6g reference %-14.6g tol %g\n", k.passed ? "pass" : "FAIL",
                            k.name.c_str(), k.computed, k.reference, k.tolerance);
    }
    io::write_json(staged.path() / "summary.json", summary);
    staged.commit();
    if (!quiet)
        std::printf("%s\n  %zu material points, %d grid nodes, %ld steps, t = %.4g s\n  results in %s\n", c.title.c_str(),
                    m.particles.size(), m.grid.num_nodes(), solver.steps(), solver.time(), out_dir.c_str());
    return 0;
}

}  // namespace

int check_mpm_case(const std::string& file) {
    const io::MpmCase c = io::read_mpm_case(file);
    std::printf("%s: valid\n  title          %s\n", file.c_str(), c.title.c_str());
    if (c.dimension == 2) {
        auto run = io::build_mpm_run<2>(c);
        mpm::MpmSolver<2> solver(run.model);
        std::printf("  MPM            2D %s, %zu material points, %d grid nodes, dt %.3g s\n",
                    c.axisymmetric ? "axisymmetric" : "plane strain", run.model.particles.size(),
                    run.model.grid.num_nodes(), solver.stable_time_step());
    } else {
        auto run = io::build_mpm_run<3>(c);
        mpm::MpmSolver<3> solver(run.model);
        std::printf("  MPM            3D, %zu material points, %d grid nodes, dt %.3g s\n", run.model.particles.size(),
                    run.model.grid.num_nodes(), solver.stable_time_step());
    }
    std::printf("  stages         %zu\n", c.stages.size());
    return 0;
}

int run_mpm_case(const std::string& file, const fs::path& out_dir, bool quiet, bool resume) {
    const io::MpmCase c = io::read_mpm_case(file);
    return c.dimension == 2 ? run_dimension<2>(c, out_dir, quiet, resume) : run_dimension<3>(c, out_dir, quiet, resume);
}

}  // namespace pilempm::app
