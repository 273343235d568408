#pragma once
// Pile wave analysis: one hammer blow travelling down the FE pile. Physics only; the
// caller receives tables, snapshots and progress through PileWaveObserver.
#include <string>
#include <vector>

#include "fem/hammer/hammer.hpp"
#include "core/table.hpp"
#include "fem/dynamics/explicit_pile.hpp"

namespace pilempm::fem {

struct PileWaveSetup {
    fem::PileMesh mesh;
    fem::LinearElasticSteel steel;
    fem::ToeSupport toe;
    HammerSpec hammer;
    double duration = 0.0;          // s
    double time_step = 0.0;         // s; 0: time_step_factor x stable
    double time_step_factor = 0.9;  // of the stable step
    double ram_element_size = 0.0;  // m, for an elastic ram without an element count
    std::vector<double> gauge_depths;  // m below the head
    double snapshot_interval = 0.0;    // s; 0: no snapshots
};

struct PileWaveSummary {
    double peak_head_force = 0.0;          // N, compression
    double max_compression_stress = 0.0;   // Pa, magnitude
    double max_compression_depth = 0.0;    // m below head
    double max_tension_stress = 0.0;       // Pa
    double max_tension_depth = 0.0;        // m below head
    double enthru = 0.0;                   // J, integral of F v at the head
    double max_enthru = 0.0;               // J, its maximum over the blow
    double hammer_energy = 0.0;            // J, kinetic energy of the ram at impact (0: prescribed)
    double wave_speed = 0.0;               // m/s
    double head_impedance = 0.0;           // N s/m
    double head_area = 0.0;                // m^2, steel
    double toe_area = 0.0;                 // m^2, steel
    double time_step = 0.0;                // s
    double stable_time_step = 0.0;         // s
    long steps = 0;
    int elements = 0;
    int nodes = 0;
    double pile_mass = 0.0;                // kg
    double pile_length = 0.0;              // m
};

struct PileWaveResult {
    std::vector<Table> tables;  // pile_head, toe, energy, gauge_*
    Table envelope;             // stress_envelope: depth_below_head_m, max_compression_Pa, max_tension_Pa
    PileWaveSummary summary;
    std::vector<double> final_displacement, final_velocity, final_axial_stress;
    const Table& table(const std::string& name) const;
};

class PileWaveObserver {
public:
    virtual ~PileWaveObserver() = default;
    // Called at t = 0 and every snapshot interval with the pile's current state.
    virtual void on_snapshot(double /*time*/, const fem::ExplicitPile& /*pile*/,
                             const std::vector<double>& /*velocity*/,
                             const std::vector<double>& /*axial_stress*/) {}
    virtual void on_progress(double /*time*/, double /*duration*/, long /*step*/) {}
};

// Stable time step of the pile and hammer together (before the factor).
double pile_wave_stable_time_step(const fem::ExplicitPile& pile, const PileWaveSetup& setup);

PileWaveResult run_pile_wave(const PileWaveSetup& setup, PileWaveObserver* observer = nullptr);

}  // namespace pilempm::fem
