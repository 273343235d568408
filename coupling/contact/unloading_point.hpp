#pragma once
// The unloading-point method (Middendorp et al. 1992) for a rapid load test: the pile is
// taken as one rigid mass m, so the soil's force is F - m a; at the unloading point (the
// pile's largest settlement, v = 0) the soil's damping vanishes and F - m a is the static
// resistance F_u there; the damping constant C is fitted, with the static resistance held
// at F_u, between the peak load and the unloading point; the derived static curve is
// F - m a - C v. Read off the head's record of the test (force, settlement, velocity; down
// positive), so it applies to a field record as well as to a run's history.
#include <vector>

#include "core/table.hpp"

namespace pilempm::coupling {

struct RapidLoadRecord {
    std::vector<double> time, force, settlement, velocity;  // s, N, m, m/s; down positive
};

struct UnloadingPointResult {
    double unloading_time = 0.0;        // s, where v changes sign after the peak load
    double max_settlement = 0.0;        // m, there
    double static_resistance = 0.0;     // N: F - m a at the unloading point, F_u
    double damping = 0.0;               // N s/m, C
    double peak_force = 0.0;            // N, of the test's load
    double peak_velocity = 0.0;         // m/s
    // Per row of the record up to the unloading point: acceleration (m/s^2), the soil's force
    // F - m a and the derived static force F - m a - C v (N).
    Table curve;
};

// mass: the pile's (whole ring), kg; window: the acceleration's differences span at least
// this (s; the pile's wave period 2 L / c averages its ringing out; 0: neighbouring rows).
// Throws when the record has no unloading point (the pile still moving down at its end) or
// no load.
UnloadingPointResult unloading_point(const RapidLoadRecord& record, double mass, double window = 0.0);

// The stage's rows of a run's history (the pile recorder's columns), the settlement from the
// stage's start.
RapidLoadRecord rapid_load_record(const Table& history, int stage);

}  // namespace pilempm::coupling
