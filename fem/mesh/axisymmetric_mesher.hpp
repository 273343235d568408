#pragma once
// Structured mesh of the pile's tube wall in the (r, z) plane, built by gmsh from the same
// stations as the rod model, so both models describe the same steel.
#include <string>

#include "fem/mesh/pile_geometry.hpp"
#include "fem/mesh/pile_mesh.hpp"

namespace pilempm::fem {

// Meshes the tube wall of `geometry` with 4-node axisymmetric quads through gmsh.
// element_size: target size along the axis (m); radial_divisions: elements through the wall (>=1).
// Returns dim = 2, (r, z) per node, one AxisymQuad4 block with counter-clockwise
// connectivity, and head/toe nodes sorted by r; derived arrays (section_area, ...) are left
// empty. Throws std::invalid_argument for bad arguments or a radius step (two stations at
// the same z with different radii: the structured wall cannot join them conformingly) and
// std::runtime_error naming `geo_file` when the file is missing or gmsh fails.
PileMesh mesh_axisymmetric_wall(const PileGeometry& geometry, double element_size,
                                int radial_divisions, const std::string& geo_file);

// Path of meshes/pile_wall_axisymmetric.geo: in $PILEMPM_MESH_DIR if set, else in the
// directory compiled in as PILEMPM_MESH_DIR_DEFAULT, else in "meshes" (relative to the cwd).
std::string default_pile_wall_geo();

}  // namespace pilempm::fem
