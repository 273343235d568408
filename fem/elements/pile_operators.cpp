#include "fem/elements/pile_operators.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "fem/elements/element_kernels.hpp"

namespace pilempm::fem {

PileOperators assemble_pile_operators(PileMesh& mesh, const LinearElasticSteel& steel) {
    const int ndof_node = mesh.dofs_per_node();
    PileOperators ops;
    ops.lumped_mass.assign(mesh.num_dofs(), 0.0);
    for (auto& block : mesh.blocks) {
        const int nen = block.nodes_per_element;
        const int nde = nen * ndof_node;
        const int ne = block.num_elements();
        block.stiffness.assign(static_cast<std::size_t>(ne) * nde * nde, 0.0);
        block.axial_stress.assign(static_cast<std::size_t>(ne) * nde, 0.0);
        block.centroid_z.resize(ne);
        block.z_min.resize(ne);
        block.z_max.resize(ne);
        const bool rod = block.kind == ElementKind::Rod2;
        if (rod && static_cast<int>(block.section_area.size()) != ne)
            throw std::logic_error("rod block without section areas");
        if (!rod) block.section_area.resize(ne);

        std::vector<double> coords(nen * mesh.dim), mass_node(nen), mass_dof(nde);
        for (int e = 0; e < ne; ++e) {
            const int* conn = &block.connectivity[static_cast<std::size_t>(e) * nen];
            double zmin = 1e300, zmax = -1e300, zsum = 0.0, rmin = 1e300, rmax = -1e300;
            for (int a = 0; a < nen; ++a) {
                for (int d = 0; d < mesh.dim; ++d)
                    coords[a * mesh.dim + d] = mesh.coordinates[conn[a] * mesh.dim + d];
                const double z = mesh.z(conn[a]);
                zmin = std::min(zmin, z);
                zmax = std::max(zmax, z);
                zsum += z;
                if (mesh.dim == 2) {
                    rmin = std::min(rmin, coords[a * 2]);
                    rmax = std::max(rmax, coords[a * 2]);
                }
            }
            block.centroid_z[e] = zsum / nen;
            block.z_min[e] = zmin;
            block.z_max[e] = zmax;
            double* K = &block.stiffness[static_cast<std::size_t>(e) * nde * nde];
            double* S = &block.axial_stress[static_cast<std::size_t>(e) * nde];
            switch (block.kind) {
                case ElementKind::Rod2:
                    rod2_operators(coords.data(), block.section_area[e], steel, K,
                                   mass_node.data(), S);
                    break;
                case ElementKind::AxisymQuad4:
                    axisym_quad4_operators(coords.data(), steel, K, mass_node.data(), S);
                    block.section_area[e] = std::numbers::pi * (rmax * rmax - rmin * rmin);
                    break;
            }
            for (int a = 0; a < nen; ++a) {
                for (int d = 0; d < ndof_node; ++d) {
                    mass_dof[a * ndof_node + d] = mass_node[a];
                    ops.lumped_mass[conn[a] * ndof_node + d] += mass_node[a];
                }
                ops.total_mass += mass_node[a];
            }
            ops.max_frequency =
                std::max(ops.max_frequency, element_max_frequency(K, mass_dof.data(), nde));
        }
    }
    if (!(ops.max_frequency > 0.0)) throw std::logic_error("pile mesh has no stiffness");
    ops.stable_time_step = 2.0 / ops.max_frequency;
    return ops;
}

}  // namespace pilempm::fem
