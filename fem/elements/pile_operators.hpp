#pragma once
#include <vector>

#include "fem/mesh/pile_mesh.hpp"

namespace pilempm::fem {

struct PileOperators {
    std::vector<double> lumped_mass;  // kg, one value per DOF
    double max_frequency = 0.0;       // rad/s, upper bound of the mesh's highest frequency
    double stable_time_step = 0.0;    // s, 2 / max_frequency (central difference limit)
    double total_mass = 0.0;          // kg
};

// Fills every block's stiffness, stress rows, centroids, axial extents and section areas
// (rod blocks keep the areas their mesher gave) and returns the lumped mass.
PileOperators assemble_pile_operators(PileMesh& mesh, const LinearElasticSteel& steel);

}  // namespace pilempm::fem
