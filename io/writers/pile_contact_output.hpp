#pragma once
// What the coupled pile's contact looks like for a spreadsheet: the tractions along each
// side of the pile (outer shaft, inner shaft, toe), one row per surface segment.
#include <vector>

#include "core/table.hpp"
#include "coupling/contact/coupled_pile.hpp"

namespace pilempm::io {

// Tables pile_tractions_outer, _inner, _toe: height_above_toe_m, elevation_m, radius_m,
// length_m, normal_traction_compression_Pa and shear_traction_Pa (the soil's on the pile:
// up along a shaft, outward along the toe), from the last step's contact forces over each
// segment's ring area 2 pi r L; and the same from the mean forces over the last stage the
// pile stepped in (stage_mean_*: what a chattering contact bore on average).
std::vector<Table> pile_traction_profiles(const coupling::CoupledPile& pile);

}  // namespace pilempm::io
