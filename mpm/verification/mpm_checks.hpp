#pragma once
// Closed-form checks of MPM runs: stresses of a column under self-weight and of a thick
// cylinder under internal pressure, the arrival and the absorption of a 1D wave, Prandtl's
// footing, K0 and the collapse laws. Each compares the run with an independent number.
#include <array>
#include <map>
#include <string>
#include <vector>

#include "core/table.hpp"
#include "core/verification_check.hpp"
#include "mpm/solver/mpm_solver.hpp"

namespace pilempm::mpm {

// What the checks read besides the model: the case's check names and parameters
// (verification.* keys), gravity and the first material's density, model and Poisson's
// ratio.
struct MpmCheckContext {
    std::vector<std::string> checks;
    std::map<std::string, double> parameters;
    double gravity = 0.0;  // m/s^2, magnitude
    double density = 0.0;  // kg/m^3
    std::string model;     // linear_elastic, mohr_coulomb, ...
    double poisson_ratio = 0.0;
    std::vector<std::array<double, 3>> probes;  // the case's probe positions (output.probes), m
    double youngs_modulus = 0.0;  // Pa, of the first material
};

// Shared by the checks: a verification.* parameter (throws naming the check when missing),
// a history column by name, and the half-amplitude arrival time of a pulse of the given
// plateau in a probe's series (dt: the largest sample interval seen).
double parameter(const MpmCheckContext& c, const char* key, const char* check);
const std::vector<double>& column(const Table& t, const std::string& name);
double arrival(const std::vector<double>& t, const std::vector<double>& v, double plateau, double& dt);

template <int D>
std::vector<VerificationCheck> run_mpm_verification(const MpmCheckContext& c, const MpmModel<D>& m,
                                                    const std::vector<double>& x0, const Table& history);


}  // namespace pilempm::mpm
