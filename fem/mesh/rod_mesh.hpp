#pragma once
#include "fem/mesh/pile_geometry.hpp"
#include "fem/mesh/pile_mesh.hpp"

namespace pilempm::fem {

// 2-node rod elements along the axis; every station is a node, so tapers are resolved.
// Each element carries the steel area at its mid-height.
PileMesh mesh_rod(const PileGeometry& geometry, double element_size);

}  // namespace pilempm::fem
