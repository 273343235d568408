#pragma once
// Eigen-decomposition of a symmetric 3x3 tensor in Voigt order [xx yy zz xy yz zx] (core/voigt.hpp),
// for constitutive updates that work in principal space at every point and step: no
// allocation, no trigonometry, and a closed form for the plane tensors of every 2D run.
#include <cmath>

namespace pilempm::core {

// The in-plane principal pair of a plane tensor (yz = zx = 0): mean +- radius of Mohr's circle.
struct PlanePrincipalPair {
    double mean, half, radius;  // half: (xx - yy) / 2
};
inline PlanePrincipalPair plane_principal_pair(const double* t) {
    const double mean = 0.5 * (t[0] + t[1]), half = 0.5 * (t[0] - t[1]);
    return {mean, half, std::sqrt(half * half + t[3] * t[3])};
}

// Eigenvalues d and unit eigenvectors q[i] (Cartesian components, unsorted) of the symmetric
// tensor t, by cyclic Jacobi rotations (one square root and one division per rotation). In
// the frame of a nearby decomposition (frame: its eigenvectors as rows, or null) the tensor
// is already almost diagonal, and one sweep or two reach rounding; without one, from the
// Cartesian axes. A plane tensor is solved in closed form (d[0] >= d[1] its in-plane pair,
// d[2] = zz), a diagonal one taken as it is (its eigenvalues are its entries exactly).
void symmetric_eigen3(const double* t, const double (*frame)[3], double d[3], double q[3][3]);

}  // namespace pilempm::core
