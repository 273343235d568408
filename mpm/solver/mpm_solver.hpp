#pragma once
// Explicit MPM (MUSL with a FLIP/PIC blend) for a single-phase (dry or drained) soil in
// plane strain, axisymmetry or 3D. One step: shape functions at the points, particles to
// grid (mass, momentum, forces), grid update with boundary conditions, grid to particles,
// the momentum mapped back (MUSL), the velocity gradient, the Jaumann-rotated stress update
// by each material's model in one batch.
#include <array>
#include <memory>
#include <vector>

#include "mpm/materials/constitutive_model.hpp"
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
    std::vector<SurfaceLoad> surface_loads;  // the active ones; set between steps
};

// What a step carries over besides the model: the clock and the energy ledger. A resumed run
// restores it from its checkpoint.
struct SolverState {
    double time = 0.0;             // s
    long steps = 0;
    double absorbed_energy = 0.0;  // J, work of the absorbing dashpots (energy leaving)
    double external_work = 0.0;    // J, work of the external forces (gravity, surface loads)
};

template <int D>
class MpmSolver {
public:
    explicit MpmSolver(MpmModel<D>& model);
    double stable_time_step() const;
    void step(double dt);

    double time() const { return time_; }
    long steps() const { return steps_; }
    double kinetic_energy() const;
    std::array<double, D> momentum() const;
    double total_mass() const;
    // ||unbalanced force|| / ||external force|| over the grid nodes of the last step.
    double unbalanced_force_ratio() const { return unbalanced_ratio_; }
    // Work done on the grid by the absorbing dashpots so far (energy leaving), J.
    double absorbed_energy() const { return absorbed_; }
    // Work done on the grid by the external forces (gravity, surface loads) so far, J.
    double external_work() const { return external_work_; }
    void set_time(double t, long steps) {
        time_ = t;
        steps_ = steps;
    }
    SolverState state() const { return {time_, steps_, absorbed_, external_work_}; }
    void restore(const SolverState& s) {
        time_ = s.time;
        steps_ = s.steps;
        absorbed_ = s.absorbed_energy;
        external_work_ = s.external_work;
    }

private:
    void velocity_toward_node(const Stencil<D>& s, int k, const double* v, const double* C, double* out) const;
    void check_points_inside() const;
    void build_stencil(long i);
    void particles_to_grid();
    void update_grid(double dt);
    void grid_to_point(long i, double dt);
    void update_points_and_remap(double dt);
    void update_stress(double dt);
    template <class Accumulate>
    void scatter(int fields, Accumulate&& accumulate, std::vector<double>& out);

    MpmModel<D>& m_;
    std::vector<Stencil<D>> stencil_;
    std::vector<std::vector<int>> points_of_material_;
    std::vector<int> tensor_states_;  // per material: symmetric tensors rotated with the stress
    std::vector<std::vector<double>> thread_buffer_;
    std::vector<double> scratch_;
    std::vector<double> external_;  // D per node: gravity and tractions, for the equilibrium measure
    std::vector<double> residual_;  // D per node: unbalanced force after the walls' reaction
    double time_ = 0.0;
    double mass_ = 0.0;
    long steps_ = 0;
    double unbalanced_ratio_ = 0.0;
    double absorbed_ = 0.0;
    double external_work_ = 0.0;
};

}  // namespace pilempm::mpm
