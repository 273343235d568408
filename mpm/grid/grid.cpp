#include "mpm/grid/grid.hpp"

#include <algorithm>
#include <stdexcept>

namespace pilempm::mpm {

template <int D>
void Grid<D>::allocate() {
    if (fields < 1) throw std::invalid_argument("a grid needs at least one velocity field");
    if (water && fields % 2 != 0) throw std::invalid_argument("a grid with water needs solid and water fields in pairs");
    int count = 1;
    for (int d = 0; d < D; ++d) {
        blocks_[d] = (cells[d] + 1 + kBlockEdge - 1) / kBlockEdge;
        count *= blocks_[d];
    }
    slot_of_block_.assign(count, -1);
    block_of_slot_.clear();
    marked_.assign(count, 0);
    remap_ = true;
    mass.clear();
    momentum.clear();
    force.clear();
    velocity.clear();
    acceleration.clear();
    position.clear();
    condition_at.clear();
    drag.clear();
    water_inertia.clear();
}

template <int D>
void Grid<D>::set_lines(int d, std::vector<double> coordinates) {
    if (coordinates.size() < 2) throw std::invalid_argument("a graded axis needs two nodes or more");
    double smallest = coordinates[1] - coordinates[0];
    for (std::size_t i = 1; i < coordinates.size(); ++i) {
        if (!(coordinates[i] > coordinates[i - 1])) throw std::invalid_argument("graded axis: node coordinates must increase");
        smallest = std::min(smallest, coordinates[i] - coordinates[i - 1]);
    }
    origin[d] = coordinates.front();
    cells[d] = static_cast<int>(coordinates.size()) - 1;
    spacing[d] = smallest;
    lines[d] = std::move(coordinates);
    // Bin k covers [origin + k h, origin + (k + 1) h) with h the smallest cell: the cell at
    // its start, then at most one step forward finds any x in it.
    const int bins = static_cast<int>(std::ceil((lines[d].back() - origin[d]) / smallest)) + 1;
    bin_cell_[d].assign(bins, 0);
    int c = 0;
    for (int k = 0; k < bins; ++k) {
        const double x = origin[d] + k * smallest;
        while (c < cells[d] - 1 && x >= lines[d][c + 1]) ++c;
        bin_cell_[d][k] = c;
    }
}

template <int D>
std::array<int, D> Grid<D>::stored_ijk(int stored) const {
    int block = block_of_slot_[stored / kBlockNodes], local = stored % kBlockNodes;
    std::array<int, D> c{};
    for (int d = 0; d < D; ++d) {
        c[d] = (block % blocks_[d]) * kBlockEdge + local % kBlockEdge;
        block /= blocks_[d];
        local /= kBlockEdge;
    }
    return c;
}

template <int D>
bool Grid<D>::stored_node_exists(int stored) const {
    const auto c = stored_ijk(stored);
    for (int d = 0; d < D; ++d)
        if (c[d] > cells[d]) return false;
    return true;
}

template <int D>
bool Grid<D>::set_active_blocks(const std::vector<unsigned char>& marked) {
    if (marked.size() != slot_of_block_.size()) throw std::logic_error("block marks of another grid");
    if (!remap_ && marked == marked_) return false;
    remap_ = false;
    marked_ = marked;
    block_of_slot_.clear();
    for (int b = 0; b < block_count(); ++b) {
        slot_of_block_[b] = marked[b] ? static_cast<int>(block_of_slot_.size()) : -1;
        if (marked[b]) block_of_slot_.push_back(b);
    }
    const std::size_t n = static_cast<std::size_t>(stored_nodes());
    const std::size_t nf = n * static_cast<std::size_t>(fields);
    mass.assign(nf, 0.0);
    momentum.assign(D * nf, 0.0);
    force.assign(D * nf, 0.0);
    velocity.assign(D * nf, 0.0);
    acceleration.assign(D * nf, 0.0);
    position.resize(D * nf);
    if (water) {
        drag.assign(nf, 0.0);
        water_inertia.assign(nf, 0.0);
    }
    for (std::size_t k = 0; k < n; ++k) {
        const auto c = stored_ijk(static_cast<int>(k));
        for (int f = 0; f < fields; ++f)
            for (int d = 0; d < D; ++d) position[D * (k * fields + f) + d] = coordinate(d, c[d]);
    }
    condition_at.assign(n, -1);
    for (std::size_t i = 0; i < conditions.size(); ++i) {
        auto& c = conditions[i];
        const int at = index(ijk(c.node));
        if (at >= 0) condition_at[at] = static_cast<int>(i);
        else std::fill(c.reaction, c.reaction + 3, 0.0);  // no material there: nothing pushes
    }
    return true;
}

template <int D>
void Grid<D>::activate_all() {
    set_active_blocks(std::vector<unsigned char>(slot_of_block_.size(), 1));
}

template <int D>
NodeCondition& Grid<D>::condition(int node) {
    const auto [it, fresh] = condition_of_node_.emplace(node, static_cast<int>(conditions.size()));
    if (fresh) {
        conditions.emplace_back();
        conditions.back().node = node;
        remap_ = true;  // the next activation maps it to its stored node
    }
    return conditions[it->second];
}

template <int D>
const NodeCondition* Grid<D>::find_condition(int node) const {
    const auto it = condition_of_node_.find(node);
    return it == condition_of_node_.end() ? nullptr : &conditions[it->second];
}

template <int D>
std::size_t Grid<D>::bytes_per_stored_node() const {
    // mass, momentum, force, velocity, acceleration and position per field (with water: drag
    // and water inertia); condition_at.
    return static_cast<std::size_t>(fields) * (1 + 5 * D + (water ? 2 : 0)) * sizeof(double) + sizeof(int);
}

template struct Grid<2>;
template struct Grid<3>;

}  // namespace pilempm::mpm
