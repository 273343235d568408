#include "mpm/grid/grid.hpp"

#include <algorithm>

namespace pilempm::mpm {

template <int D>
void Grid<D>::allocate() {
    const std::size_t n = num_nodes();
    mass.assign(n, 0.0);
    momentum.assign(D * n, 0.0);
    force.assign(D * n, 0.0);
    velocity.assign(D * n, 0.0);
    acceleration.assign(D * n, 0.0);
    fixed.assign(D * n, 0);
    prescribed.assign(D * n, 0.0);
    reaction.assign(D * n, 0.0);
    dashpot.assign(D * n, 0.0);
    wall.assign(n, -1);
    wall_friction.assign(n, 0.0);
    position.resize(D * n);
    for (std::size_t k = 0; k < n; ++k) {
        const auto idx = ijk(static_cast<int>(k));
        for (int d = 0; d < D; ++d) position[D * k + d] = coordinate(d, idx[d]);
    }
}

template <int D>
void Grid<D>::reset() {
    std::fill(mass.begin(), mass.end(), 0.0);
    std::fill(momentum.begin(), momentum.end(), 0.0);
    std::fill(force.begin(), force.end(), 0.0);
}

template struct Grid<2>;
template struct Grid<3>;

}  // namespace pilempm::mpm
