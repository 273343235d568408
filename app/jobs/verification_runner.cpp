#include "app/jobs/verification_runner.hpp"

#include <cstdio>
#include <memory>

namespace pilempm::app {


std::vector<VerificationCheck> run_verification(const io::PileWaveCase& c,
                                                const fem::PileWaveSetup& setup,
                                                const fem::PileWaveResult& result,
                                                io::JsonObject& details, bool quiet) {
    std::vector<VerificationCheck> all;
    auto append = [&all](std::vector<VerificationCheck> v) {
        all.insert(all.end(), v.begin(), v.end());
    };
    for (const auto& name : c.verification_checks) {
        if (name == "rigid_ram_decay") append(fem::check_rigid_ram_decay(setup, result));
        else if (name == "elastic_ram_pulse") append(fem::check_elastic_ram_pulse(setup, result));
        else if (name == "toe_reflection") append(fem::check_toe_reflection(setup, result));
        else if (name == "half_sine_transfer") append(fem::check_half_sine_transfer(setup, result));
        else if (name == "energy_conservation") append(fem::check_energy_conservation(setup, result));
        else if (name == "rod_axisymmetric_agreement") {
            // The twin: same case, rod model, same element size along the axis.
            const auto rod_setup = io::build_pile_wave_setup(c, io::PileModel::Rod, c.element_size);
            const auto rod = fem::run_pile_wave(rod_setup);
            append(fem::check_model_agreement(result, rod));
            details.add("rod_peak_head_force_N", rod.summary.peak_head_force)
                .add("axisymmetric_peak_head_force_N", result.summary.peak_head_force);
        } else if (name == "mesh_convergence") {
            std::vector<double> sizes;
            std::vector<fem::PileWaveSetup> setups;
            std::vector<fem::PileWaveResult> results;
            for (int k = 0; k < c.refinements; ++k) {
                const double h = c.element_size / (1 << k);
                sizes.push_back(h);
                setups.push_back(io::build_pile_wave_setup(c, c.model, h));
                setups.back().snapshot_interval = 0.0;
                results.push_back(k == 0 ? result : fem::run_pile_wave(setups.back()));
                if (!quiet) std::fprintf(stderr, "mesh convergence: element size %.4g m done\n", h);
            }
            const auto study = fem::convergence_of_peak_toe_stress(sizes, setups, results);
            append(fem::check_mesh_convergence(study));
            details.add("element_sizes_m", study.element_sizes)
                .add("peak_toe_stress_Pa", study.peak_toe_stress)
                .add("reference_peak_toe_stress_Pa", study.reference)
                .add("observed_order", study.observed_order);
            if (!quiet)
                std::printf("mesh convergence of the peak toe stress: observed order %.2f\n",
                            study.observed_order);
        }
    }
    return all;
}

io::JsonObject verification_json(const io::CaseFile& c, const std::vector<VerificationCheck>& checks,
                                 const io::JsonObject& details) {
    std::vector<io::JsonObject> list;
    bool all_passed = !checks.empty();
    for (const auto& k : checks) {
        io::JsonObject o;
        o.add("name", k.name).add("computed", k.computed).add("reference", k.reference)
            .add("tolerance", k.tolerance)
            .add("tolerance_kind", std::string(k.informative     ? "reported"
                                              : k.at_least      ? "at_least"
                                              : k.within_factor ? "factor"
                                              : k.relative      ? "relative"
                                                                : "absolute"))
            .add("passed", k.passed).add("note", k.note);
        list.push_back(std::move(o));
        all_passed = all_passed && k.passed;
    }
    io::JsonObject root;
    root.add("case", c.file).add("title", c.title).add("all_passed", all_passed).add("checks", list)
        .add("details", std::make_shared<io::JsonObject>(details));
    return root;
}

}  // namespace pilempm::app
