#pragma once
// Closed-form checks of MPM runs (issue 4, verification 1-3): stresses of a column under
// self-weight and of a thick cylinder under internal pressure, and the arrival and the
// absorption of a 1D wave.
#include <vector>

#include "coupling/pile_wave_verification.hpp"
#include "coupling/table.hpp"
#include "io/mpm_case.hpp"
#include "mpm/mpm_solver.hpp"

namespace pilempm::app {

template <int D>
std::vector<coupling::VerificationCheck> run_mpm_verification(const io::MpmCase& c, const mpm::MpmModel<D>& m,
                                                              const std::vector<double>& x0, const Table& history);

// RMS of (sigma_v - rho g z) / (rho g H) over the points: the stress noise of a column
// under its weight (verification.surface gives the top).
template <int D>
double stress_noise(const io::MpmCase& c, const mpm::MpmModel<D>& m, const std::vector<double>& x0);

}  // namespace pilempm::app
