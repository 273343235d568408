#include "coupling/contact/pile_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace pilempm::coupling {

ContactSurface pile_contact_surface(const fem::PileMesh& mesh) {
    if (mesh.dim != 2) throw std::invalid_argument("pile contact needs the axisymmetric wall mesh (a rod has no surface)");
    // Each edge of every quad, keyed by its sorted ends: those seen once are the boundary,
    // kept in the quad's (counter-clockwise) direction.
    std::map<std::pair<int, int>, std::pair<int, int>> once;
    for (const auto& block : mesh.blocks) {
        if (block.kind != fem::ElementKind::AxisymQuad4) continue;
        for (int e = 0; e < block.num_elements(); ++e) {
            const int* q = &block.connectivity[4 * e];
            for (int k = 0; k < 4; ++k) {
                const int from = q[k], to = q[(k + 1) % 4];
                const auto key = std::minmax(from, to);
                if (!once.erase(key)) once[key] = {from, to};
            }
        }
    }
    if (once.empty()) throw std::invalid_argument("pile contact: the mesh has no axisymmetric quads");
    ContactSurface s;
    s.x.assign(mesh.coordinates.begin(), mesh.coordinates.end());
    s.v.assign(mesh.coordinates.size(), 0.0);
    double r_max = 0.0;
    for (int i = 0; i < mesh.num_nodes(); ++i) r_max = std::max(r_max, mesh.coordinates[2 * i]);
    std::vector<bool> on_toe(mesh.num_nodes(), false);
    for (int node : mesh.toe_nodes) on_toe[node] = true;
    for (const auto& [key, edge] : once) {
        const double* xa = &mesh.coordinates[2 * edge.first];
        const double* xb = &mesh.coordinates[2 * edge.second];
        // A solid pile's edges on the axis are its symmetry line, not a surface.
        if (xa[0] <= 1e-12 * r_max && xb[0] <= 1e-12 * r_max) continue;
        const double tr = xb[0] - xa[0], tz = xb[1] - xa[1];
        const double nr = tz, nz = -tr;  // outward: to the right of a -> b
        // The toe row's edges are the toe whatever their slope (a cone's face is steeper than 45 deg).
        SurfaceSide side;
        if (on_toe[edge.first] && on_toe[edge.second]) side = SurfaceSide::Toe;
        else if (std::abs(nr) >= std::abs(nz)) side = nr > 0.0 ? SurfaceSide::Outer : SurfaceSide::Inner;
        else side = nz > 0.0 ? SurfaceSide::Head : SurfaceSide::Toe;
        s.add_segment(edge.first, edge.second, side);
    }
    return s;
}

void place_pile_surface(ContactSurface& surface, const fem::PileMesh& mesh, const std::vector<double>& u,
                        const std::vector<double>& v, const PileFrame& frame) {
    const int n = mesh.num_nodes();
    for (int i = 0; i < n; ++i) {
        surface.x[2 * i] = mesh.coordinates[2 * i] + u[2 * i];
        surface.x[2 * i + 1] = mesh.coordinates[2 * i + 1] + u[2 * i + 1] + frame.toe_elevation;
        surface.v[2 * i] = v[2 * i];
        surface.v[2 * i + 1] = v[2 * i + 1];
    }
}

std::vector<double> pile_mid_line(const fem::PileMesh& mesh, const std::vector<double>& u, const PileFrame& frame) {
    // Levels by reference z (the structured wall has one row of nodes per level).
    std::map<double, std::array<double, 3>> level;  // z -> {r_min, r_max, sum of current z}
    std::map<double, int> count;
    for (int i = 0; i < mesh.num_nodes(); ++i) {
        const double z = mesh.coordinates[2 * i + 1];
        const double r = mesh.coordinates[2 * i] + u[2 * i];
        const double zc = z + u[2 * i + 1] + frame.toe_elevation;
        auto [it, fresh] = level.try_emplace(z, std::array<double, 3>{r, r, 0.0});
        it->second[0] = std::min(it->second[0], r);
        it->second[1] = std::max(it->second[1], r);
        it->second[2] += zc;
        ++count[z];
    }
    std::vector<double> line;
    for (const auto& [z, l] : level) {
        line.push_back(0.5 * (l[0] + l[1]));
        line.push_back(l[2] / count[z]);
    }
    return line;
}

std::vector<double> toe_slip_line(const ContactSurface& surface, double length) {
    // The outer face's nodes, lowest (the corner) first, and the toe segment ending there.
    std::vector<int> outer;
    for (int k = 0; k < surface.num_segments(); ++k)
        if (surface.side[k] == SurfaceSide::Outer) {
            outer.push_back(surface.a[k]);
            outer.push_back(surface.b[k]);
        }
    if (outer.empty()) throw std::invalid_argument("a toe slip line needs a pile with an outer face");
    const auto& x = surface.x;
    std::sort(outer.begin(), outer.end(), [&](int i, int j) { return x[2 * i + 1] < x[2 * j + 1]; });
    outer.erase(std::unique(outer.begin(), outer.end()), outer.end());
    const int corner = outer.front();
    int from = -1;  // the toe segment's other node
    for (int k = 0; k < surface.num_segments(); ++k)
        if (surface.side[k] == SurfaceSide::Toe && (surface.a[k] == corner || surface.b[k] == corner))
            from = surface.a[k] == corner ? surface.b[k] : surface.a[k];
    if (from < 0) throw std::invalid_argument("a toe slip line needs a toe that meets the outer face");
    const double cx = x[2 * corner], cy = x[2 * corner + 1];
    const double ex = cx - x[2 * from], ey = cy - x[2 * from + 1], e = std::hypot(ex, ey);
    // The toe face's outward normal (the face runs outward from `from` to the corner) plus the shaft's.
    double bx = ey / e + 1.0, by = -ex / e;
    const double b = std::hypot(bx, by);
    std::vector<double> line = {cx + length * bx / b, cy + length * by / b};
    for (const int i : outer) {
        line.push_back(x[2 * i]);
        line.push_back(x[2 * i + 1]);
    }
    return line;
}

}  // namespace pilempm::coupling
