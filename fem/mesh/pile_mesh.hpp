#pragma once
// The pile as a finite-element mesh: node coordinates and blocks of one element kind.
// Elements are linear elastic with small strain, so each block stores its element
// stiffness matrices once; the explicit step is then a batched K_e u_e product per block,
// free of per-element dispatch. New kinds (8-node hex, beam) only have to fill a block.
#include <vector>

namespace pilempm::fem {

enum class ElementKind { Rod2, AxisymQuad4 };

const char* element_kind_name(ElementKind kind);

struct ElementBlock {
    ElementKind kind = ElementKind::Rod2;
    int nodes_per_element = 2;
    std::vector<int> connectivity;  // nodes_per_element entries per element
    // Filled by assemble_pile_operators():
    std::vector<double> stiffness;     // (nen*ndof)^2 per element, row-major
    std::vector<double> axial_stress;  // nen*ndof per element: sigma_axial = row . u_e (centroid)
    std::vector<double> centroid_z;    // m
    std::vector<double> z_min, z_max;  // axial extent of each element, m
    std::vector<double> section_area;  // steel area the element carries in a cross-section, m^2

    int num_elements() const {
        return nodes_per_element ? static_cast<int>(connectivity.size()) / nodes_per_element : 0;
    }
};

struct PileMesh {
    // 1: rod, one axial coordinate/DOF per node. 2: axisymmetric (r, z), two DOFs per node.
    int dim = 1;
    std::vector<double> coordinates;  // dim per node; the last component is z (up)
    std::vector<ElementBlock> blocks;
    std::vector<int> head_nodes;  // nodes on the pile head (z = L)
    std::vector<int> toe_nodes;   // nodes on the toe (z = 0)

    int num_nodes() const { return dim ? static_cast<int>(coordinates.size()) / dim : 0; }
    int dofs_per_node() const { return dim; }
    int num_dofs() const { return static_cast<int>(coordinates.size()); }
    int axial_dof(int node) const { return node * dim + (dim - 1); }
    double z(int node) const { return coordinates[axial_dof(node)]; }
    // The pile's length L: its highest node (the toe at z = 0).
    double length() const {
        double L = 0.0;
        for (int i = 0; i < num_nodes(); ++i) L = L > z(i) ? L : z(i);
        return L;
    }
    int num_elements() const;
};

struct LinearElasticSteel {
    double youngs_modulus = 210e9;  // Pa
    double poisson_ratio = 0.3;
    double density = 7850.0;  // kg/m^3
    double wave_speed() const;  // bar wave speed sqrt(E/rho), m/s
};

}  // namespace pilempm::fem
