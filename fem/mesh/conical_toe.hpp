#pragma once
// A closed-ended pile's conical tip (a CPT's or the mini-ICP's 60 degree cone): the solid
// wall mesh's lowest rows mapped onto the cone, so the soil flows round a shoulder rather
// than a right-angled corner. Connectivity is kept; only coordinates move.
#include "fem/mesh/pile_mesh.hpp"

namespace pilempm::fem {

// Maps an axisymmetric mesh whose toe (z = 0) is solid out to radius R onto a cone of the
// given apex angle (degrees, 0 < angle < 180): the apex at z = 0 on the axis, the shoulder
// at height h = R / tan(angle / 2). Nodes below 2 h move up by h (r / R) (1 - z / (2 h)),
// so the toe row lies on the cone and rows at 2 h and above stay where they were; the
// cone's elements are at most halved in height. Returns h (m). Throws
// std::invalid_argument for a rod mesh, an open toe (no node on the axis), a bad angle, or
// a pile shorter than 2 h.
double shape_conical_toe(PileMesh& mesh, double apex_angle_deg);

// A cone's height from its base radius and apex angle (degrees): R / tan(angle / 2).
double cone_height(double radius, double apex_angle_deg);

}  // namespace pilempm::fem
