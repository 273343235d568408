#pragma once
// Closed-form checks of saturated-soil runs: Terzaghi's 1D consolidation (isochrones and
// degree of consolidation against the series solution), the undrained P-wave's speed,
// hydrostatic equilibrium under a water column, and Skempton's B against Gassmann.
#include <array>
#include <vector>

#include "core/table.hpp"
#include "core/verification_check.hpp"
#include "mpm/verification/mpm_checks.hpp"

namespace pilempm::mpm {

// Terzaghi: excess pore pressure u(z, T) / u0 at depth z below the drained face of a layer
// of drainage length H, T = c_v t / H^2 (series, converged to 1e-12).
double terzaghi_excess_pressure(double depth_over_h, double time_factor);
double terzaghi_degree_of_consolidation(double time_factor);

template <int D>
std::vector<VerificationCheck> terzaghi_consolidation(const MpmCheckContext& c, const MpmModel<D>& m,
                                                      const std::vector<double>& x0, const Table& history);
// A pressure pulse in a saturated column: undrained (low permeability) or the fast wave
// of the drag-free limit (high permeability).
template <int D>
std::vector<VerificationCheck> saturated_wave_arrival(const MpmCheckContext& c, const MpmModel<D>& m,
                                                      const Table& history, bool fast);
// Pore-pressure and effective-stress histories at the probes of a column loaded at its
// drained surface by a sin^2 pulse, beside the dynamic poro-elastic reference
// (dynamic_poroelastic_column.hpp): time_s, then per probe computed and reference columns.
template <int D>
Table poroelastic_wave_histories(const MpmCheckContext& c, const MpmModel<D>& m, const std::vector<double>& x0,
                                 const Table& history);
template <int D>
std::vector<VerificationCheck> poroelastic_wave_history(const MpmCheckContext& c, const MpmModel<D>& m,
                                                        const std::vector<double>& x0, const Table& history);
template <int D>
std::vector<VerificationCheck> hydrostatic_equilibrium(const MpmCheckContext& c, const MpmModel<D>& m,
                                                       const std::vector<double>& x0);
template <int D>
VerificationCheck skempton_b_check(const MpmCheckContext& c, const MpmModel<D>& m);

}  // namespace pilempm::mpm
