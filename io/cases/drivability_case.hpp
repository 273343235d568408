#pragma once
// A drivability case (analysis: drivability) as read from YAML, validated, in SI units.
#include <string>
#include <vector>

#include "coupling/wave_equation/drivability.hpp"
#include "io/cases/pile_hammer_input.hpp"

namespace pilempm::io {

struct DrivabilityCase : CaseFile, PileInput, HammerInput {
    coupling::SoilProfile soil;
    std::string cpt_file;
    coupling::SrdCoefficients coefficients;
    std::vector<coupling::SoilCase> cases;
    coupling::SmithParameters smith;
    double sand_shaft_damping = 0.16, clay_shaft_damping = 0.65;
    std::vector<double> energy_levels = {1.0};
    double start_depth = -1.0, final_depth = 0.0, depth_step = 0.25;
    double refusal_blow_count = 250.0, hard_driving_blow_count = 75.0;
    int max_blows = 8;
    double steady_tolerance = 0.05;
    int threads = 0;
    std::vector<double> bearing_resistances;
    double bearing_shaft_fraction = 0.5, bearing_penetration = 0.0;
    bool plots = true;
    std::vector<std::string> verification_checks;
    double verification_depth = 0.0;  // m; 0: final depth
    double observed_self_weight_penetration = -1.0;  // m, for the validation check
    double observed_tolerance = 0.5;                 // m
};

DrivabilityCase read_drivability_case(const std::string& file);
coupling::DrivabilitySetup build_drivability_setup(const DrivabilityCase& c);

// The `analysis` of a case file (pile_wave or drivability), checked.
std::string read_analysis_kind(const std::string& file);

}  // namespace pilempm::io
