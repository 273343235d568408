#pragma once
// A pile wave analysis case as read from YAML, in SI units, already validated.
#include <map>
#include <string>
#include <vector>

#include "fem/pile_wave/pile_wave.hpp"
#include "fem/mesh/pile_geometry.hpp"
#include "io/cases/pile_hammer_input.hpp"

namespace pilempm::io {

struct PileWaveCase : CaseFile, PileInput, HammerInput {
    double duration = 0.0;
    double time_step = 0.0;      // 0: from the stable step
    double time_step_factor = 0.9;
    std::vector<double> gauge_depths;
    double snapshot_interval = 0.0;
    bool plots = true;
    std::vector<std::string> verification_checks;
    int refinements = 3;
};

// Reads and validates a case file; throws CaseError on any bad input.
PileWaveCase read_pile_wave_case(const std::string& file);

// Checks that need the built model (stable time step) and builds the setup: meshes the
// pile (rod, or axisymmetric through gmsh). model/element size may be overridden for
// verification runs (mesh convergence, rod twin).
fem::PileWaveSetup build_pile_wave_setup(const PileWaveCase& c);
fem::PileWaveSetup build_pile_wave_setup(const PileWaveCase& c, PileModel model,
                                              double element_size);

}  // namespace pilempm::io
