#pragma once
// Explicit MPM (MUSL with a FLIP/PIC blend) for a single-phase (dry or drained) soil in
// plane strain, axisymmetry or 3D. One step: shape functions at the points, particles to
// grid (mass, momentum, forces), grid update with boundary conditions, grid to particles,
// the momentum mapped back (MUSL), the velocity gradient, the Jaumann-rotated stress update
// by each material's model in one batch.
#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "mpm/materials/constitutive_model.hpp"
#include "mpm/materials/pore_water.hpp"
#include "mpm/grid/field_cut.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/points/particles.hpp"
#include "mpm/grid/shape_functions.hpp"

namespace pilempm::mpm {

// A load on the face of a material point (a pressure on a free surface): it acts at the
// point's face, x_p + F offset, through the grid hats there, so the traction is delivered
// where the surface is rather than at the point's centre.
struct SurfaceLoad {
    int point = 0;
    double offset[3] = {0, 0, 0};  // from the centre to the loaded face, undeformed, m
    double force[3] = {0, 0, 0};   // N (per radian in axisymmetry)
};

// A point against an impermeable body's surface (the FE pile, set by coupling each step):
// the surface's unit normal, pointing into the soil, and a point on it. The pore water does
// not cross it relative to the skeleton (Solver: hold_water_at_walls).
struct WaterWall {
    long point = 0;
    double normal[3] = {0, 0, 0};
    double on_surface[3] = {0, 0, 0};  // m
};

template <int D>
struct MpmModel {
    Grid<D> grid;
    Particles<D> particles;
    std::vector<std::unique_ptr<ConstitutiveModel>> materials;
    ShapeKind shape = ShapeKind::GIMP;
    bool axisymmetric = false;          // D = 2 only: x = r
    std::array<double, D> gravity{};    // m/s^2
    double flip = 0.98;                 // FLIP fraction of the particle velocity update
    bool apic = false;                  // affine PIC transfers (flip unused)
    double cfl = 0.5;                   // of the P-wave crossing time of a cell
    double local_damping = 0.0;         // Cundall's alpha (quasi-static stages)
    // Each point's volumetric strain increment replaced by the mass-weighted mean of its
    // neighbours', projected on the grid's nodes and read back: against volumetric locking
    // of near-isochoric flow (plastic flow at zero dilatancy, undrained soil).
    bool smooth_dilatation = false;
    std::vector<SurfaceLoad> surface_loads;  // the active ones; set between steps
    // Saturated soil: per material how it drains (empty: all dry), and the pore water. A
    // coupled material needs a grid with water fields (Grid::water).
    std::vector<MaterialDrainage> drainage;
    PoreWater water;
    // Thin walls the grid's fields are cut along (D = 2; a pile's wall, set by coupling).
    std::vector<FieldCut> field_cuts;
    std::vector<WaterWall> water_walls;  // grids with water fields only
    bool saturated() const {
        for (const auto& d : drainage)
            if (d.saturated()) return true;
        return false;
    }
};

// What sets the stable time step, for `pilempm check` and logs.
struct TimeStepLimit {
    double dt = 0.0;               // s
    std::string limited_by;        // the wave that sets it, and at which point
    double wave_speed = 0.0;       // m/s, that wave's speed plus the point's speed
    // Coupled materials: the step an explicit Darcy drag would need, 2 k / (n g) (Mieremet
    // et al. 2016); the drag here is semi-implicit, so it does not limit. 0: none coupled.
    double explicit_drag_limit = 0.0;
};

// What a step carries over besides the model: the clock and the energy ledger. A resumed run
// restores it from its checkpoint.
struct SolverState {
    double time = 0.0;             // s
    long steps = 0;
    double absorbed_energy = 0.0;  // J, work of the absorbing dashpots (energy leaving)
    double external_work = 0.0;    // J, work of the external forces (gravity, surface loads)
    std::vector<double> held_force;  // N, 3 per grid condition: what absorbing boundaries hold
    std::vector<double> boundary_displacement;  // m, 3 per grid condition: since they were held
};

// Memory of a run: per point (its arrays and its stored stencil) and per stored grid node
// (node data, the solver's per-node arrays and one scatter buffer per thread).
struct MpmMemory {
    std::size_t points = 0, stored_nodes = 0, grid_nodes = 0;
    std::size_t bytes_per_point = 0, bytes_per_stored_node = 0;
    std::size_t total_bytes() const { return points * bytes_per_point + stored_nodes * bytes_per_stored_node; }
};

template <int D>
class MpmSolver {
public:
    explicit MpmSolver(MpmModel<D>& model);
    double stable_time_step() const;
    TimeStepLimit time_step_limit() const;
    void step(double dt);
    // Stores the grid blocks the points reach (each step does it first); throws when a point
    // has left the grid.
    void activate_grid();

    double time() const { return time_; }
    long steps() const { return steps_; }
    double kinetic_energy() const;
    // As stored after the last step (or the first activation).
    MpmMemory memory() const;
    std::array<double, D> momentum() const;
    double total_mass() const;
    // ||unbalanced force|| / ||external force|| over the grid nodes of the last step.
    double unbalanced_force_ratio() const { return unbalanced_ratio_; }
    // An implicit stage's own measure of it (the explicit steps compute theirs).
    void set_unbalanced_force_ratio(double ratio) { unbalanced_ratio_ = ratio; }
    // Work done on the grid by the absorbing dashpots so far (energy leaving), J.
    double absorbed_energy() const { return absorbed_; }
    // Work done on the grid by the external forces (gravity, surface loads) so far, J.
    double external_work() const { return external_work_; }
    // A stage in which the pore water drains freely (a drained nil step): coupled materials
    // step as drained ones, the water with the skeleton at hydrostatic pressure, until set
    // back. Their points' excess pressure and relative water velocity are zeroed whenever
    // this changes (the drained state is where a coupled stage after it starts).
    void set_drained(bool drained);
    bool drained() const { return drained_; }
    void set_time(double t, long steps) {
        time_ = t;
        steps_ = steps;
    }
    // Each point's weights (grid entries and N) of the last step's scatter, and the grid's
    // masses of that step in model().grid.mass: what a contact needs for its stable step.
    const std::vector<Stencil<D>>& stencils() const { return stencil_; }
    SolverState state() const;
    void restore(const SolverState& s);
    // Static stages (quasi-static): absorbing boundaries hold their normal and record the
    // reaction; dynamic ones: they absorb and keep applying that reaction.
    void set_static_boundaries(bool is_static) { static_boundaries_ = is_static; }

private:
    void velocity_toward_node(const Stencil<D>& s, int k, const double* v, const double* C, double* out) const;
    // A node lighter than this holds no material: a fraction of a point's mean mass, so that
    // the threshold does not depend on how large the grid is.
    double empty_node_mass() const {
        return 1e-12 * mass_ / static_cast<double>(std::max<std::size_t>(1, m_.particles.size()));
    }
    void half_edges(long i, double* half) const;
    void face_of(const SurfaceLoad& load, double* x) const;
    void build_stencil(long i);
    void particles_to_grid();
    template <bool PointForces>
    void scatter_to_grid();
    void update_grid(double dt);
    void walls_and_balance(double dt, double applied);
    void grid_to_point(long i, double dt);
    void update_points_and_remap(double dt);
    void update_stress(double dt);
    void smooth_dilatation();
    // Saturated soil (mpm_solver_pore_water.cpp): the scatter with buoyancy, the mixture's
    // stress and the water field; the coupled v-w grid update with semi-implicit drag; the
    // water's velocity on the points; the excess pore pressure and porosity.
    void scatter_saturated();
    void update_grid_coupled(double dt);
    void water_to_point(long i, double dt);
    void hold_water_at_walls(double dt);
    void mark_water_walls();
    void update_pore_water(double dt);
    double point_wave_speed(long i) const;  // P-wave speed for the stable step, m/s
    template <class Accumulate>
    void scatter(int values, Accumulate&& accumulate, std::vector<double>& out);

    MpmModel<D>& m_;
    bool saturated_ = false;  // some material holds water
    bool coupled_ = false;    // ... with its own velocity field (v-w)
    bool drained_ = false;    // coupled materials held drained (set_drained)
    bool static_boundaries_ = false;  // absorbing boundaries held (set_static_boundaries)
    std::vector<MaterialDrainage> drainage_;  // per material (dry when the model gives none)
    std::vector<double> volume_before_;       // per point: volume before this step's update
    std::vector<int> void_ratio_state_;       // per material: its state "void_ratio" (-1: none), set from the porosity
    std::vector<Stencil<D>> stencil_;
    std::vector<std::vector<int>> points_of_material_;
    std::vector<int> tensor_states_;  // per material: symmetric tensors rotated with the stress
    std::vector<std::vector<double>> thread_buffer_;
    std::vector<double> scratch_;
    std::vector<double> dilatation_;  // 2 per stored node and field: sum N m de_v, sum N m
    std::vector<unsigned char> block_marks_;
    std::vector<int> chunk_blocks_;  // per chunk of points: first and last slot its points reach (-1: none)
    // Chunk c of `chunks` is the points [chunk_begin(c), chunk_begin(c + 1)).
    long chunk_begin(int chunk, int chunks) const {
        return static_cast<long>(m_.particles.size()) * chunk / chunks;
    }
    std::vector<double> external_;  // D per stored node and field: gravity and tractions (equilibrium measure)
    std::vector<double> wall_normal_;  // D per stored node and field: impermeable walls' normals summed
    std::vector<int> wall_entries_;    // the solid entries wall_normal_ marks
    std::vector<double> residual_;  // D per stored node and field: unbalanced force after the walls' reaction
    double time_ = 0.0;
    double mass_ = 0.0;
    long steps_ = 0;
    double unbalanced_ratio_ = 0.0;
    double absorbed_ = 0.0;
    double external_work_ = 0.0;
};

}  // namespace pilempm::mpm
