#include "app/jobs/mpm_job.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <cstdio>
#include <memory>

#include "app/jobs/verification_runner.hpp"
#include "core/table.hpp"
#include "coupling/contact/blow_table.hpp"
#include "coupling/contact/coupled_pile.hpp"
#include "coupling/contact/pile_recorder.hpp"
#include "coupling/contact/unloading_point.hpp"
#include "coupling/driver/stage_driver.hpp"
#include "io/cases/mpm_case.hpp"
#include "io/cases/mpm_run_builder.hpp"
#include "io/hdf5/hdf5_results.hpp"
#include "io/hdf5/history_segments.hpp"
#include "io/hdf5/run_checkpoint.hpp"
#include "io/writers/csv_writer.hpp"
#include "io/writers/json_writer.hpp"
#include "io/writers/mpm_run_output.hpp"
#include "io/writers/staged_directory.hpp"
#include "io/writers/stage_progress.hpp"
#include "mpm/analysis/granular_collapse.hpp"
#include "io/writers/pile_contact_output.hpp"
#include "io/writers/plots.hpp"
#include "io/writers/vtk_pile_writer.hpp"
#include "mpm/verification/mpm_checks.hpp"
#include "mpm/verification/pore_water_checks.hpp"

namespace pilempm::app {

namespace fs = std::filesystem;

namespace {

// The FE pile coupled to the soil through the contact, carried by the soil's stages, its
// history recorded (nothing in 3D: the pile is axisymmetric).
template <int D>
struct AttachedPile {
    std::unique_ptr<fem::ExplicitPile> pile;
    std::unique_ptr<coupling::CoupledPile> coupled;
    // ground: the seabed in the soil's frame (ground_elevation), m.
    AttachedPile(io::MpmRun<D>& run, coupling::StageDriver<D>& driver, double ground) {
        if constexpr (D == 2) {
            if (!run.pile.present) return;
            pile = std::make_unique<fem::ExplicitPile>(run.pile.mesh, run.pile.steel, fem::ToeSupport{});
            coupled = std::make_unique<coupling::CoupledPile>(*pile, run.pile.contact, run.pile.frame, run.pile.gravity,
                                                              run.pile.cut_fields, run.pile.toe_slip_line);
            coupled->set_head_control(run.pile.heads);
            driver.couple(coupled.get());
            driver.add_recorder(std::make_unique<coupling::PileRecorder>(*coupled, ground));
        }
    }
};

// The pile's mesh in the soil's frame (its toe at the frame's toe elevation): for ParaView
// and the results file.
template <int D>
fem::PileMesh placed_pile_mesh(const io::MpmRun<D>& run) {
    fem::PileMesh placed = run.pile.mesh;
    for (int i = 0; i < placed.num_nodes(); ++i) placed.coordinates[2 * i + 1] += run.pile.frame.toe_elevation;
    return placed;
}

// The seabed (m, the soil's frame) that depths count from: the K0 state's surface, else the
// top of the highest material point's domain at the start.
template <int D>
double ground_elevation(const io::MpmCase& c, const io::MpmRun<D>& run) {
    if (c.k0_initial_stress) return c.surface;
    double top = -1e300;
    for (std::size_t k = D - 1; k < run.x0.size(); k += D) top = std::max(top, run.x0[k]);
    return top + 0.5 * run.model.grid.spacing[D - 1] / c.per_cell;
}

// A drive's blows (blows.csv, blow_count.csv) in the stages before `stages_done`, read off
// the history; false when there are none. Written at the end, and at every checkpoint of a
// run in progress (its finished blows).
template <int D>
bool write_drive_tables(const io::MpmCase& c, const io::MpmRun<D>& run, const Table& history, const Table& extremes,
                        const fs::path& dir, std::size_t stages_done, Table* blow_table = nullptr,
                        Table* count_table = nullptr) {
    std::vector<coupling::BlowStage> blows;
    for (std::size_t k = 0; k < std::min(stages_done, c.stages.size()); ++k)
        if (c.stages[k].blow) blows.push_back({static_cast<int>(k) + 1, c.stages[k].blow_number});
    if (blows.empty()) return false;
    const Table table = coupling::blow_table(history, extremes, blows, ground_elevation(c, run));
    const Table count = coupling::blow_count_table(table);
    io::write_csv(dir / "blows.csv", table);
    io::write_csv(dir / "blow_count.csv", count);
    if (blow_table) *blow_table = table;
    if (count_table) *count_table = count;
    return true;
}

// A drive's record (blows.csv, blow_count.csv, blow_wall_times.csv, and results.h5 with the
// pile's mesh and final state): nothing when the case drives no blows.
template <int D>
void write_drive_record(const io::MpmCase& c, const io::MpmRun<D>& run, const Table& history, const Table& extremes,
                        const io::MpmRunOutput<D>& output, const coupling::CoupledPile& coupled,
                        const fs::path& dir) {
    Table table, count;
    if (!write_drive_tables(c, run, history, extremes, dir, c.stages.size(), &table, &count)) return;
    const double ground = ground_elevation(c, run);
    // Wall time per blow and pause of this invocation (not in blows.csv: a resumed run's
    // tables are the uninterrupted one's to the byte).
    Table walls("blow_wall_times", {"stage", "blow", "pause", "wall_time_s"});
    for (const auto& w : output.stage_wall_times()) {
        const auto& st = c.stages[static_cast<std::size_t>(w.stage)];
        if (st.drive >= 0) walls.add_row({w.stage + 1.0, static_cast<double>(st.blow_number), st.blow ? 0.0 : 1.0, w.wall});
    }
    io::write_csv(dir / "blow_wall_times.csv", walls);
    std::vector<double> stress;
    coupled.pile().axial_stress(stress);
    io::write_results_h5(dir / "results.h5", {table, count, history, extremes}, placed_pile_mesh(run), coupled.pile().displacement(),
                         coupled.pile().velocity(), stress, {{"ground_elevation_m", ground}}, {{"title", c.title}});
}

// Each load test's record, load_test_<stage>.csv: a static test's load against the head's
// settlement from the stage's start (the jack's force and the soil's resistance); a rapid
// test's unloading-point analysis (its rows to the unloading point: load, F - m a and the
// derived static force), F_u and C in summary.json. Nothing when the case has none.
void write_load_tests(const io::MpmCase& c, const Table& history, const coupling::CoupledPile& coupled,
                      const fs::path& dir, io::JsonObject& summary) {
    std::vector<io::JsonObject> tests;
    const double mass = coupled.mass();
    for (std::size_t k = 0; k < c.stages.size(); ++k) {
        const auto& st = c.stages[k];
        if (st.load_test.empty()) continue;
        const int stage = static_cast<int>(k) + 1;
        io::JsonObject entry;
        entry.add("stage", st.name).add("type", st.load_test);
        const coupling::RapidLoadRecord record = coupling::rapid_load_record(history, stage);
        if (st.load_test == "static") {
            Table curve("load_test", {"time_s", "settlement_m", "load_N", "soil_resistance_N"});
            const auto& stages = mpm::column(history, "stage");
            const auto& outer = mpm::column(history, "outer_shaft_resistance_N");
            const auto& inner = mpm::column(history, "inner_shaft_resistance_N");
            const auto& base = mpm::column(history, "base_resistance_N");
            std::size_t row = 0;
            for (std::size_t i = 0; i < stages.size(); ++i) {
                if (stages[i] != stage) continue;
                const double soil = outer[i] + inner[i] + base[i];
                curve.add_row({record.time[row], record.settlement[row], record.force[row], soil});
                ++row;
            }
            io::write_csv(dir / ("load_test_" + st.name + ".csv"), curve);
            double peak = 0.0;
            for (double f : record.force) peak = std::max(peak, f);
            entry.add("max_settlement_m", record.settlement.empty() ? 0.0 : record.settlement.back()).add("max_load_N", peak);
        } else {
            try {
                const auto& mesh = coupled.pile().mesh();
                const double period = 2.0 * mesh.z(mesh.head_nodes.front()) / coupled.pile().steel().wave_speed();
                const coupling::UnloadingPointResult u = coupling::unloading_point(record, mass, period);
                io::write_csv(dir / ("load_test_" + st.name + ".csv"), u.curve);
                entry.add("static_resistance_N", u.static_resistance).add("damping_N_s_m", u.damping)
                    .add("max_settlement_m", u.max_settlement).add("unloading_time_s", u.unloading_time)
                    .add("peak_load_N", u.peak_force).add("peak_velocity_m_s", u.peak_velocity).add("pile_mass_kg", mass);
            } catch (const std::invalid_argument& e) {
                entry.add("note", std::string(e.what()) + " (make the stage longer)");
            }
        }
        tests.push_back(entry);
    }
    if (!tests.empty()) summary.add("load_tests", tests);
}

// What the checks read of the case: its parameters and the first material's constants.
mpm::MpmCheckContext check_context(const io::MpmCase& c) {
    const auto& first = c.materials.front();
    return {c.verification_checks, c.verification, c.gravity, first.density, first.model, first.poisson_ratio,
            c.probes,             first.youngs_modulus};
}

// The case on a grid `factor` times finer along every axis (the pile's mesh with it), run
// with no output but progress, and its checks, their names saying the grid; nothing, with
// `stopped` set, when a stop request (SIGINT, SIGTERM) ends the rerun early.
template <int D>
std::vector<VerificationCheck> checks_on_grid(const io::MpmCase& c, const mpm::MpmCheckContext& context,
                                              double factor, std::string& grid, bool quiet,
                                              const coupling::StopRequest* stop, bool& stopped) {
    io::MpmCase refined = c;
    for (int d = 0; d < D; ++d) {
        if (!c.refined_axes[d]) continue;
        if (c.zones[d].empty()) {
            refined.cells[d] = static_cast<int>(std::lround(c.cells[d] * factor));
            continue;
        }
        for (auto& zone : refined.zones[d]) zone.cell /= factor;  // a graded axis: its zones' cells
        refined.cells[d] = static_cast<int>(mpm::graded_axis(c.origin[d], refined.zones[d]).size()) - 1;
    }
    grid = std::to_string(refined.cells[0]);
    for (int d = 1; d < D; ++d) grid.append("x").append(std::to_string(refined.cells[d]));
    if (refined.pile.present) {
        // The pile's mesh refined with the grid.
        refined.pile.pile.element_size /= factor;
        refined.pile.pile.radial_divisions = static_cast<int>(std::lround(c.pile.pile.radial_divisions * factor));
    }
    io::MpmRun<D> run = io::build_mpm_run<D>(refined);
    io::StageProgress<D> progress("grid " + grid + ", ", quiet);
    coupling::StageDriver<D> driver(run.model, run.stages, run.loads, run.settings, &progress);
    driver.add_recorder(std::make_unique<coupling::EnergyRecorder<D>>());
    driver.add_recorder(std::make_unique<coupling::ConservationRecorder<D>>());
    driver.add_recorder(std::make_unique<coupling::ReactionRecorder<D>>(run.reaction_nodes));
    driver.add_recorder(std::make_unique<coupling::ProbeRecorder<D>>(run.probe_points, run.model.saturated()));
    const AttachedPile<D> pile(run, driver, ground_elevation(refined, run));
    stopped = driver.run(stop) == coupling::StageDriver<D>::Outcome::Stopped;
    if (stopped) return {};
    auto checks = mpm::run_mpm_verification<D>(context, run.model, run.x0, driver.history());
    for (auto& k : checks) k.name += "_grid_" + grid;
    return checks;
}

// The observed order of convergence of each error that must converge (the checks of the
// kinds in verification.converging): log(e_coarse / e_fine) / log(h_coarse / h_fine) between
// the coarsest and finest grids, at least verification.min_order (default 0.5).
std::vector<VerificationCheck> convergence_checks(const io::MpmCase& c,
                                                  const std::vector<std::vector<VerificationCheck>>& by_grid,
                                                  const std::vector<double>& factors) {
    std::size_t coarse = 0, fine = 0;
    for (std::size_t k = 1; k < factors.size(); ++k) {
        if (factors[k] < factors[coarse]) coarse = k;
        if (factors[k] > factors[fine]) fine = k;
    }
    const double min_order = c.verification.count("min_order") ? c.verification.at("min_order") : 0.5;
    std::vector<VerificationCheck> out;
    for (std::size_t i = 0; i < by_grid[coarse].size(); ++i) {
        const auto& a = by_grid[coarse][i];
        const auto& b = by_grid[fine][i];
        const std::string base = a.name.substr(0, a.name.find("_grid_"));
        if (std::find(c.converging.begin(), c.converging.end(), base) == c.converging.end()) continue;
        const double ea = std::abs(a.computed - a.reference), eb = std::abs(b.computed - b.reference);
        const double order = std::log(ea / eb) / std::log(factors[fine] / factors[coarse]);
        auto k = make_check(base + "_observed_order", order, min_order, 0.0, false,
                            "order of convergence of the error from the coarsest to the finest grid");
        k.at_least = true;
        k.passed = std::isfinite(order) && order >= min_order;
        out.push_back(k);
    }
    // Self-convergence of the quantities whose limit is not the reference (verification.
    // self_converging): from the three finest grids, refined by the same ratio r,
    // log(|q_2 - q_1| / |q_3 - q_2|) / log r, at least min_order.
    std::vector<std::size_t> order(factors.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return factors[a] < factors[b]; });
    if (order.size() < 3) return out;
    const std::size_t g1 = order[order.size() - 3], g2 = order[order.size() - 2], g3 = order.back();
    for (std::size_t i = 0; i < by_grid[g1].size(); ++i) {
        const std::string base = by_grid[g1][i].name.substr(0, by_grid[g1][i].name.find("_grid_"));
        if (std::find(c.self_converging.begin(), c.self_converging.end(), base) == c.self_converging.end()) continue;
        const double d12 = std::abs(by_grid[g2][i].computed - by_grid[g1][i].computed);
        const double d23 = std::abs(by_grid[g3][i].computed - by_grid[g2][i].computed);
        const double r = factors[g2] / factors[g1];
        const double p = d23 > 0.0 ? std::log(d12 / d23) / std::log(r) : std::numeric_limits<double>::infinity();
        auto k = make_check(base + "_self_convergence_order", p, min_order, 0.0, false,
                            "log(|q2 - q1| / |q3 - q2|) / log(refinement) over the three finest grids");
        k.at_least = true;
        k.passed = !std::isnan(p) && p >= min_order;
        out.push_back(k);
    }
    return out;
}

// What a checkpoint must match to be resumed: the case file's name (not its path as typed,
// so a run resumes from another folder, or with the path spelt otherwise), its dimension,
// cells, number of stages and pile.
std::string fingerprint(const io::MpmCase& c) {
    return fs::path(c.file).filename().string() + "|" + std::to_string(c.dimension) + "|" + std::to_string(c.cells[0]) + "x" +
           std::to_string(c.cells[1]) + "x" + std::to_string(c.cells[2]) + "|" + std::to_string(c.stages.size()) +
           (c.pile.present ? "|pile" : "");
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
            throw std::runtime_error("nothing to resume: no checkpoint in " + staged.incomplete_path().string() +
                                     " nor in a " + staged.final_path().filename().string() +
                                     ".partial-PID folder left by a killed run");
        if (!quiet && staged.adopted_from() != staged.incomplete_path())
            std::fprintf(stderr, "pilempm: resuming from the checkpoint a killed run left in %s\n",
                         staged.adopted_from().c_str());
        restored = io::read_run_checkpoint<D>(file, m.particles);
        if (restored.case_fingerprint != fingerprint(c))
            throw std::runtime_error("the checkpoint in " + staged.path().string() + " belongs to another case (" +
                                     restored.case_fingerprint.substr(0, restored.case_fingerprint.find('|')) +
                                     "), not to " + c.file);
        if (!quiet)
            std::fprintf(stderr, "resuming at stage %d, t = %g s, step %ld\n", restored.driver.stage + 1,
                         restored.solver.time, restored.solver.steps);
    }
    io::MpmRunOutput<D> output(staged, io::state_names(m), fingerprint(c), quiet,
                               static_cast<std::size_t>(c.history_segment_rows));
    if (m.saturated()) {
        std::vector<double> friction;
        for (const auto& mat : c.materials) friction.push_back(mat.friction_angle);
        output.set_pore_water(m.water, friction);
    }
    coupling::StageDriver<D> driver(m, run.stages, run.loads, run.settings, &output);
    driver.add_recorder(std::make_unique<coupling::EnergyRecorder<D>>());
    driver.add_recorder(std::make_unique<coupling::ConservationRecorder<D>>());
    driver.add_recorder(std::make_unique<coupling::ReactionRecorder<D>>(run.reaction_nodes));
    driver.add_recorder(std::make_unique<coupling::ProbeRecorder<D>>(run.probe_points, run.model.saturated()));
    const AttachedPile<D> attached(run, driver, ground_elevation(c, run));
    const auto& pile = attached.pile;
    const auto& coupled = attached.coupled;
    std::unique_ptr<io::PileVtkSeries> pile_vtk;
    if constexpr (D == 2) {
        if (run.pile.present) {
            output.set_body(coupled.get(), ground_elevation(c, run));
            // The pile in ParaView over the soil (its mesh placed in the soil's frame), with
            // its displacements, axial stress and contact forces.
            pile_vtk = std::make_unique<io::PileVtkSeries>(staged.path() / "vtk", placed_pile_mesh(run), "pile");
            output.also_at_snapshots([&pile, &coupled, &pile_vtk](double time) {
                std::vector<double> stress;
                pile->axial_stress(stress);
                const auto& force = coupled->contact().nodal_force();  // none before the first step
                pile_vtk->write(time, pile->displacement(), pile->velocity(), stress,
                                force.empty() ? std::vector<double>(pile->displacement().size(), 0.0) : force);
            });
            if (resume) pile_vtk->adopt_written_steps(restored.snapshot_times);
            // A long drive can be followed: its tables so far beside each checkpoint.
            output.also_at_checkpoints(
                [&c, &run, &staged, &pile_vtk](const coupling::DriverState& state, const Table& history) {
                    write_drive_tables(c, run, history, state.extremes, staged.path(),
                                       static_cast<std::size_t>(state.stage));
                    pile_vtk->finish();
                });
        }
    }
    if (resume) {
        output.adopt_snapshots(restored.snapshot_times);
        output.adopt_history_segments(restored.history_segments);
        driver.resume(restored.driver, restored.solver,
                      io::assemble_history(staged.path(), restored.history_segments, restored.history));
        if constexpr (D == 2)
            if (coupled) coupled->restore(restored.body);
    }
    const coupling::StopRequest stop(!resume);
    if (driver.run(&stop) == coupling::StageDriver<D>::Outcome::Stopped) {
        std::fprintf(stderr, "pilempm: interrupted; resume with --resume (checkpoint kept in %s)\n",
                     staged.incomplete_path().c_str());
        return 130;
    }
    const auto& solver = driver.solver();
    const Table& history = driver.history();
    const long resumed_steps = resume ? restored.solver.steps : 0;
    output.finish();
    if (pile_vtk) pile_vtk->finish();
    io::write_csv(staged.path() / "history.csv", history);
    if constexpr (D == 2)
        if (coupled) {
            for (const auto& t : io::pile_traction_profiles(*coupled)) io::write_csv(staged.path() / (t.name + ".csv"), t);
            write_drive_record(c, run, history, driver.extremes(), output, *coupled, staged.path());
        }
    if constexpr (D == 2) {
        // A collapse's final deposit, one row per grid column, for comparison with profiles.
        if (std::find(c.verification_checks.begin(), c.verification_checks.end(), "granular_runout") !=
            c.verification_checks.end()) {
            const auto thickness = mpm::deposit_profile(m);
            Table profile("deposit_profile", {c.axisymmetric ? "r_centre_m" : "x_centre_m", "thickness_m"});
            for (std::size_t k = 0; k < thickness.size(); ++k)
                profile.add_row({m.grid.coordinate(0, static_cast<int>(k)) + 0.5 * m.grid.width(0, static_cast<int>(k)), thickness[k]});
            io::write_csv(staged.path() / "deposit_profile.csv", profile);
        }
    }

    const bool poroelastic = std::find(c.verification_checks.begin(), c.verification_checks.end(),
                                       "poroelastic_wave_history") != c.verification_checks.end();
    if (poroelastic) {
        // The probes' histories beside the dynamic poro-elastic reference, for the plot.
        io::write_csv(staged.path() / "poroelastic_wave_histories.csv",
                      mpm::poroelastic_wave_histories<D>(check_context(c), m, run.x0, history));
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
        const auto mem = solver.memory();
        summary.add("stored_grid_nodes", static_cast<double>(mem.stored_nodes))
            .add("memory_bytes_per_point", static_cast<double>(mem.bytes_per_point))
            .add("memory_bytes_per_stored_node", static_cast<double>(mem.bytes_per_stored_node))
            .add("memory_MB", 1e-6 * static_cast<double>(mem.total_bytes()));
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
        const mpm::MpmCheckContext context = check_context(c);
        auto checks = mpm::run_mpm_verification<D>(context, m, run.x0, history);
        if (!c.grid_sequence.empty()) {
            // The case's own grid (factor 1) and the others, coarsest to finest in the file.
            std::vector<double> factors = {1.0};
            std::vector<std::vector<VerificationCheck>> by_grid = {checks};
            for (double f : c.grid_sequence) {
                std::string grid;
                if (!quiet) std::printf("  grid sequence: running the case at %g x the cells\n", f);
                bool stopped = false;
                by_grid.push_back(checks_on_grid<D>(c, context, f, grid, quiet, &stop, stopped));
                if (stopped) {
                    // Resuming from the case's own checkpoint, if it wrote one, reruns the sequence.
                    if (fs::exists(output.checkpoint_path()))
                        std::fprintf(stderr, "pilempm: interrupted on grid %s of the verification's grid sequence; resume "
                                             "with --resume (checkpoint kept in %s)\n",
                                     grid.c_str(), staged.incomplete_path().c_str());
                    else
                        std::fprintf(stderr, "pilempm: interrupted on grid %s of the verification's grid sequence; "
                                             "nothing kept\n", grid.c_str());
                    return 130;
                }
                factors.push_back(f);
                checks.insert(checks.end(), by_grid.back().begin(), by_grid.back().end());
            }
            if (c.tolerance_on_finest_grid) {
                // Only the finest grid is held to the tolerance; the others are reported.
                const double finest = *std::max_element(factors.begin(), factors.end());
                checks.clear();
                for (std::size_t g = 0; g < by_grid.size(); ++g)
                    for (auto k : by_grid[g]) {
                        if (factors[g] < finest) k.informative = true, k.passed = true;
                        checks.push_back(k);
                    }
            }
            const auto converged = convergence_checks(c, by_grid, factors);
            checks.insert(checks.end(), converged.begin(), converged.end());
        }
        io::write_json(staged.path() / "verification.json", verification_json(c, checks, io::JsonObject{}));
        if (!quiet)
            for (const auto& k : checks)
                std::printf("  [%s] %-40s computed %-14.6g reference %-14.6g tol %g\n", k.informative ? "note" : k.passed ? "pass" : "FAIL",
                            k.name.c_str(), k.computed, k.reference, k.tolerance);
    }
    if constexpr (D == 2)
        if (coupled) write_load_tests(c, history, *coupled, staged.path(), summary);
    io::write_json(staged.path() / "summary.json", summary);
    if (c.pile.present && c.plots) {
        std::string note;
        if (!io::make_plots("plot_pile_installation.py", staged.path(), note) && !quiet) std::printf("  %s\n", note.c_str());
    }
    if (poroelastic && c.plots) {
        std::string note;
        if (!io::make_plots("plot_poroelastic_wave.py", staged.path(), note) && !quiet) std::printf("  %s\n", note.c_str());
    }
    staged.commit();
    if (!quiet)
        std::printf("%s\n  %zu material points, %d grid nodes, %ld steps, t = %.4g s\n  results in %s\n", c.title.c_str(),
                    m.particles.size(), m.grid.num_nodes(), solver.steps(), solver.time(), out_dir.c_str());
    return 0;
}

template <int D>
void describe_run(const io::MpmCase& c) {
    auto run = io::build_mpm_run<D>(c);
    mpm::MpmSolver<D> solver(run.model);
    solver.activate_grid();
    const auto mem = solver.memory();
    const mpm::TimeStepLimit limit = solver.time_step_limit();
    std::printf("  MPM            %s, %zu material points, dt %.3g s\n",
                D == 3 ? "3D" : c.axisymmetric ? "2D axisymmetric" : "2D plane strain", mem.points, limit.dt);
    std::printf("  time step      set by the %s, %.4g m/s\n", limit.limited_by.c_str(), limit.wave_speed);
    if (limit.explicit_drag_limit > 0.0)
        std::printf("  Darcy drag     semi-implicit: no limit (explicit drag would need dt < %.3g s)\n",
                    limit.explicit_drag_limit);
    if (run.model.saturated()) {
        for (std::size_t k = 0; k < c.materials.size(); ++k) {
            const auto& dr = run.model.drainage[k];
            if (!dr.saturated()) continue;
            std::printf("  pore water     %s: %s, n = %.3f", c.materials[k].name.c_str(), mpm::drainage_name(dr.drainage),
                        dr.porosity);
            if (dr.darcy_resistance > 0.0)
                std::printf(", k = %.3g m/s", run.model.water.density * 9.80665 / dr.darcy_resistance);
            std::printf("\n");
        }
        if (run.model.water.free_surface)
            std::printf("  water surface  at %.3f m (hydrostatic pore pressure below it)\n", run.model.water.level);
    }
    std::printf("  grid           %zu nodes; stored where the points are: %d blocks of %d nodes\n", mem.grid_nodes,
                run.model.grid.active_blocks(), mpm::Grid<D>::kBlockNodes);
    std::printf("  memory         %.1f MB (%zu B per point, %zu B per stored node)\n", 1e-6 * mem.total_bytes(),
                mem.bytes_per_point, mem.bytes_per_stored_node);
}

}  // namespace

int check_mpm_case(const std::string& file) {
    const io::MpmCase c = io::read_mpm_case(file);
    std::printf("%s: valid\n  title          %s\n", file.c_str(), c.title.c_str());
    if (c.dimension == 2) describe_run<2>(c);
    else describe_run<3>(c);
    std::printf("  stages         %zu\n", c.stages.size());
    return 0;
}

int run_mpm_case(const std::string& file, const fs::path& out_dir, bool quiet, bool resume) {
    const io::MpmCase c = io::read_mpm_case(file);
    return c.dimension == 2 ? run_dimension<2>(c, out_dir, quiet, resume) : run_dimension<3>(c, out_dir, quiet, resume);
}

}  // namespace pilempm::app
