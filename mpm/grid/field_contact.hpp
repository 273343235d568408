#pragma once
// Frictional contact between the two sides of a slip line (a FieldCut with contact) at the
// nodes both sides reach, after Bardenhagen et al. (2001): where a side moves toward the
// other relative to their common centre of mass, its normal velocity is brought to the
// centre of mass's and its tangential slip is limited by Coulomb friction; the other side
// takes the opposite momentum, so the pair's momentum is unchanged. The normal is the
// line's own (known geometry), not one estimated from mass gradients. Solid fields only.
#include <vector>

#include "mpm/grid/field_cut.hpp"
#include "mpm/grid/grid.hpp"

namespace pilempm::mpm {

// Corrects the velocities of the pairs of fields each contact cut separates, at the stored
// nodes free of boundary conditions where both hold more than `empty_mass` and whose
// nearest segment of the cut is a slip line's. With dt > 0
// the change is also an acceleration (the grid update's), and its push m dv / dt is added
// to `residual` (D per entry) when that is given; dt = 0 corrects velocities only (a remap).
void contact_across_cuts(Grid<2>& grid, const std::vector<FieldCut>& cuts, double empty_mass, double dt,
                         std::vector<double>* residual);

// Whether any cut has a slip line (sides in contact).
bool any_contact_cut(const std::vector<FieldCut>& cuts);

}  // namespace pilempm::mpm
