#include "fem/mesh/rod_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pilempm::fem {

PileMesh mesh_rod(const PileGeometry& geometry, double element_size) {
    if (!(element_size > 0.0)) throw std::invalid_argument("element size must be positive");
    PileMesh mesh;
    mesh.dim = 1;
    const auto& st = geometry.stations;
    mesh.coordinates.push_back(st.front().z);
    for (std::size_t i = 1; i < st.size(); ++i) {
        const double h = st[i].z - st[i - 1].z;
        if (h <= 0.0) continue;  // a step in wall thickness: no length to mesh
        const int n = std::max(1, static_cast<int>(std::lround(h / element_size)));
        for (int k = 1; k <= n; ++k) mesh.coordinates.push_back(st[i - 1].z + h * k / n);
    }
    ElementBlock block;
    block.kind = ElementKind::Rod2;
    block.nodes_per_element = 2;
    const int nn = mesh.num_nodes();
    for (int e = 0; e + 1 < nn; ++e) {
        block.connectivity.push_back(e);
        block.connectivity.push_back(e + 1);
        block.section_area.push_back(
            geometry.area_at(0.5 * (mesh.coordinates[e] + mesh.coordinates[e + 1])));
    }
    mesh.blocks.push_back(std::move(block));
    mesh.toe_nodes = {0};
    mesh.head_nodes = {nn - 1};
    return mesh;
}

int PileMesh::num_elements() const {
    int n = 0;
    for (const auto& b : blocks) n += b.num_elements();
    return n;
}

}  // namespace pilempm::fem
