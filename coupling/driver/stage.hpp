#pragma once
// The stages of a run and the loads switched per stage. A quasi-static stage relaxes to
// equilibrium under local damping in pseudo-time (the clock stands still); a dynamic stage
// runs for its duration in real time; a consolidation stage lets the pore water flow for its
// duration in real time with the soil at rest (implicit). Load times count from the start of the stage, so a
// pulse acts at the start of every dynamic stage it is switched on in.
#include <string>
#include <vector>

#include "core/linear_algebra/sparse_linear_solver.hpp"
#include "mpm/solver/mpm_solver.hpp"

namespace pilempm::coupling {

struct StageSpec {
    std::string name = "stage";
    bool quasi_static = false;
    // A consolidation stage: the implicit u-p solver (mpm/implicit) over `duration` seconds
    // of real time in `steps` backward-Euler steps growing by `step_growth` each (short
    // first steps for the steep early gradients of pressure).
    bool consolidation = false;
    int steps = 20;
    double step_growth = 1.2;
    core::SolverOptions linear_solver;
    int direct_below = 0;  // unknowns below which the step's system is factorised instead (0: never)
    double duration = 0.0;       // s (dynamic, consolidation)
    long max_steps = 100000;     // quasi-static
    double tolerance = 1e-4;     // unbalanced force ratio that ends a quasi-static stage
    double local_damping = 0.0;  // Cundall's alpha
    bool drained = false;        // coupled pore water held drained (MpmSolver::set_drained)
    // Gravity in this stage over the case's: n for n g in a centrifuge (the soil's body
    // forces, its pore water's and the pile's weight).
    double gravity_factor = 1.0;
    // A dynamic stage may end before its duration once the coupled body has come to rest
    // after min_duration s: no node faster than rest_speed (m/s; 0: runs its duration) for
    // rest_span s on end, so a pile bouncing on the soil is not taken at rest at the top of
    // a bounce, where its speed passes through zero.
    double rest_speed = 0.0;
    double min_duration = 0.0;
    double rest_span = 0.0;
    // From min_duration on, the stage's local damping becomes this (0: unchanged): a blow
    // whose wave has passed settles to rest on the soil instead of rocking on it for
    // seconds, so its set is read at rest and the pause starts from equilibrium.
    double settle_damping = 0.0;
    // A dynamic stage stores every record_every-th step's row in the history, every step's
    // while in_stage < min_duration (a blow's wave: the head's record) and its last; the
    // peaks are kept over every step all the same (DriverState::extremes).
    int record_every = 1;
    // Impact driving: the blows and pauses of one drive share `drive` (>= 0; -1: none). After
    // a blow the driver ends the drive (goes on after its last stage) when the body's toe is
    // at end_toe_elevation or lower, or when refusal_blows blows in a row each set it less
    // than refusal_set (m).
    int drive = -1;
    bool blow = false;
    double end_toe_elevation = -1e300;
    double refusal_set = 0.0;
    int refusal_blows = 0;
    // A pause: a consolidation stage whose duration is what is left of `blow_interval` (s)
    // since the last blow began (0: its own duration).
    double blow_interval = 0.0;
    bool snapshot_at_end = true;
};

// The time shape of a pulse: constant over its duration, p sin(pi t / T), whose smooth
// rise carries little energy at the grid's cut-off wavelengths, or p sin^2(pi t / T), smooth
// at both ends too (its spectrum falls as 1 / f^3: the pulse for comparing wave histories).
enum class PulseShape { Rectangular, HalfSine, SineSquared };

// A force on the face of a material point (from a pressure) and when it acts.
struct StageLoad {
    mpm::SurfaceLoad load;
    double duration = 0.0;     // s; 0: held for the whole stage, else a pulse from the stage start
    PulseShape shape = PulseShape::Rectangular;
    std::vector<int> stages;   // indices of the stages it acts in; empty: every stage
    bool acts_in(int stage) const;
    // The share of the force acting (0 when off). Held loads act in quasi-static stages;
    // pulses only in dynamic ones, for `duration` after the stage's start.
    double factor(int stage, bool quasi_static, double time_in_stage) const;
};

}  // namespace pilempm::coupling
