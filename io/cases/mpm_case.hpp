#pragma once
// An MPM soil case (analysis: mpm) as read from YAML, validated, SI units.
#include <array>
#include <string>
#include <vector>

#include "core/linear_algebra/sparse_linear_solver.hpp"
#include "io/cases/material_input.hpp"
#include "io/cases/pile_hammer_input.hpp"
#include "mpm/grid/graded_axis.hpp"
#include "mpm/setup/model_setup.hpp"
#include "mpm/grid/shape_functions.hpp"

namespace pilempm::io {

using MpmMaterialInput = MaterialInput;

struct MpmBox {
    std::array<double, 3> min{}, max{};
};

struct MpmRegionInput {
    int material = 0;
    enum Kind { Box, Cylinder, Layer } kind = Box;
    MpmBox box;                    // Box; Layer uses min[vertical]..max[vertical]
    std::array<double, 3> centre{};  // Cylinder: base centre; axis vertical
    double radius = 0.0, height = 0.0;
};

struct MpmBoundaryInput {
    int axis = 0, side = 0;
    mpm::BoundaryKind kind = mpm::BoundaryKind::Fixed;
    double friction = 0.0;  // Coulomb coefficient of a frictional wall
    bool drained = false;   // saturated soil: water flows through it (default: impermeable)
    // Absorbing: the distance R (m) setting its far-field springs 2 G / R and G / R; < 0: the
    // grid's extent across the boundary; 0: none (dashpots alone).
    double far_field_distance = -1.0;
};

// The pore water of saturated materials and the free water surface above the ground.
struct MpmWaterInput {
    double density = 1000.0;      // kg/m^3
    double bulk_modulus = 2.2e9;  // Pa
    double viscosity = 1.0e-3;    // Pa s (converts an intrinsic permeability)
    bool free_surface = false;
    double level = 0.0;           // elevation of the free water surface, m
    bool cavitation = false;      // the pore water's absolute pressure held at 0 or above
    double atmospheric_pressure = 101.325e3;  // Pa, on the free water surface
};

struct MpmPressureInput {  // on the points in a box: force = -pressure n x face area
    MpmBox box;
    int normal_axis = 1;
    double normal_sign = 1.0;
    double pressure = 0.0;          // Pa, compression positive
    std::array<double, 3> traction{};  // Pa, added to -pressure n (a shear load: along the face)
    double duration = 0.0;          // s; 0: held (a step), else a pulse from each stage's start
    std::string pulse = "rectangular";  // the pulse's shape: rectangular | half_sine | sine_squared
    std::vector<int> stages;        // the stages it acts in (indices); empty: all
};

struct MpmVelocityInput {  // grid nodes in a box move at a prescribed velocity
    MpmBox box;
    std::array<double, 3> velocity{};
    std::array<bool, 3> components{};
};

struct MpmStageInput {
    std::string name;
    bool quasi_static = false;      // local damping until equilibrium
    bool consolidation = false;     // implicit u-p: the pore water flows, the soil at rest
    int steps = 20;                 // consolidation: backward-Euler steps
    double step_growth = 1.2;       // consolidation: each step this much longer than the last
    core::SolverOptions linear_solver;
    int direct_below = 0;           // consolidation: factorise (KLU2) below this many unknowns (0: never)
    double duration = 0.0;          // s (dynamic)
    long max_steps = 100000;        // quasi-static
    double tolerance = 1e-4;        // unbalanced force ratio (quasi-static)
    bool drained = false;           // coupled pore water held drained (a drained nil step)
    bool pile_driven = false;       // the pile's head driven at pile_velocity (jacking, load test)
    double pile_velocity = 0.0;     // m/s, down positive (0: held)
    bool pile_loaded = false;       // the pile's head pushed by pile_force (a maintained load)
    double pile_force = 0.0;        // N, compression positive
    double pile_rise_time = 0.0;    // s over which the velocity or force changes from the last stage's
    bool pile_struck = false;       // the case's hammer strikes the head at the stage's start (a blow)
    // The stage is a load test on the pile: "static" (the head driven), read off as a load-
    // settlement curve; "rapid" (the hammer's slow pulse), read by the unloading-point
    // method. Empty: none.
    std::string load_test;
    int pile_line = 0;              // the stage's pile key, for errors found later
    double local_damping = 0.7;     // quasi-static (default 0.7); dynamic (default 0)
    double gravity_factor = 1.0;    // gravity over the case's in this stage (n g in a centrifuge)
    // A blow or pause of a `type: driving` stage (coupling::StageSpec says what each means).
    int drive = -1;                 // the driving stage's index among the case's drives (-1: none)
    bool blow = false;
    int blow_number = 0;            // 1-based within its drive
    double rest_speed = 0.0;        // m/s
    double min_duration = -1.0;     // s (< 0: the pulse and four of the pile's wave transits)
    double rest_span = -1.0;        // s below rest_speed that counts as rest (< 0: min_duration)
    double settle_damping = 0.0;    // a blow's local damping after min_duration (0: none)
    int history_every = 1;          // a blow's history row every n-th step after min_duration
    double end_toe_elevation = -1e300;
    double refusal_set = 0.0;       // m
    int refusal_blows = 0;
    double blow_interval = 0.0;     // s (a pause)
};

// An FE pile in the soil (2D axisymmetric), coupled by penalty contact.
struct MpmPileInput {
    bool present = false;
    PileInput pile;                 // geometry, steel, mesh (the axisymmetric wall)
    double toe_elevation = 0.0;     // m, the toe's elevation in the soil's frame at the start
    double friction = 0.0;          // mu = tan(delta) of the pile-soil interface
    double penalty_factor = 4.0;    // k_n = factor x M A_p / h_p^2, A_p the domain's area (coupling/contact/penalty_contact.hpp)
    bool corner_overlap_share = false;  // corner_contact: overlap (else full)
    bool self_weight = true;        // the pile's weight under the case's gravity
    bool wished_in_place = false;   // starts embedded: the soil in its wall removed, overlaps ignored
    double toe_cone_angle = 0.0;    // degrees: a closed toe's conical tip, its apex at toe_elevation (0: flat)
    // A slip line from the toe's outer corner into the soil (coupling::ToeSlipLine): its
    // length in grid cells (0: none) and the soil's friction angle across it, degrees.
    double slip_line_cells = 0.0;
    double slip_line_friction_angle = 0.0;
    // The hammer of the stages with `pile: {blow: true}` (the top-level `hammer:` section,
    // as the pile wave analysis reads it).
    bool has_hammer = false;
    HammerInput hammer;
    // Open at the toe (a tube; segments run head to toe), else closed-ended (solid there).
    bool open_ended() const {
        return !pile.segments.empty() && pile.segments.back().wall_thickness < 0.5 * pile.segments.back().outer_diameter;
    }
};

struct MpmCase : CaseFile {
    int dimension = 2;
    bool axisymmetric = false;
    std::array<double, 3> origin{}, size{};
    std::array<int, 3> cells{};
    // A graded grid (grid.zones): per axis, the zones its node coordinates are made of; empty
    // along a uniform axis. size and cells then describe the grid they make.
    std::array<std::vector<mpm::GridZone>, 3> zones;
    mpm::ShapeKind shape = mpm::ShapeKind::GIMP;
    int per_cell = 2;
    double flip = 0.98, cfl = 0.5;
    bool apic = false;              // velocity_transfer: apic (else the FLIP/PIC blend)
    bool smooth_dilatation = false; // volumetric_strain: nodal_average (else: each point's own)
    std::vector<MpmMaterialInput> materials;
    std::vector<MpmRegionInput> regions;
    std::vector<MpmBoundaryInput> boundaries;
    std::vector<MpmPressureInput> pressures;
    std::vector<MpmVelocityInput> velocities;
    MpmWaterInput water;
    bool k0_initial_stress = false;
    double surface = 0.0;           // elevation of the ground surface for K0, m
    double surcharge = 0.0;         // Pa on that surface (the K0 state's sigma'_v there); apply it as a pressure too
    std::vector<MpmStageInput> stages;
    MpmPileInput pile;
    double snapshot_interval = 0.0; // s of simulated time (0: one snapshot per stage end)
    long checkpoint_every = 0;      // steps (0: only at stage ends)
    long history_segment_rows = 100000;  // history rows per file sealed beside the checkpoint
    bool plots = true;
    std::vector<std::array<double, 3>> probes;  // points whose nearest material point is recorded
    std::vector<std::string> verification_checks;
    std::map<std::string, double> verification;  // parameters of the checks
    std::vector<double> grid_sequence;           // refinement factors the checks are rerun at
    std::array<bool, 3> refined_axes{true, true, true};  // the axes the sequence refines
    std::vector<std::string> converging;         // checks whose errors must converge on them
    std::vector<std::string> self_converging;    // checks whose values must converge (to any limit)
    // tolerance_on: finest_grid holds only the finest grid's checks to their tolerance (a
    // criterion stated on the finest of a sequence); the others are reported.
    bool tolerance_on_finest_grid = false;
};

MpmCase read_mpm_case(const std::string& file);

}  // namespace pilempm::io
