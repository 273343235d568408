#pragma once
// A drivability case (analysis: drivability) as read from YAML, validated, in SI units.
#include <string>
#include <vector>

#include "coupling/wave_equation/cpt_interpretation.hpp"
#include "coupling/wave_equation/drivability.hpp"
#include "coupling/wave_equation/fast_path_calibration.hpp"
#include "coupling/wave_equation/field_comparison.hpp"
#include "io/cases/pile_hammer_input.hpp"

namespace pilempm::io {

// `analysis: drivability_study`: one drivability case run at many locations of a field
// records file, each with its CPT, pile and hammer energy, against the measured blows.
struct DrivabilityStudy {
    std::string records;                    // path of the records CSV (io/cases/field_records.hpp)
    std::vector<std::string> locations;     // empty: all
    double stick_up = 10.0;                 // m of pile above the seabed at final penetration
    double reference_energy = 0.0;          // J: normalised hammer energy x this = energy
    std::string calibration_location;       // empty: no calibration
    std::string calibration_soil_case = "best_estimate";
    double calibration_low = 0.0, calibration_high = 0.0;  // J, bracket of reference_energy
    std::string lower_case = "lower_bound", upper_case = "upper_bound";  // the band
    double split_depth = 0.0;               // m: statistics also above and below it (0: none)
    // verification: the statistics of one soil case against stated aims (negative: none).
    std::string verified_case;
    double max_median_abs_ln_ratio = -1.0, min_median_profile_correlation = -2.0;
};

struct DrivabilityCase : CaseFile, PileInput, HammerInput {
    coupling::SoilProfile soil;
    std::string cpt_file;
    bool cpt_soil = false;                     // soil.cpt: layers derived from the sounding
    coupling::CptInterpretationOptions cpt_options;
    coupling::CptInterpretation cpt_interpretation;
    std::string energy_plan_source;            // how the plan was given, for the summary
    bool study_mode = false;
    DrivabilityStudy study;
    coupling::SrdCoefficients coefficients;
    std::vector<coupling::SoilCase> cases;
    coupling::SmithParameters smith;
    double sand_shaft_damping = 0.16, clay_shaft_damping = 0.65;
    std::vector<double> energy_levels = {1.0};
    std::vector<double> energy_plan_depth, energy_plan_level;  // fractions of the rated energy
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
    double calibration_tolerance = 0.1;              // the fitted sets against the coupled, relative
    // calibrated_blow_count: a coupled drive's blow count (its blow_count.csv, complete
    // intervals) that the calibrated sheet's blows over the same depths are checked against.
    coupling::MeasuredDriving reference_drive;
    double blow_count_tolerance = 0.15;              // relative
    // calibration: the fast path fitted to coupled runs (empty targets: none).
    std::vector<coupling::CalibrationTarget> calibration_targets;
    std::string calibration_soil_case = "best_estimate";
    coupling::CalibrationOptions calibration;
};

DrivabilityCase read_drivability_case(const std::string& file);
coupling::DrivabilitySetup build_drivability_setup(const DrivabilityCase& c);

// The `analysis` of a case file (pile_wave, drivability, drivability_study, ...), checked.
std::string read_analysis_kind(const std::string& file);

}  // namespace pilempm::io
