#pragma once
// Wave-equation drivability at one penetration: the FE pile and hammer on Smith soil,
// struck blow after blow (each starting from the rest state the previous one left, so
// residual stresses carry over) until the permanent set per blow is steady.
#include <vector>

#include "fem/hammer/hammer.hpp"
#include "coupling/wave_equation/resistance_distribution.hpp"
#include "coupling/wave_equation/smith_soil.hpp"
#include "fem/dynamics/explicit_pile.hpp"

namespace pilempm::coupling {

enum class DampingLaw {
    SmithViscous,  // dashpot J R_u (J in s/m) on each soil point
    Case           // dashpot J_c Z R_u,i / R_u,total (J_c dimensionless, Z of the pile)
};

struct SmithParameters {
    double shaft_quake = 2.5e-3;   // m
    double toe_quake = 2.5e-3;     // m
    double shaft_damping = 0.16;   // s/m (Smith) or - (Case)
    double toe_damping = 0.50;     // s/m (Smith) or - (Case)
    DampingLaw law = DampingLaw::SmithViscous;
};

// Smith points on the pile's nodes below the mudline (pile frame: toe at z = 0, mudline
// at z = penetration): each node takes the shaft resistance of its tributary length; the
// toe node takes the toe resistance as a separate, compression-only point.
SmithSoil make_smith_soil(const fem::ExplicitPile& pile, const ResistanceDistribution& r,
                          const SmithParameters& p, double pile_impedance);

struct BlowOptions {
    double time_step_factor = 0.9;
    double dynamic_duration = 0.0;  // s; 0: hammer pulse + 4 round trips 2L/c
    long max_rest_steps = 20000;    // kinetic-damping steps to bring the pile to rest
};

struct BlowOutcome {
    double set = 0.0;                    // m, permanent toe movement, down positive
    double peak_head_force = 0.0;        // N
    double max_compression_stress = 0.0; // Pa, magnitude, anywhere in the pile
    double max_tension_stress = 0.0;     // Pa
    double enthru = 0.0;                 // J, max of the integral of F v at the head
    // Energy record of the dynamic phase, J.
    double energy_in = 0.0;              // hammer impact energy + gravity work, or load work
    double energy_pile = 0.0;            // change of pile kinetic + strain energy
    double energy_hammer = 0.0;          // hammer kinetic + stored + its losses at the end
    double energy_soil_plastic = 0.0;
    double energy_soil_damping = 0.0;
    double energy_soil_elastic = 0.0;    // change of the springs' stored energy
    double energy_error() const;         // relative imbalance
    long steps = 0;
};

// The head's record over a blow's dynamic phase, PDA-style: force (compression positive)
// and velocity (down positive) at the head's gauge, from the blow's start.
struct HeadRecord {
    std::vector<double> time, force, velocity;  // s, N, m/s
    void clear() { time.clear(), force.clear(), velocity.clear(); }
};

// One blow on a pile at rest, then kinetic damping until it is at rest again; the head's
// record of the dynamic phase into `record` when given.
BlowOutcome simulate_blow(fem::ExplicitPile& pile, SmithSoil& soil, const fem::HammerSpec& hammer,
                          double ram_element_size, const BlowOptions& options, HeadRecord* record = nullptr);

struct DrivingOptions {
    int max_blows = 8;
    double steady_tolerance = 0.05;   // relative change of the set between two blows
    double refusal_blow_count = 250;  // blows per 0.25 m
    BlowOptions blow;
};

struct PenetrationResult {
    double penetration = 0.0;
    double srd_shaft = 0.0, srd_toe = 0.0;  // N
    double set = 0.0;                       // m per blow, of the last blow
    double blows_per_quarter_metre = 0.0;   // 0.25 / set, capped at 10 x refusal
    BlowOutcome last;
    int blows = 0;
    bool steady = false;
    bool refusal = false;
};

PenetrationResult drive_at_penetration(const fem::PileMesh& mesh, const fem::LinearElasticSteel& steel,
                                       const ResistanceDistribution& srd, const SmithParameters& smith,
                                       const fem::HammerSpec& hammer, double ram_element_size,
                                       const DrivingOptions& options, HeadRecord* last_record = nullptr);

// Quasi-static push of the head at `velocity` (m/s, down) to `displacement` (m): the
// largest head force, which tends to the total static resistance (verification).
double static_push_capacity(fem::ExplicitPile& pile, SmithSoil& soil, double velocity,
                            double displacement);

}  // namespace pilempm::coupling
