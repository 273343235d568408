#pragma once
// Closed-form checks of a pile wave run (issue: verification 1-6). Each returns named
// comparisons of a computed number with its reference and a stated tolerance.
#include <string>
#include <vector>

#include "core/verification_check.hpp"
#include "fem/pile_wave/pile_wave.hpp"

namespace pilempm::fem {

// Rigid ram of mass m on the pile, no cushion: F = (Z v0 - m g) exp(-t Z/m) + m g.
std::vector<VerificationCheck> check_rigid_ram_decay(const PileWaveSetup& s, const PileWaveResult& r);
// Elastic ram: rectangular pulse of Z_p Z_r / (Z_p + Z_r) v0 lasting 2 L_ram / c_ram.
std::vector<VerificationCheck> check_elastic_ram_pulse(const PileWaveSetup& s, const PileWaveResult& r);
// Prescribed pulse: return at 2L/c; free toe -> tension of equal size; fixed -> toe force x2.
std::vector<VerificationCheck> check_toe_reflection(const PileWaveSetup& s, const PileWaveResult& r);
// Prescribed pulse, no damping: stored energy after the load equals its work (0.5 %).
std::vector<VerificationCheck> check_energy_conservation(const PileWaveSetup& s, const PileWaveResult& r);
// Half-sine pulse into a pile whose toe absorbs the wave (matched dashpot): the head force
// peaks at F0 and the energy transferred is F0^2 t_i / (2 Z).
std::vector<VerificationCheck> check_half_sine_transfer(const PileWaveSetup& s, const PileWaveResult& r);
// Axisymmetric solid against rod: peak head force (3 %) and arrival times at the toe.
std::vector<VerificationCheck> check_model_agreement(const PileWaveResult& solid,
                                                     const PileWaveResult& rod);

struct ConvergenceStudy {
    std::vector<double> element_sizes;
    std::vector<double> peak_toe_stress;  // Pa, compression
    double reference = 0.0;
    double observed_order = 0.0;  // from the two finest meshes
};
// Peak toe stress of a fixed toe under a half-sine pulse: 2 F0 / A_toe.
ConvergenceStudy convergence_of_peak_toe_stress(const std::vector<double>& sizes,
                                                const std::vector<PileWaveSetup>& setups,
                                                const std::vector<PileWaveResult>& results);
std::vector<VerificationCheck> check_mesh_convergence(const ConvergenceStudy& study);

}  // namespace pilempm::fem
