#pragma once
// Checks of the wave-equation drivability (issue: verification 1-4), at one depth of the
// study's first best-estimate soil case.
#include <vector>

#include "coupling/wave_equation/drivability.hpp"
#include "fem/pile_wave/pile_wave_verification.hpp"

namespace pilempm::coupling {

// 1. A slow push of the Smith pile mobilises the SRD at that depth (1 %).
std::vector<VerificationCheck> check_static_push(const DrivabilitySetup& s, const SoilCase& c, double depth);
// 2. On the bearing graph, blow count rises and set falls with resistance.
std::vector<VerificationCheck> check_bearing_graph(const Table& bearing_graph);
// 3. One blow: hammer energy = soil plastic + soil damping + elastic energy left (1 %).
std::vector<VerificationCheck> check_blow_energy(const DrivabilitySetup& s, const SoilCase& c, double depth);
// 4. Set per blow against the Danish formula with the transferred energy: same order
//    (within a factor of 3): s = E / R - sqrt(2 E L / (A E_p)) / 2.
std::vector<VerificationCheck> check_danish_formula(const DrivabilitySetup& s, const PenetrationResult& point);

}  // namespace pilempm::coupling
