#pragma once
// A pile wave analysis case as read from YAML, in SI units, already validated.
#include <map>
#include <string>
#include <vector>

#include "coupling/pile_wave.hpp"
#include "fem/pile_geometry.hpp"

namespace pilempm::io {

enum class PileModel { Rod, Axisymmetric };

struct PileWaveCase {
    std::string file;   // the case file, for messages
    std::string title;
    PileModel model = PileModel::Rod;
    std::vector<fem::PileSegment> segments;  // head to toe
    double taper_ratio = 4.0;
    fem::LinearElasticSteel steel;
    double element_size = 0.0;   // m
    int radial_divisions = 2;    // axisymmetric
    fem::ToeSupport toe;
    bool toe_impedance_given = false;  // else: the pile's own impedance
    coupling::HammerSpec hammer;
    std::string hammer_description;
    double rated_energy = 0.0;   // J, m g h of the hammer when known
    double gravity = 9.81;
    double duration = 0.0;
    double time_step = 0.0;      // 0: from the stable step
    double time_step_factor = 0.9;
    std::vector<double> gauge_depths;
    double snapshot_interval = 0.0;
    bool plots = true;
    std::vector<std::string> verification_checks;
    int refinements = 3;
    std::map<std::string, int> lines;  // key path -> line, for errors found after reading
    int line_of(const std::string& key) const {
        auto it = lines.find(key);
        return it == lines.end() ? 0 : it->second;
    }
};

// Reads and validates a case file; throws CaseError on any bad input.
PileWaveCase read_pile_wave_case(const std::string& file);

// Checks that need the built model (stable time step) and builds the setup: meshes the
// pile (rod, or axisymmetric through gmsh). model/element size may be overridden for
// verification runs (mesh convergence, rod twin).
coupling::PileWaveSetup build_pile_wave_setup(const PileWaveCase& c);
coupling::PileWaveSetup build_pile_wave_setup(const PileWaveCase& c, PileModel model,
                                              double element_size);

const char* pile_model_name(PileModel m);

}  // namespace pilempm::io
