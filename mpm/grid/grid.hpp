#pragma once
// Rectilinear background grid, uniform or graded per axis (O(1) cell lookup either way),
// stored in blocks of nodes: only the blocks the material points reach hold node data, so a box of
// kilometres of half-space costs memory where the soil is, not where the grid is.
// - Nodes have a global number (x fastest, then y, then z) for setting up and reporting,
//   and, while their block is active, a stored index into the node arrays.
// - Each node holds `fields` velocity fields (mass, momentum, force, velocity,
//   acceleration per field): the solid, the pore water, one per side of a body in contact.
//   Field f of stored node n is entry n * fields + f.
// - Supports, prescribed velocities, dashpots and walls are NodeConditions on the nodes
//   they name; the solver looks them up through the stored node.
#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace pilempm::mpm {

// What a boundary does at one node, for every velocity field there.
struct NodeCondition {
    int node = 0;                   // global node number
    unsigned char fixed[3] = {0, 0, 0};  // the velocity component is prescribed
    double prescribed[3] = {0, 0, 0};   // m/s (0 for supports)
    double dashpot[3] = {0, 0, 0};      // N s/m (absorbing boundaries)
    int wall = -1;                  // rigid Coulomb wall: axis * 2 + side, -1 none
    double wall_friction = 0.0;
    double reaction[3] = {0, 0, 0};     // N: what the prescription and the wall exerted last step
    // Pore water (grids with water fields): a fixed component holds the water too (an
    // impermeable boundary) unless the boundary is drained; the water's own dashpots.
    bool drained = false;
    double water_dashpot[3] = {0, 0, 0};  // N s/m
    // Absorbing boundaries (normal axes): held like a roller in static stages, whose
    // reaction they keep as a constant force through the dynamic stages after (the weight
    // the far field carried at rest), with their dashpots.
    unsigned char absorbing[3] = {0, 0, 0};
    double held_force[3] = {0, 0, 0};   // N
    // The far field's static stiffness behind an absorbing boundary (N/m), on the node's
    // displacement since it was held: a held force a little off balance then moves the
    // boundary a little instead of letting it creep for as long as the run lasts.
    double spring[3] = {0, 0, 0};
    double displacement[3] = {0, 0, 0};  // m, since the last static stage

    // At the node's turn in a grid update: last step's reactions cleared; a static stage
    // holds the boundary afresh (its force found again, its displacement counted from here).
    void begin_update(bool static_stage) {
        std::fill(reaction, reaction + 3, 0.0);
        if (!static_stage) return;
        std::fill(held_force, held_force + 3, 0.0);
        std::fill(displacement, displacement + 3, 0.0);
    }
    // N: the far field's spring along d on the displacement so far (outside static stages).
    double spring_force(int d) const { return -spring[d] * displacement[d]; }
    // The boundary moved from v0 to v1 over dt under the spring's force f: its displacement
    // grows, and the work done on the spring (J, stored in the far field) is returned.
    double move_far_field(int d, double f, double v0, double v1, double dt) {
        if (spring[d] <= 0.0) return 0.0;
        displacement[d] += 0.5 * (v0 + v1) * dt;
        return -0.5 * f * (v0 + v1) * dt;
    }
};

template <int D>
struct Grid {
    // Nodes along a block's edge: large enough that most stencils lie in one block (a uGIMP
    // stencil of 3 nodes per axis crosses into the next block at 2 of 16 or 8 positions).
    static constexpr int kBlockEdge = D == 2 ? 16 : 8;
    static constexpr int kBlockShift = D == 2 ? 4 : 3;
    static constexpr int kBlockNodes = D == 2 ? 256 : 512;

    std::array<double, D> origin{};
    // Along a uniform axis the cell size; along a graded one its smallest cell (what the
    // time step and the penetration's measure need).
    std::array<double, D> spacing{};
    std::array<int, D> cells{};
    // Graded axes: the node coordinates (cells + 1 of them); empty along a uniform axis.
    std::array<std::vector<double>, D> lines;
    int fields = 1;
    // Saturated soil: the fields come in pairs, solid 2k and its pore water 2k + 1.
    bool water = false;

    // Node data of the active blocks (stored nodes), reset each step.
    std::vector<double> mass;          // `fields` per stored node, kg (per radian when axisymmetric)
    std::vector<double> momentum;      // D per field
    std::vector<double> force;         // D per field, internal + external
    std::vector<double> velocity;      // D per field, after the update
    std::vector<double> acceleration;  // D per field
    std::vector<double> position;      // D per field (the node's, repeated), m: hot loops need no ijk()
    std::vector<int> condition_at;     // per stored node: index into conditions, -1 none
    // With water fields: the Darcy drag sum N n (mu/kappa) V (water entries) and the water's
    // inertia in the mixture's momentum, sum N n rho_w V (solid entries), per field.
    std::vector<double> drag;
    std::vector<double> water_inertia;

    std::vector<NodeCondition> conditions;
    // Edge planes (axis * 2 + side) the material cannot cross: fixed, roller and frictional
    // boundaries. A point carried past one by interpolation is put back on the plane.
    std::array<bool, 2 * D> closed{};

    // Sizes the block table for origin, spacing and cells; no block is active yet.
    void allocate();
    // Makes exactly the blocks marked (one byte per block, block numbers x fastest) active,
    // in block order; returns whether the set changed (node arrays and conditions remapped).
    bool set_active_blocks(const std::vector<unsigned char>& marked);
    void activate_all();  // every block (tests, small grids)
    const std::vector<unsigned char>& active_marks() const { return marked_; }
    int block_count() const { return static_cast<int>(slot_of_block_.size()); }
    int active_blocks() const { return static_cast<int>(block_of_slot_.size()); }
    int stored_nodes() const { return active_blocks() * kBlockNodes; }
    // The block holding global node ijk, and the blocks along each axis.
    int block_of(const std::array<int, D>& ijk) const {
        int b = 0;
        for (int d = D - 1; d >= 0; --d) b = b * blocks_[d] + (ijk[d] >> kBlockShift);
        return b;
    }
    const std::array<int, D>& blocks_along() const { return blocks_; }
    // Stored index of the node at ijk; -1 when its block is not active.
    int index(const std::array<int, D>& ijk) const {
        const int slot = slot_of_block_[block_of(ijk)];
        if (slot < 0) return -1;
        int local = 0;
        for (int d = D - 1; d >= 0; --d) local = local * kBlockEdge + (ijk[d] & (kBlockEdge - 1));
        return slot * kBlockNodes + local;
    }
    // The slot of a block (-1: inactive); stored index = slot * kBlockNodes + local, with
    // block = sum (i_d >> kBlockShift) block_stride(d), local = sum (i_d & (kBlockEdge - 1)) kBlockEdge^d.
    int slot_of_block(int block) const { return slot_of_block_[block]; }
    int block_stride(int d) const {
        int s = 1;
        for (int e = 0; e < d; ++e) s *= blocks_[e];
        return s;
    }
    std::array<int, D> stored_ijk(int stored) const;
    bool stored_node_exists(int stored) const;  // inside the grid (blocks overhang its edge)

    // The condition of a global node, created (all free) if it has none.
    NodeCondition& condition(int node);
    const NodeCondition* find_condition(int node) const;

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
    // Makes axis d graded with these node coordinates (increasing; origin, cells and
    // spacing follow from them).
    void set_lines(int d, std::vector<double> coordinates);
    bool graded(int d) const { return !lines[d].empty(); }
    // Node i's coordinate along axis d; past the edges (i < 0, i > cells) the edge cell repeats.
    double coordinate(int d, int i) const {
        if (lines[d].empty()) return origin[d] + spacing[d] * i;
        if (i < 0) return lines[d][0] + i * (lines[d][1] - lines[d][0]);
        if (i > cells[d]) return lines[d][cells[d]] + (i - cells[d]) * (lines[d][cells[d]] - lines[d][cells[d] - 1]);
        return lines[d][i];
    }
    double width(int d, int i) const { return coordinate(d, i + 1) - coordinate(d, i); }  // cell i's
    double top(int d) const { return coordinate(d, cells[d]); }
    // The length along axis d that node i stands for: half of each cell beside it.
    double tributary(int d, int i) const {
        return 0.5 * ((i > 0 ? width(d, i - 1) : 0.0) + (i < cells[d] ? width(d, i) : 0.0));
    }
    // Index of the cell holding x along axis d (clamped to the grid). A graded axis looks
    // in a table of bins of its smallest cell: a bin holds one cell boundary at most.
    int cell_of(int d, double x) const {
        const int i = static_cast<int>(std::floor((x - origin[d]) / spacing[d]));
        if (lines[d].empty()) return i < 0 ? 0 : (i >= cells[d] ? cells[d] - 1 : i);
        if (i < 0) return 0;
        if (i >= static_cast<int>(bin_cell_[d].size())) return cells[d] - 1;
        int c = bin_cell_[d][i];
        while (c < cells[d] - 1 && x >= lines[d][c + 1]) ++c;
        return c;
    }
    // The cell holding x (unclamped, may be -1 or cells): past the edges the edge cell repeats.
    int cell_beyond(int d, double x) const {
        if (x < origin[d]) return static_cast<int>(std::floor((x - origin[d]) / width(d, 0)));
        if (x >= top(d)) return cells[d] + static_cast<int>(std::floor((x - top(d)) / width(d, cells[d] - 1)));
        return cell_of(d, x);
    }
    bool inside(const double* x) const {
        for (int d = 0; d < D; ++d)
            if (x[d] < origin[d] || x[d] > top(d)) return false;
        return true;
    }
    // Bytes of node data per stored node (all fields), for memory reports.
    std::size_t bytes_per_stored_node() const;

private:
    std::array<std::vector<int>, D> bin_cell_;  // graded axes: the cell at each bin's start
    std::array<int, D> blocks_{};
    std::vector<int> slot_of_block_;
    std::vector<int> block_of_slot_;
    std::vector<unsigned char> marked_;
    bool remap_ = true;  // conditions were added since the last activation
    std::unordered_map<int, int> condition_of_node_;
};

}  // namespace pilempm::mpm
