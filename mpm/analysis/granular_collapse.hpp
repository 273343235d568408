#pragma once
// Granular column collapse (issue 4, verification 5): where the deposit ends, and the
// experimental run-out laws it is compared with.
#include <vector>

#include "mpm/solver/mpm_solver.hpp"

namespace pilempm::mpm {

// Front of the deposit along x: the furthest point of the material that is continuous from
// x = origin. Points beyond a gap of one empty grid cell are grains that left the deposit;
// an experimenter's ruler stops at the deposit's edge too.
template <int D>
double deposit_front(const mpm::MpmModel<D>& m);

// Deposit thickness per grid column along x (2D), m: the points' volume in the column over
// its width (plane strain) or over its ring area (axisymmetric: volume per radian over
// (r2^2 - r1^2) / 2). The profile experimenters photograph, in a form a spreadsheet plots.
std::vector<double> deposit_profile(const mpm::MpmModel<2>& m);

// Front of the deposit read at a thickness: the left edge of the first column, from x =
// origin, thinner than `thickness`. A toe a few grains thick is not a continuum; this
// reads the run-out where the deposit still is one.
double thickness_front(const mpm::MpmModel<2>& m, const std::vector<double>& profile, double thickness);

// Normalised run-out (L_f - L_0) / L_0 at aspect ratio a = H / L_0, after Lube et al.
// Plane strain (2005, Phys. Rev. E 72, 041301): 1.2 a for a < 1.8, 1.9 a^(2/3) for a > 2.8,
// linear between the two in the transition they leave open. Axisymmetric (2004, J. Fluid
// Mech. 508, 175-199), L_0 the radius: 1.24 a for a < 1.7, 1.6 a^(1/2) above.
double lube_runout(double aspect_ratio, bool axisymmetric);

// Final height of the deposit H_inf / L_0 (its highest point, at the wall or the axis), after
// Lube et al. Plane strain (2005): a for a < 1.15 (the top is left undisturbed), a^(2/5)
// above. Axisymmetric (2004), L_0 the radius: a for a < 0.7, 0.88 a^(1/6) above.
double lube_final_height(double aspect_ratio, bool axisymmetric);

// Highest thickness of a 2D deposit profile (deposit_profile), m.
double deposit_height(const std::vector<double>& profile);

}  // namespace pilempm::mpm
