#include "fem/mesh/conical_toe.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace pilempm::fem {

double cone_height(double radius, double apex_angle_deg) {
    return radius / std::tan(0.5 * apex_angle_deg * std::numbers::pi / 180.0);
}

double shape_conical_toe(PileMesh& mesh, double apex_angle_deg) {
    if (mesh.dim != 2) throw std::invalid_argument("a conical toe needs the axisymmetric wall mesh, not a rod");
    if (!(apex_angle_deg > 0.0 && apex_angle_deg < 180.0))
        throw std::invalid_argument("a cone's apex angle must be between 0 and 180 degrees, got " +
                                    std::to_string(apex_angle_deg));
    double inner = 1e300, outer = 0.0, length = 0.0;
    for (int node : mesh.toe_nodes) {
        inner = std::min(inner, mesh.coordinates[2 * node]);
        outer = std::max(outer, mesh.coordinates[2 * node]);
    }
    for (int i = 0; i < mesh.num_nodes(); ++i) length = std::max(length, mesh.z(i));
    if (mesh.toe_nodes.empty() || inner > 1e-12 * outer)
        throw std::invalid_argument("a conical toe needs a closed-ended (solid) toe; this pile is open at its toe");
    const double height = cone_height(outer, apex_angle_deg);
    const double blend = 2.0 * height;
    if (blend >= length)
        throw std::invalid_argument("the pile (" + std::to_string(length) + " m) is too short for its cone (" +
                                    std::to_string(height) + " m high; the mesh is shaped over twice that)");
    for (int i = 0; i < mesh.num_nodes(); ++i) {
        const double r = mesh.coordinates[2 * i];
        double& z = mesh.coordinates[2 * i + 1];
        if (z < blend) z += height * (r / outer) * (1.0 - z / blend);
    }
    return height;
}

}  // namespace pilempm::fem
