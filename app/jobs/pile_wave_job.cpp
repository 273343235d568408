#include "app/jobs/pile_wave_job.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "io/writers/terminal_progress.hpp"
#include "app/jobs/verification_runner.hpp"
#include "fem/pile_wave/pile_wave.hpp"
#include "io/writers/csv_writer.hpp"
#include "io/hdf5/hdf5_results.hpp"
#include "io/writers/json_writer.hpp"
#include "io/cases/pile_wave_case.hpp"
#include "io/writers/plots.hpp"
#include "io/writers/staged_directory.hpp"
#include "io/writers/vtk_pile_writer.hpp"

namespace pilempm::app {

namespace fs = std::filesystem;

namespace {

const char* toe_name(fem::ToeCondition t) {
    switch (t) {
        case fem::ToeCondition::Free: return "free";
        case fem::ToeCondition::Fixed: return "fixed";
        case fem::ToeCondition::Dashpot: return "dashpot";
    }
    return "?";
}

// Snapshots to ParaView and progress to the terminal.
class JobObserver : public fem::PileWaveObserver {
public:
    JobObserver(io::PileVtkSeries* vtk, io::TerminalProgress* progress) : vtk_(vtk), progress_(progress) {}
    void on_snapshot(double t, const fem::ExplicitPile& pile, const std::vector<double>& v,
                     const std::vector<double>& stress) override {
        if (vtk_) vtk_->write(t, pile.displacement(), v, stress);
    }
    void on_progress(double t, double duration, long step) override {
        progress_->update(t, duration, step);
    }

private:
    io::PileVtkSeries* vtk_;
    io::TerminalProgress* progress_;
};

io::JsonObject summary_json(const io::PileWaveCase& c, const fem::PileWaveSetup& s,
                            const fem::PileWaveResult& r, double wall) {
    const auto& m = r.summary;
    io::JsonObject o;
    o.add("title", c.title).add("case_file", c.file).add("analysis", std::string("pile_wave"))
        .add("pile_model", std::string(io::pile_model_name(c.model)))
        .add("hammer", c.hammer_description).add("toe_condition", std::string(toe_name(s.toe.condition)))
        .add("sign_convention", std::string("forces and stresses compression positive unless named tension; velocity down positive"))
        .add("peak_head_force_N", m.peak_head_force)
        .add("max_compression_stress_Pa", m.max_compression_stress)
        .add("max_compression_depth_below_head_m", m.max_compression_depth)
        .add("max_tension_stress_Pa", m.max_tension_stress)
        .add("max_tension_depth_below_head_m", m.max_tension_depth)
        .add("enthru_J", m.enthru).add("max_enthru_J", m.max_enthru);
    if (c.rated_energy > 0.0)
        o.add("rated_energy_J", c.rated_energy).add("energy_transfer_ratio", m.max_enthru / c.rated_energy);
    if (m.hammer_energy > 0.0) o.add("ram_kinetic_energy_at_impact_J", m.hammer_energy);
    o.add("wave_speed_m_s", m.wave_speed).add("head_impedance_N_s_m", m.head_impedance)
        .add("two_L_over_c_s", 2.0 * m.pile_length / m.wave_speed)
        .add("pile_length_m", m.pile_length).add("pile_mass_kg", m.pile_mass)
        .add("time_step_s", m.time_step).add("stable_time_step_s", m.stable_time_step)
        .add("steps", static_cast<double>(m.steps)).add("element_count", static_cast<double>(m.elements))
        .add("node_count", static_cast<double>(m.nodes)).add("wall_time_s", wall)
        .add("element_steps_per_second", wall > 0 ? m.elements * static_cast<double>(m.steps + 1) / wall : 0.0);
    return o;
}

void print_summary(const io::PileWaveCase& c, const fem::PileWaveResult& r, double wall,
                   const fs::path& out) {
    const auto& m = r.summary;
    std::printf("%s\n", c.title.c_str());
    std::printf("  peak head force        %10.3f MN\n", m.peak_head_force * 1e-6);
    std::printf("  max compression stress %10.1f MPa at %.2f m below head\n",
                m.max_compression_stress * 1e-6, m.max_compression_depth);
    std::printf("  max tension stress     %10.1f MPa at %.2f m below head\n",
                m.max_tension_stress * 1e-6, m.max_tension_depth);
    std::printf("  ENTHRU (max)           %10.1f kJ", m.max_enthru * 1e-3);
    if (c.rated_energy > 0) std::printf("  (%.0f %% of rated %.1f kJ)", 100 * m.max_enthru / c.rated_energy, c.rated_energy * 1e-3);
    std::printf("\n  %d elements, %ld steps of %.3g s, wall time %.2f s\n", m.elements, m.steps + 1,
                m.time_step, wall);
    std::printf("  results in %s\n", out.c_str());
}

}  // namespace

int check_pile_wave_case(const std::string& file) {
    const io::PileWaveCase c = io::read_pile_wave_case(file);
    const fem::PileWaveSetup s = io::build_pile_wave_setup(c);
    const fem::ExplicitPile pile(s.mesh, s.steel, s.toe);
    const double stable = fem::pile_wave_stable_time_step(pile, s);
    const double dt = s.time_step > 0 ? s.time_step : s.time_step_factor * stable;
    double length = 0.0;
    for (const auto& seg : c.segments) length += seg.length;
    std::printf("%s: valid\n", file.c_str());
    std::printf("  title          %s\n", c.title.c_str());
    std::printf("  analysis       pile wave analysis, one blow\n");
    std::printf("  pile           %s model, %zu segment(s), L = %.3f m, mass %.1f t\n",
                io::pile_model_name(c.model), c.segments.size(), length, pile.operators().total_mass * 1e-3);
    std::printf("  mesh           %d elements (%s), %d nodes, element size %.4g m\n",
                pile.mesh().num_elements(), fem::element_kind_name(pile.mesh().blocks.front().kind),
                pile.mesh().num_nodes(), c.element_size);
    std::printf("  steel          E = %.4g Pa, nu = %.3g, rho = %.5g kg/m^3, c = %.1f m/s\n",
                c.steel.youngs_modulus, c.steel.poisson_ratio, c.steel.density, c.steel.wave_speed());
    std::printf("  toe            %s", toe_name(s.toe.condition));
    if (s.toe.condition == fem::ToeCondition::Dashpot) std::printf(", impedance %.4g N s/m", s.toe.impedance);
    std::printf("\n  hammer         %s\n", c.hammer_description.c_str());
    if (s.hammer.kind == fem::HammerKind::PrescribedForce && s.hammer.force.table_time.empty())
        std::printf("                 peak force %.4g N over %.4g s\n", s.hammer.force.peak, s.hammer.force.duration);
    if (s.hammer.kind == fem::HammerKind::RamCushion)
        std::printf("                 ram %.4g kg at %.4g m/s\n", s.hammer.ram_cushion.ram.mass,
                    s.hammer.ram_cushion.impact_velocity);
    std::printf("  time step      %.4g s (stable %.4g s), %ld steps over %.4g s\n", dt, stable,
                static_cast<long>(std::ceil(c.duration / dt)), c.duration);
    std::printf("  gauges         %zu, snapshots every %.4g s\n", c.gauge_depths.size(), c.snapshot_interval);
    if (!c.verification_checks.empty()) std::printf("  verification   %zu check(s)\n", c.verification_checks.size());
    return 0;
}

int run_pile_wave_case(const std::string& file, const fs::path& out_dir, bool quiet) {
    const io::PileWaveCase c = io::read_pile_wave_case(file);
    const fem::PileWaveSetup setup = io::build_pile_wave_setup(c);

    io::StagedDirectory staged(out_dir);
    std::unique_ptr<io::PileVtkSeries> vtk;
    if (setup.snapshot_interval > 0.0) {
        fs::create_directory(staged.path() / "vtk");
        vtk = std::make_unique<io::PileVtkSeries>(staged.path() / "vtk", setup.mesh, "pile");
    }
    io::TerminalProgress progress("pile wave", !quiet);
    JobObserver observer(vtk.get(), &progress);
    const auto t0 = std::chrono::steady_clock::now();
    const fem::PileWaveResult result = fem::run_pile_wave(setup, &observer);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    progress.done();
    if (vtk) vtk->finish();

    for (const auto& t : result.tables) io::write_csv(staged.path() / (t.name + ".csv"), t);
    io::write_csv(staged.path() / "stress_envelope.csv", result.envelope);

    io::JsonObject summary = summary_json(c, setup, result, wall);
    if (!c.verification_checks.empty()) {
        io::JsonObject details;
        const auto checks = run_verification(c, setup, result, details, quiet);
        const io::JsonObject v = verification_json(c, checks, details);
        io::write_json(staged.path() / "verification.json", v);
        int passed = 0;
        for (const auto& k : checks) passed += k.passed;
        summary.add("verification_checks_passed", static_cast<double>(passed))
            .add("verification_checks", static_cast<double>(checks.size()));
        if (!quiet)
            for (const auto& k : checks)
                std::printf("  [%s] %-40s computed %-14.6g reference %-14.6g tol %g%s\n",
                            k.passed ? "pass" : "FAIL", k.name.c_str(), k.computed, k.reference,
                            k.tolerance, k.at_least ? " (at least)" : k.relative ? " (rel)" : " (abs)");
    }

    std::vector<Table> tables = result.tables;
    tables.push_back(result.envelope);
    const auto& m = result.summary;
    io::write_results_h5(staged.path() / "results.h5", tables, setup.mesh, result.final_displacement,
                         result.final_velocity, result.final_axial_stress,
                         {{"peak_head_force_N", m.peak_head_force}, {"enthru_J", m.enthru},
                          {"max_compression_stress_Pa", m.max_compression_stress},
                          {"max_tension_stress_Pa", m.max_tension_stress},
                          {"wave_speed_m_s", m.wave_speed}, {"head_impedance_N_s_m", m.head_impedance},
                          {"time_step_s", m.time_step}},
                         {{"title", c.title}, {"case_file", c.file}, {"pile_model", io::pile_model_name(c.model)}});
    io::write_json(staged.path() / "summary.json", summary);
    if (c.plots) {
        std::string note;
        if (!io::make_plots("plot_pile_wave.py", staged.path(), note) && !quiet)
            std::fprintf(stderr, "note: %s\n", note.c_str());
    }
    staged.commit();
    if (!quiet) print_summary(c, result, wall, out_dir);
    return 0;
}

}  // namespace pilempm::app
