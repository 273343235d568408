#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/cases/pile_wave_case.hpp"
#include "io/yaml/yaml_reader.hpp"

namespace pilempm::io {
namespace {

const std::vector<std::string> kChecks = {"rigid_ram_decay",  "elastic_ram_pulse",
                                          "toe_reflection",   "energy_conservation",
                                          "rod_axisymmetric_agreement", "mesh_convergence",
                                          "half_sine_transfer"};

}  // namespace

PileWaveCase read_pile_wave_case(const std::string& file) {
    MapReader root = load_yaml_file(file);
    PileWaveCase c;
    read_case_header(root, c, file, "pile_wave");
    read_pile_section(root.map("pile"), c, c, true);
    read_hammer_section(root.map("hammer"), c, c);

    auto sim = root.map("simulation");
    c.duration = sim.number("duration", positive("duration in s"));
    c.lines["simulation.time_step"] = sim.line_of("time_step");
    c.time_step = sim.number_or("time_step", 0.0, positive("time step in s"));
    c.time_step_factor = sim.number_or("time_step_factor", 0.9,
                                       in_half_open_range(0.0, 1.0, "a fraction of the stable time step"));
    sim.finish();

    const double length = c.length();
    c.snapshot_interval = c.duration / 50.0;
    if (auto out = root.optional_map("output")) {
        if (out->has("gauges"))
            c.gauge_depths = out->numbers("gauges", {"a depth below the pile head within the pile (0 to " +
                                                         std::to_string(length) + " m)",
                                                     [length](double d) { return d >= 0.0 && d <= length; }});
        c.snapshot_interval = out->number_or("snapshot_interval", c.snapshot_interval,
                                             non_negative("snapshot interval in s (0: none)"));
        c.plots = out->boolean_or("plots", true);
        out->finish();
    }
    if (auto ver = root.optional_map("verification")) {
        c.verification_checks = ver->words("checks", kChecks);
        c.refinements = ver->integer_or("refinements", 3, 3);
        ver->finish();
    }
    root.finish();
    return c;
}

}  // namespace pilempm::io
