#pragma once
// The drivability study: for every soil case (lower / best / upper SRD) and hammer energy
// level, the blow count against depth from the wave equation at each depth point; the
// self-weight penetration; optionally a bearing graph. Depth points are independent and
// run in parallel (OpenMP).
#include <functional>
#include <string>
#include <vector>

#include "coupling/wave_equation/driving.hpp"
#include "coupling/wave_equation/srd_methods.hpp"
#include "core/table.hpp"

namespace pilempm::coupling {

struct SoilCase {
    std::string name;              // e.g. "best_estimate"
    SrdMethod method = SrdMethod::AlmHamre2001;
    double factor = 1.0;           // on shaft and toe resistance
};

struct DrivabilitySetup {
    fem::PileMesh mesh;            // rod model, pile frame (toe at z = 0)
    fem::LinearElasticSteel steel;
    double outer_diameter = 0.0;   // m, of the embedded (lowest) segment
    double wall_thickness = 0.0;   // m
    double pile_mass = 0.0;        // kg, for the self-weight penetration
    SoilProfile soil;
    SrdCoefficients coefficients;
    std::vector<SoilCase> cases;
    SmithParameters smith;
    double sand_shaft_damping = 0.16;  // s/m (Smith)
    double clay_shaft_damping = 0.65;  // s/m (Smith)
    fem::HammerSpec hammer;
    double ram_element_size = 0.5;
    double hammer_weight = 0.0;        // N resting on the pile (helmet, sleeve): self-weight penetration
    std::vector<double> energy_levels = {1.0};  // fractions of the hammer's energy
    // Driving plan: the fraction of the hammer's energy against depth (piecewise linear,
    // constant beyond its ends), scaled by each energy level. Empty: 1 at every depth.
    std::vector<double> energy_plan_depth, energy_plan_level;
    double start_depth = -1.0;         // m; negative: from the self-weight penetration
    double final_depth = 0.0;          // m
    double depth_step = 0.25;          // m
    double hard_driving_blow_count = 75.0;
    DrivingOptions driving;
    double srd_spacing = 0.1;          // m between SRD samples
    int threads = 0;                   // 0: all cores
    // Bearing graph: blow count against ultimate resistance (empty: none).
    std::vector<double> bearing_resistances;  // N
    double bearing_shaft_fraction = 0.5;
    double bearing_penetration = 0.0;  // m; 0: final_depth
};

struct DrivabilityRun {
    std::string soil_case;
    double energy_level = 1.0;
    Table table;                       // one row per depth point
    double self_weight_penetration = 0.0;   // m, pile alone
    double self_weight_penetration_with_hammer = 0.0;
    double refusal_depth = -1.0;       // m; negative: none
    double final_depth_reached = 0.0;  // m
    double total_blows = 0.0;          // to the final depth or refusal
    double max_compression = 0.0, max_compression_depth = 0.0;  // Pa, m
    double max_tension = 0.0, max_tension_depth = 0.0;
    double hard_driving_from = -1.0;   // m, first depth above the hard-driving count
};

struct DrivabilityResult {
    std::vector<DrivabilityRun> runs;
    Table bearing_graph;               // empty when not asked for
    long depth_points = 0, blows_simulated = 0;
    double wall_time = 0.0;            // s
};

// Depth where SRD reaches `weight` (N), between 0 and max_depth (by bisection).
double self_weight_penetration(const SoilProfile& soil, SrdMethod method, const SrdCoefficients& k,
                               double factor, double d_outer, double wall, double weight,
                               double max_depth, double spacing);

// SRD sampled for the Smith soil, with the shaft damping of each layer's soil type.
ResistanceDistribution srd_for_driving(const DrivabilitySetup& s, const SoilCase& c, double penetration);

// Bearing-graph soil: `r_u` (N) on a uniform shaft (bearing_shaft_fraction) and the toe at
// the bearing-graph penetration, with the shaft damping of each layer's soil type.
ResistanceDistribution bearing_graph_resistance(const DrivabilitySetup& s, double r_u);

// The fraction of the hammer's energy used at `depth`: `level` x the driving plan there.
double planned_energy_level(const DrivabilitySetup& s, double depth, double level);

// Hammer with its energy scaled by `level` (impact velocity or pulse force x sqrt(level)).
fem::HammerSpec scaled_hammer(const fem::HammerSpec& h, double level);

using DrivabilityProgress = std::function<void(long done, long total)>;
DrivabilityResult run_drivability(const DrivabilitySetup& s, const DrivabilityProgress& progress = {});

}  // namespace pilempm::coupling
