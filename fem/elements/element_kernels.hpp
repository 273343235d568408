#pragma once
// Per-element operators of each element kind: stiffness, lumped mass, and the row that
// recovers the axial stress at the centroid. Pure functions of geometry and material.
#include "fem/mesh/pile_mesh.hpp"

namespace pilempm::fem {

// 2-node axial rod between elevations z[0] < z[1] with cross-section area `area`.
// K: 2x2, mass: 2, stress_row: 2 (axial DOFs).
void rod2_operators(const double z[2], double area, const LinearElasticSteel& steel,
                    double* K, double* mass, double* stress_row);

// 4-node axisymmetric quad, nodes counter-clockwise in the (r, z) plane, r > 0 for the
// tube wall; DOFs (u_r, u_z) per node. Integrated over the full circumference (2 pi r),
// so forces are those of the whole tube. 2x2 Gauss.
// K: 8x8, mass: 4 (one value per node, both DOFs), stress_row: 8 (sigma_zz at centroid).
void axisym_quad4_operators(const double rz[8], const LinearElasticSteel& steel, double* K,
                            double* mass, double* stress_row);

// Largest eigenfrequency (rad/s) of an element's K x = w^2 M x with lumped M; bounds the
// mesh's highest frequency from above, so dt = 2 / max_e(w_e) is stable for any kind.
double element_max_frequency(const double* K, const double* mass_per_dof, int ndof);

}  // namespace pilempm::fem
