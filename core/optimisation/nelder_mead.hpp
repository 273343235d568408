#pragma once
// Derivative-free minimisation by the Nelder-Mead simplex (Lagarias et al. 1998's standard
// coefficients: reflection 1, expansion 2, contraction 1/2, shrink 1/2), for fits of a few
// parameters to a model without gradients (a wave-equation blow). Bounds are the caller's:
// map them into the objective (e.g. fit logarithms of positive parameters).
#include <functional>
#include <vector>

namespace pilempm {

struct NelderMeadOptions {
    int max_evaluations = 200;
    double value_tolerance = 1e-6;  // stop when the simplex's values span less than this
    double step_tolerance = 1e-4;   // ... and its vertices lie within this of the best
};

struct NelderMeadResult {
    std::vector<double> x;  // the best point found
    double value = 0.0;
    int evaluations = 0;
    bool converged = false;  // the tolerances were met before max_evaluations
};

// Minimises f from x0; the starting simplex steps each coordinate by steps[i].
NelderMeadResult nelder_mead(const std::function<double(const std::vector<double>&)>& f,
                             const std::vector<double>& x0, const std::vector<double>& steps,
                             const NelderMeadOptions& options = {});

}  // namespace pilempm
