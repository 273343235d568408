#pragma once
// The fast path calibrated by the coupled model: the Smith soil of a drivability study
// (its SRD factor, shaft and toe quakes, shaft and toe dampings) fitted to the sets and
// head records of coupled MPM-FEM blows at a few depths, so that the whole drivability
// sheet, computed in seconds, carries what the coupled model saw. Each fitted parameter
// is a factor on its starting value, searched in logarithms (Nelder-Mead) within bounds.
#include <string>
#include <vector>

#include "coupling/wave_equation/drivability.hpp"
#include "core/table.hpp"

namespace pilempm::coupling {

// What the coupled model measured at one depth: the mean set of its blows there and one
// blow's head record (time from the blow's start).
struct CalibrationTarget {
    double depth = 0.0;        // m below the mudline, the toe's before the blows
    double set = 0.0;          // m per blow, mean
    double enthru = 0.0;       // J, mean
    int blows = 0;
    HeadRecord record;
    std::string source;        // where it was read, for the report
};

enum class CalibrationParameter { SrdFactor, ShaftQuake, ToeQuake, ShaftDamping, ToeDamping };
const char* calibration_parameter_name(CalibrationParameter p);
std::vector<CalibrationParameter> all_calibration_parameters();

// The fast path's soil: the SRD factor of the calibrated case and the Smith parameters
// (shaft dampings per soil type, as the setup holds them).
struct FastPathSoil {
    double srd_factor = 1.0;
    SmithParameters smith;  // quakes, dampings (the shaft's: Case's J_c, or the fallback)
    double sand_shaft_damping = 0.0, clay_shaft_damping = 0.0;  // s/m, Smith-viscous
    // The parameter's value; the shaft damping: Case's J_c, or the sand's J (s/m).
    double value(CalibrationParameter p) const;
};

struct CalibrationOptions {
    std::vector<CalibrationParameter> fit = all_calibration_parameters();
    double record_weight = 1.0;   // of the head records' misfit against the sets'
    double record_window = 0.0;   // s of each record compared; 0: the pulse and two round trips 2L/c
    double bound = 10.0;          // each factor between 1/bound and bound
    // Tikhonov's pull toward the start: + regularisation x sum of ln(factor)^2, so that what
    // the blows cannot tell apart stays at its default instead of wandering to a bound.
    double regularisation = 0.01;
    int max_evaluations = 300;
};

struct CalibrationPoint {
    CalibrationTarget target;
    double fast_set_before = 0.0, fast_set_after = 0.0;            // m
    double record_misfit_before = 0.0, record_misfit_after = 0.0;  // relative RMS
    double fast_enthru_after = 0.0;                                // J
    HeadRecord fast_before, fast_after;
};

struct CalibrationResult {
    std::vector<CalibrationParameter> fitted;
    FastPathSoil before, after;
    double objective_before = 0.0, objective_after = 0.0;  // the misfits' mean, penalty included
    double record_window = 0.0;   // s
    bool compares_force = false;  // a ram-cushion hammer's force answers the soil too
    std::vector<CalibrationPoint> points;
    int evaluations = 0;
    bool converged = false;
    std::vector<CalibrationParameter> at_bound;  // fitted factors that ended on a bound
    double wall_time = 0.0;       // s
};

FastPathSoil starting_soil(const DrivabilitySetup& s, const SoilCase& c);

// The setup with the soil: one case, named `name`, of c's SRD method and the soil's factor.
DrivabilitySetup with_soil(const DrivabilitySetup& s, const SoilCase& c, const FastPathSoil& soil,
                           const std::string& name);

// Misfit of one target: ln(set ratio)^2 + weight x the records' relative mean square
// difference (velocity; and force when compares_force) over the window.
double target_misfit(const CalibrationTarget& t, double fast_set, const HeadRecord& fast, double window,
                     bool compares_force, double record_weight, double* record_misfit = nullptr);

CalibrationResult calibrate_fast_path(const DrivabilitySetup& s, const SoilCase& c,
                                      const std::vector<CalibrationTarget>& targets, const CalibrationOptions& o);

// calibration.csv: per target, the coupled set and blow count against the fast path's
// before and after the fit, and the records' misfits.
Table calibration_table(const CalibrationResult& r);
// calibration_records.csv: per target, the head records over the window at the coupled
// record's times: the coupled model's and the fast path's before and after the fit.
Table calibration_records_table(const CalibrationResult& r);

}  // namespace pilempm::coupling
