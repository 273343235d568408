#pragma once
// Rectilinear background grid with uniform spacing per axis (O(1) cell lookup), node
// data as structure of arrays. Nodes are numbered x fastest, then y (then z).
#include <array>
#include <cmath>
#include <vector>

namespace pilempm::mpm {

template <int D>
struct Grid {
    std::array<double, D> origin{};
    std::array<double, D> spacing{};
    std::array<int, D> cells{};

    // Node data, reset each step (fixed and damping persist).
    std::vector<double> mass;          // kg (per radian when axisymmetric)
    std::vector<double> momentum;      // D per node
    std::vector<double> force;         // D per node, internal + external
    std::vector<double> velocity;      // D per node, after the update
    std::vector<double> acceleration;  // D per node
    std::vector<unsigned char> fixed;  // D per node: 1 = that velocity component is prescribed
    std::vector<double> prescribed;    // D per node: the prescribed velocity (0 for supports)
    std::vector<double> reaction;      // D per node: force the prescription exerted last step, N
    std::vector<double> dashpot;       // D per node, N s/m (absorbing boundaries)
    std::vector<double> position;      // D per node, m: kept so that hot loops need no ijk()
    // Rigid frictional walls (Coulomb): per node, the wall's axis * 2 + side (-1: none) and
    // the friction coefficient. The material may not move into the wall and slides on it.
    std::vector<int> wall;
    std::vector<double> wall_friction;
    // Edge planes (axis * 2 + side) the material cannot cross: fixed, roller and frictional
    // boundaries. A point carried past one by interpolation is put back on the plane.
    std::array<bool, 2 * D> closed{};

    void allocate();
    void reset();
    int nodes_along(int d) const { return cells[d] + 1; }
    int num_nodes() const {
        int n = 1;
        for (int d = 0; d < D; ++d) n *= cells[d] + 1;
        return n;
    }
    int node(const std::array<int, D>& ijk) const {
        int n = 0;
        for (int d = D - 1; d >= 0; --d) n = n * (cells[d] + 1) + ijk[d];
        return n;
    }
    std::array<int, D> ijk(int n) const {
        std::array<int, D> c{};
        for (int d = 0; d < D; ++d) {
            c[d] = n % (cells[d] + 1);
            n /= cells[d] + 1;
        }
        return c;
    }
    double coordinate(int d, int i) const { return origin[d] + spacing[d] * i; }
    // Index of the cell holding x along axis d (clamped to the grid).
    int cell_of(int d, double x) const {
        const int i = static_cast<int>(std::floor((x - origin[d]) / spacing[d]));
        return i < 0 ? 0 : (i >= cells[d] ? cells[d] - 1 : i);
    }
    bool inside(const double* x) const {
        for (int d = 0; d < D; ++d)
            if (x[d] < origin[d] || x[d] > origin[d] + spacing[d] * cells[d]) return false;
        return true;
    }
};

}  // namespace pilempm::mpm
