#pragma once
// The FE pile as a contact master: the boundary edges of its axisymmetric wall (edges used
// by one quad only), named by where they lie, and placed in the soil's frame each step.
#include <vector>

#include "coupling/contact/contact_surface.hpp"
#include "fem/mesh/pile_mesh.hpp"

namespace pilempm::coupling {

// The pile's frame (toe at z = 0) in the soil's: soil y = pile z + toe_elevation; r alike.
struct PileFrame {
    double toe_elevation = 0.0;  // m, in the soil's frame
};

// The boundary of the mesh's AxisymQuad4 blocks as segments, node k of the surface being
// node k of the mesh; sides by the outward normal (outer r+, inner r-, toe z-, head z+).
// Throws std::invalid_argument for a rod mesh, which has no surface.
ContactSurface pile_contact_surface(const fem::PileMesh& mesh);

// Positions (reference + u, shifted into the soil's frame) and velocities of the nodes.
void place_pile_surface(ContactSurface& surface, const fem::PileMesh& mesh, const std::vector<double>& u,
                        const std::vector<double>& v, const PileFrame& frame);

// The wall's mid-line in the soil's frame, toe to head: at each level of the mesh's nodes
// (equal reference z) the middle of its radial extent, as a field cut's polyline (2 per
// vertex, ascending in y).
std::vector<double> pile_mid_line(const fem::PileMesh& mesh, const std::vector<double>& u, const PileFrame& frame);

// The toe's slip line and the shaft above it, as one field cut's polyline in the soil's
// frame (2 per vertex, ascending in y): a straight line `length` long from the toe's outer
// corner (a cone's shoulder) into the soil along the bisector of the corner's outward
// normals (45 deg down on a flat toe), then up the outer shaft to the head. The slip line
// splits the soil the toe pushes ahead from the soil beside the shaft; the shaft's part
// keeps the two from sharing the grid nodes inside the pile. From a placed surface.
std::vector<double> toe_slip_line(const ContactSurface& surface, double length);

}  // namespace pilempm::coupling
