#pragma once
// Implicit consolidation on the MPM grid: the pause between blows, where the pore water
// flows and the excess pressure dissipates while the soil is at rest. Biot's quasi-static
// u-p equations, per step of length dt (backward Euler), for the nodal displacement
// increment du and excess-pressure increment dp:
//   [ K    -Q        ] [du]   [ f_ext - f_int(sigma'_n - p_n I) ]
//   [ Q^T   S + dt H ] [dp] = [ -dt H p_n                       ]
// K = int B^T D B (the elastic tangent of each material), Q = int B^T m N, S = int N n/K_w N
// (lumped), H = int grad N (kappa/mu) grad N, integrated at the material points. The
// out-of-balance force of the last state is on the right, so a plastic stress update is
// corrected in the next step, and a state in equilibrium with no excess pressure does not
// move: an explicit stage hands over to it, and back, without loss. Drained faces: p = 0 on
// the nodes at the soil's free surface (and on drained grid boundaries); elsewhere no flow.
// The points then take du (strain, stress by their constitutive model, position) and dp.
#include <string>
#include <vector>

#include "core/linear_algebra/sparse_linear_solver.hpp"
#include "mpm/solver/mpm_solver.hpp"

namespace pilempm::mpm {

struct ConsolidationStepReport {
    int unknowns = 0;
    core::SolveReport solve;
    double max_excess_pressure = 0.0;  // Pa, over the points after the step
    double unbalanced_ratio = 0.0;     // out-of-balance over external force of the state it started from
};

template <int D>
class ConsolidationSolver {
public:
    // direct_below: systems with fewer unknowns are factorised (KLU2), larger ones solved by
    // `options` (0: always `options`; KLU2 is the fallback when they fail).
    explicit ConsolidationSolver(MpmModel<D>& model, core::SolverOptions options = {}, int direct_below = 0);
    // One backward-Euler step of dt seconds. Throws std::runtime_error when the linear
    // solve does not converge (naming the method and the residual).
    ConsolidationStepReport step(double dt);

private:
    MpmModel<D>& m_;
    MpmSolver<D> activator_;  // stores the grid blocks the points reach, as the explicit steps do
    core::SolverOptions options_;
    int direct_below_ = 0;
    std::vector<Stencil<D>> stencil_;
    std::vector<std::vector<int>> points_of_material_;
    std::vector<int> void_ratio_state_;  // per material (-1: none)
    std::vector<core::Triplet> triplets_, flow_;  // the step's assembly, reused
    // The steps' solves keep their symbolic set-up while the pattern stays (a pause's steps).
    core::LinearSolver linear_, fallback_;
};

extern template class ConsolidationSolver<2>;
extern template class ConsolidationSolver<3>;

}  // namespace pilempm::mpm
