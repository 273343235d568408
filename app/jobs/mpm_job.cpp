#include "app/jobs/mpm_job.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <numbers>

#include "mpm/verification/mpm_checks.hpp"
#include "io/writers/terminal_progress.hpp"
#include "app/jobs/verification_runner.hpp"
#include "core/table.hpp"
#include "io/writers/csv_writer.hpp"
#include "io/writers/json_writer.hpp"
#include "io/cases/mpm_case.hpp"
#include "io/hdf5/mpm_checkpoint.hpp"
#include "io/writers/staged_directory.hpp"
#include "io/writers/vtk_particle_writer.hpp"
#include "mpm/analysis/granular_collapse.hpp"
#include "mpm/materials/mohr_coulomb.hpp"
#include "mpm/solver/mpm_solver.hpp"

namespace pilempm::app {

namespace fs = std::filesystem;

namespace {

volatile std::sig_atomic_t g_interrupted = 0;
extern "C" void on_interrupt(int) { g_interrupted = 1; }

// Ctrl-C and a batch system's SIGTERM (a job at its time limit) both end the run with a
// checkpoint to resume from; the previous handlers come back when the run ends.
struct InterruptHandlers {
    using Handler = void (*)(int);
    Handler previous_int, previous_term;
    InterruptHandlers() : previous_int(std::signal(SIGINT, on_interrupt)), previous_term(std::signal(SIGTERM, on_interrupt)) {}
    ~InterruptHandlers() {
        std::signal(SIGINT, previous_int);
        std::signal(SIGTERM, previous_term);
    }
    InterruptHandlers(const InterruptHandlers&) = delete;
    InterruptHandlers& operator=(const InterruptHandlers&) = delete;
};

template <int D>
bool in_region(const io::MpmRegionInput& r, const double* x) {
    if (r.kind == io::MpmRegionInput::Cylinder) {
        const double dx = x[0] - r.centre[0], dy = x[1] - r.centre[1];
        return dx * dx + dy * dy <= r.radius * r.radius && x[D - 1] >= r.centre[D - 1] &&
               x[D - 1] <= r.centre[D - 1] + r.height;
    }
    for (int d = 0; d < D; ++d)
        if (x[d] < r.box.min[d] || x[d] > r.box.max[d]) return false;
    return true;
}

template <int D>
bool in_box(const io::MpmBox& b, const double* x) {
    for (int d = 0; d < D; ++d)
        if (x[d] < b.min[d] - 1e-12 || x[d] > b.max[d] + 1e-12) return false;
    return true;
}

// A pressure's force on each loaded point: -p n x the point's face area on that face.
struct PointLoad {
    mpm::SurfaceLoad load;
    double duration;
};

template <int D>
struct MpmRun {
    mpm::MpmModel<D> model;
    std::vector<PointLoad> loads;
    std::vector<int> probe_points;
    std::vector<double> x0;
    std::vector<int> reaction_nodes;
};

template <int D>
MpmRun<D> build(const io::MpmCase& c) {
    MpmRun<D> run;
    auto& m = run.model;
    for (int d = 0; d < D; ++d) {
        m.grid.origin[d] = c.origin[d];
        m.grid.cells[d] = c.cells[d];
        m.grid.spacing[d] = c.size[d] / c.cells[d];
    }
    m.grid.allocate();
    m.shape = c.shape;
    m.axisymmetric = c.axisymmetric;
    m.gravity[D - 1] = -c.gravity;
    m.flip = c.flip;
    m.apic = c.apic;
    m.cfl = c.cfl;
    int stride = 0;
    for (const auto& mat : c.materials) {
        m.materials.push_back(mpm::make_constitutive_model(mat));
        stride = std::max(stride, m.materials.back()->num_state());
    }
    m.particles.state_stride = stride;
    for (std::size_t k = 0; k < c.regions.size(); ++k) {
        const auto& r = c.regions[k];
        // The first region that holds a point owns it.
        auto inside = [&](const double* x) {
            if (!in_region<D>(r, x)) return false;
            for (std::size_t j = 0; j < k; ++j)
                if (in_region<D>(c.regions[j], x)) return false;
            return true;
        };
        mpm::fill_region<D>(m.grid, m.particles, inside, c.per_cell, c.materials[r.material].density, r.material,
                            c.axisymmetric);
    }
    if (m.particles.size() == 0) throw std::runtime_error("the regions hold no material points");
    for (const auto& b : c.boundaries) {
        // Absorbing boundaries take the first material's moduli (a pressure-dependent model
        // states them at its reference pressure).
        const auto& mat = c.materials.front();
        const double G = m.materials.front()->shear_modulus(), M = m.materials.front()->p_wave_modulus();
        mpm::apply_boundary<D>(m.grid, b.axis, b.side, b.kind, mat.density, std::sqrt(M / mat.density),
                               std::sqrt(G / mat.density), c.axisymmetric, b.friction);
    }
    auto& p = m.particles;
    for (const auto& pr : c.pressures)
        for (std::size_t i = 0; i < p.size(); ++i) {
            if (!in_box<D>(pr.box, &p.x[D * i])) continue;
            double area = 1.0;
            for (int d = 0; d < D; ++d)
                if (d != pr.normal_axis) area *= p.domain0[D * D * i + D * d + d];
            // Per radian the face's area scales with its own radius (the particle's face,
            // not its centre, when the face is normal to r).
            if (c.axisymmetric)
                area *= p.x[D * i] + (pr.normal_axis == 0 ? 0.5 * pr.normal_sign * p.domain0[0] : 0.0);
            PointLoad load{{}, pr.duration};
            load.load.point = static_cast<int>(i);
            load.load.force[pr.normal_axis] = -pr.pressure * pr.normal_sign * area;
            load.load.offset[pr.normal_axis] = 0.5 * pr.normal_sign * p.domain0[D * D * i + D * pr.normal_axis + pr.normal_axis];
            run.loads.push_back(load);
        }
    for (const auto& v : c.velocities)
        for (int n = 0; n < m.grid.num_nodes(); ++n) {
            const auto ijk = m.grid.ijk(n);
            double x[D];
            for (int d = 0; d < D; ++d) x[d] = m.grid.coordinate(d, ijk[d]);
            if (!in_box<D>(v.box, x)) continue;
            for (int d = 0; d < D; ++d)
                if (v.components[d]) {
                    m.grid.fixed[D * n + d] = 1;
                    m.grid.prescribed[D * n + d] = v.velocity[d];
                }
            run.reaction_nodes.push_back(n);
        }
    if (c.k0_initial_stress) {
        auto material_at = [&](double z) -> const io::MpmMaterialInput& {
            for (const auto& r : c.regions)
                if (r.kind != io::MpmRegionInput::Cylinder && z >= r.box.min[D - 1] && z <= r.box.max[D - 1])
                    return c.materials[r.material];
            return c.materials.front();
        };
        mpm::apply_k0_stress<D>(p, c.surface, c.gravity, [&](double z) { return material_at(z).density; },
                                [&](double z) { return mpm::k0_of(material_at(z)); });
    }
    for (std::size_t i = 0; i < p.size(); ++i)
        m.materials[p.material[i]]->initialise_state(&p.stress[6 * i], p.state.data() + p.state_stride * i);
    for (const auto& probe : c.probes) {
        int best = 0;
        double d2best = 1e300;
        for (std::size_t i = 0; i < p.size(); ++i) {
            double d2 = 0.0;
            for (int d = 0; d < D; ++d) d2 += (p.x[D * i + d] - probe[d]) * (p.x[D * i + d] - probe[d]);
            if (d2 < d2best) d2best = d2, best = static_cast<int>(i);
        }
        run.probe_points.push_back(best);
    }
    run.x0 = p.x;
    return run;
}

template <int D>
void apply_loads(MpmRun<D>& run, double time, bool held_only) {
    auto& active = run.model.surface_loads;
    active.clear();
    for (const auto& l : run.loads)
        if (l.duration <= 0.0 || (!held_only && time < l.duration)) active.push_back(l.load);
}

template <int D>
double elastic_energy(const mpm::Particles<D>& p) {
    double e = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
        for (int k = 0; k < 6; ++k) e += 0.5 * p.stress[6 * i + k] * p.strain[6 * i + k] * p.volume[i];
    return e;
}

// The case's quasi-static stages run with no output: used to rerun a case with another
// shape function for the stress-noise comparison.
template <int D>
MpmRun<D> run_quietly(const io::MpmCase& c) {
    MpmRun<D> run = build<D>(c);
    mpm::MpmSolver<D> solver(run.model);
    for (const auto& st : c.stages) {
        if (!st.quasi_static) throw std::invalid_argument("stress_noise reruns quasi-static stages only");
        run.model.local_damping = st.local_damping;
        run.model.flip = 1.0;  // as in the job's quasi-static stages
        run.model.apic = false;
        for (long n = 0; n < st.max_steps; ++n) {
            apply_loads(run, 0.0, true);
            solver.step(solver.stable_time_step());
            if (n >= 100 && solver.unbalanced_force_ratio() < st.tolerance) break;
        }
    }
    return run;
}

std::string fingerprint(const io::MpmCase& c) {
    return c.file + "|" + std::to_string(c.dimension) + "|" + std::to_string(c.cells[0]) + "x" +
           std::to_string(c.cells[1]) + "x" + std::to_string(c.cells[2]) + "|" + std::to_string(c.stages.size());
}

template <int D>
int run_dimension(const io::MpmCase& c, const fs::path& out_dir, bool quiet, bool resume) {
    const auto wall0 = std::chrono::steady_clock::now();
    MpmRun<D> run = build<D>(c);
    auto& m = run.model;
    io::StagedDirectory staged(out_dir, resume);
    const fs::path checkpoint = staged.path() / "checkpoint.h5";
    std::size_t first_stage = 0;
    double resumed_time = 0.0, resumed_stage_start = -1.0;
    long resumed_steps = 0;
    if (resume) {
        if (!staged.adopted() || !fs::exists(checkpoint))
            throw std::runtime_error("nothing to resume: no checkpoint in " + staged.incomplete_path().string());
        const auto info = io::read_checkpoint<D>(checkpoint, m.particles);
        if (info.case_fingerprint != fingerprint(c))
            throw std::runtime_error("the checkpoint in " + staged.incomplete_path().string() + " belongs to another case");
        for (const auto& [name, value] : info.scalars)
            if (name == "stage") first_stage = static_cast<std::size_t>(value);
            else if (name == "stage_start_time") resumed_stage_start = value;
        resumed_time = info.time;
        resumed_steps = info.step;
        if (!quiet) std::fprintf(stderr, "resuming at stage %zu, t = %g s, step %ld\n", first_stage + 1, info.time, info.step);
    }
    mpm::MpmSolver<D> solver(m);
    solver.set_time(resumed_time, resumed_steps);
    // State arrays are named after the material that has the most of them.
    const mpm::ConstitutiveModel* named = m.materials.front().get();
    for (const auto& mat : m.materials)
        if (mat->num_state() > named->num_state()) named = mat.get();
    std::vector<std::string> state_names;
    for (int k = 0; k < m.particles.state_stride; ++k) state_names.push_back(named->state_name(k));
    fs::create_directories(staged.path() / "vtk");
    io::ParticleVtkSeries<D> vtk(staged.path() / "vtk", "particles", state_names);

    std::vector<std::string> columns = {"time_s", "step", "stage", "kinetic_energy_J", "elastic_energy_J",
                                        "absorbed_energy_J", "unbalanced_force_ratio"};
    const char* axis = "xyz";
    for (int d = 0; d < D; ++d) columns.push_back(std::string("reaction_") + axis[d] + "_N");
    for (std::size_t k = 0; k < run.probe_points.size(); ++k) {
        columns.push_back("probe" + std::to_string(k) + "_velocity_vertical_m_s");
        columns.push_back("probe" + std::to_string(k) + "_stress_vertical_Pa");
    }
    Table history("history", columns);
    auto record = [&](std::size_t stage) {
        std::vector<double> row = {solver.time(), static_cast<double>(solver.steps()), static_cast<double>(stage + 1),
                                   solver.kinetic_energy(), elastic_energy(m.particles), solver.absorbed_energy(),
                                   solver.unbalanced_force_ratio()};
        for (int d = 0; d < D; ++d) {
            double r = 0.0;
            for (int n : run.reaction_nodes) r += m.grid.reaction[D * n + d];
            row.push_back(r);
        }
        for (int pnt : run.probe_points) {
            row.push_back(m.particles.v[D * pnt + D - 1]);
            row.push_back(m.particles.stress[6 * pnt + (D == 2 ? 1 : 2)]);
        }
        for (std::size_t k = 0; k < row.size(); ++k) history.data[k].push_back(row[k]);
    };

    g_interrupted = 0;
    const InterruptHandlers interrupt_handlers;
    // Test hook: send this process a signal (SIGINT, or PILEMPM_INTERRUPT_SIGNAL) once this
    // many steps are done, so the handlers themselves are exercised.
    long interrupt_after = -1;
    if (const char* e = std::getenv("PILEMPM_INTERRUPT_AFTER_STEPS")) interrupt_after = std::atol(e);
    int interrupt_signal = SIGINT;
    if (const char* e = std::getenv("PILEMPM_INTERRUPT_SIGNAL")) interrupt_signal = std::atoi(e);
    auto check_interrupt = [&] {
        if (interrupt_after >= 0 && solver.steps() >= interrupt_after && !resume && !g_interrupted)
            std::raise(interrupt_signal);
    };
    double stage_start = solver.time();
    auto save = [&](std::size_t stage) {
        io::write_checkpoint<D>(checkpoint, m.particles, solver.time(), solver.steps(),
                                {{"stage", static_cast<double>(stage)}, {"stage_start_time", stage_start}},
                                fingerprint(c));
        staged.keep_if_failed();
    };
    double next_snapshot = c.snapshot_interval;
    vtk.write(solver.time(), m.particles);
    for (std::size_t s = first_stage; s < c.stages.size(); ++s) {
        const auto& st = c.stages[s];
        // A resumed stage keeps the start time it had, so it ends when it would have.
        stage_start = (s == first_stage && resumed_stage_start >= 0.0) ? resumed_stage_start : solver.time();
        io::TerminalProgress progress("mpm stage '" + st.name + "'", !quiet);
        m.local_damping = st.local_damping;
        if (st.quasi_static) {
            // Pseudo-time: the clock stands still, held loads only, until equilibrium. The
            // local damping is the dissipation: PIC's velocity projection would fight it (pure
            // PIC never settles), so the stage runs pure FLIP.
            const double t_keep = solver.time();
            const double flip_keep = m.flip;
            const bool apic_keep = m.apic;
            m.flip = 1.0;
            m.apic = false;
            long n = 0;
            for (; n < st.max_steps; ++n) {
                apply_loads(run, 0.0, true);
                solver.step(solver.stable_time_step());
                if (n % 10 == 0) record(s);
                if (n >= 100 && solver.unbalanced_force_ratio() < st.tolerance) break;
                if (c.checkpoint_every > 0 && solver.steps() % c.checkpoint_every == 0) save(s);
                check_interrupt();
                if (g_interrupted) break;
                progress.update_count(n, st.max_steps, "steps (quasi-static)");
            }
            progress.done();
            m.flip = flip_keep;
            m.apic = apic_keep;
            std::fill(m.particles.v.begin(), m.particles.v.end(), 0.0);  // a nil step: start at rest
            std::fill(m.particles.C.begin(), m.particles.C.end(), 0.0);
            solver.set_time(t_keep, solver.steps());
            if (!quiet)
                std::printf("stage '%s': %ld steps, unbalanced force ratio %.3g (tolerance %.3g)%s\n", st.name.c_str(),
                            n, solver.unbalanced_force_ratio(), st.tolerance,
                            solver.unbalanced_force_ratio() < st.tolerance ? "" : "  NOT IN EQUILIBRIUM");
        } else {
            const double t_end = stage_start + st.duration;
            while (solver.time() < t_end - 1e-15 && !g_interrupted) {
                apply_loads(run, solver.time(), false);
                const double dt = std::min(solver.stable_time_step(), t_end - solver.time());
                solver.step(dt);
                record(s);
                if (c.snapshot_interval > 0.0 && solver.time() >= next_snapshot - 1e-12) {
                    vtk.write(solver.time(), m.particles);
                    next_snapshot += c.snapshot_interval;
                }
                if (c.checkpoint_every > 0 && solver.steps() % c.checkpoint_every == 0) save(s);
                check_interrupt();
                progress.update(solver.time(), t_end, solver.steps());
            }
            progress.done();
        }
        if (g_interrupted) {
            save(s);
            std::fprintf(stderr, "pilempm: interrupted; resume with --resume (checkpoint kept in %s)\n",
                         staged.incomplete_path().c_str());
            return 130;
        }
        vtk.write(solver.time(), m.particles);
        save(s + 1);
    }
    vtk.finish();
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
            const MpmRun<D> reference = run_quietly<D>(linear);
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
        auto run = build<2>(c);
        mpm::MpmSolver<2> solver(run.model);
        std::printf("  MPM            2D %s, %zu material points, %d grid nodes, dt %.3g s\n",
                    c.axisymmetric ? "axisymmetric" : "plane strain", run.model.particles.size(),
                    run.model.grid.num_nodes(), solver.stable_time_step());
    } else {
        auto run = build<3>(c);
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
