#pragma once
// Explicit central-difference dynamics of the FE pile (lumped mass, linear elastic).
// The head section moves as a rigid plate (the helmet enforces it), so the hammer sees
// one axial DOF; the toe is free, fixed, or on a dashpot.
#include <algorithm>
#include <vector>

#include "fem/mesh/pile_mesh.hpp"
#include "fem/elements/pile_operators.hpp"

namespace pilempm::fem {

enum class ToeCondition { Free, Fixed, Dashpot };

struct ToeSupport {
    ToeCondition condition = ToeCondition::Free;
    double impedance = 0.0;  // N s/m, of the whole toe, for the dashpot
};

class ExplicitPile {
public:
    ExplicitPile(PileMesh mesh, const LinearElasticSteel& steel, ToeSupport toe);

    const PileMesh& mesh() const { return mesh_; }
    const LinearElasticSteel& steel() const { return steel_; }
    const PileOperators& operators() const { return ops_; }
    double stable_time_step() const { return ops_.stable_time_step; }

    // One step: f_int = K u_n, then v_{n+1/2} from the forces at t_n, then (after the
    // caller's contact corrections to v) u_{n+1} = u_n + dt v_{n+1/2}.
    void compute_internal_force();
    void advance_velocity(double dt);
    void advance_displacement(double dt);
    void clear_external_force();

    // The rigid head plate, axial direction, up positive.
    double head_mass() const { return head_mass_; }
    double head_velocity() const { return v_[mesh_.axial_dof(mesh_.head_nodes.front())]; }
    double head_displacement() const { return u_[mesh_.axial_dof(mesh_.head_nodes.front())]; }
    void add_head_force(double force_up);
    void add_head_velocity(double dv_up);
    // Generic nodal loads and dashpots for whatever acts on the pile (soil springs).
    void add_nodal_force(int dof, double force) { f_ext_[dof] += force; }
    void add_nodal_damping(int dof, double c);

    // Toe reaction (force of the support on the pile, up positive) of the last step.
    double toe_reaction() const { return toe_reaction_; }
    double toe_velocity() const;      // mass-weighted mean axial velocity, up positive
    double toe_displacement() const;  // mean axial displacement, up positive

    const std::vector<double>& displacement() const { return u_; }
    const std::vector<double>& velocity() const { return v_; }  // at t_{n+1/2}
    const std::vector<double>& internal_force() const { return f_int_; }

    // Axial stress at each element's centroid (Pa, tension positive), all blocks in order.
    void axial_stress(std::vector<double>& out) const;
    double strain_energy() const;  // 0.5 u.K u, with f_int of the current u
    double kinetic_energy(const std::vector<double>& v) const;
    double dashpot_power(const std::vector<double>& v) const;  // W, rate of dissipation
    // Brings the pile to rest: zeroes every velocity (kinetic damping between blows).
    void stop() { std::fill(v_.begin(), v_.end(), 0.0); }
    // Stiffness-proportional (Rayleigh) damping beta K v: it damps the pile's vibration,
    // strongest at high frequency (the coupling's modes near pi / dt), and leaves rigid
    // motion alone, so a pile pushed at a steady speed feels no drag from it. 0: none.
    void set_stiffness_damping(double beta) { stiffness_damping_ = beta; }
    // Damping of the vibration about the pile's rigid motion (damped stages): each DOF's
    // velocity relative to the pile's mean axial velocity (radially: to rest) decays at
    // rate c, 1/s, exactly over each step. Its forces sum to zero, so it neither drags a
    // pile pushed at a steady speed (Cundall's local damping on the DOFs did: a jacked
    // pile's force +70 %) nor shrinks the stable step (stiffness damping strong in a long
    // pile's first mode is overdamped in its wall's through-thickness modes: 150 substeps
    // a soil step for a 77 m monopile). 0: none.
    void set_vibration_damping(double rate) { vibration_damping_ = rate; }
    // Cundall's local damping: each DOF's unbalanced force less alpha times its size against
    // its motion. It brings a pile rocking on the soil to rest (a blow settling), and drags
    // a pile pushed at a steady speed, so it is not for jacking. 0: none.
    void set_local_damping(double alpha) { local_damping_ = alpha; }
    // Cundall's local damping split in two: the rigid axial motion (the resultant axial force
    // less alpha times its size against the mean axial velocity, spread by mass) and the
    // vibration about it (each DOF's force and velocity relative to the rigid ones, those
    // damping forces made to sum to zero). Per DOF alone it would also resist the rigid drift
    // through the vibration's noisy forces, like friction: a pile resting on soil stood 0.3 %
    // out of balance; on the rigid motion alone a pile chattered on its contact. 0: none.
    void set_split_damping(double alpha) { split_damping_ = alpha; }
    // The stable step with that damping (the undamped one when beta = 0).
    double damped_stable_time_step() const;
    // Moves the whole pile axially by delta (m, up positive) without straining it.
    void translate_axially(double delta);
    // A checkpoint's state back: u_n and v_{n-1/2}, a value per DOF each.
    // f_int: the internal force as the run had it (strain_energy() reads it until the next
    // step computes it); empty: computed from u.
    void restore(const std::vector<double>& u, const std::vector<double>& v, const std::vector<double>& f_int = {});

private:
    // v_{n+1/2} = (keep v_{n-1/2} + f) / scale, with keep and scale = m / dt -+ c / 2.
    struct VelocityUpdate {
        double dt = 0.0;  // 0: not computed
        std::vector<double> keep, scale;
    };
    const VelocityUpdate& velocity_update(double dt);
    void list_reaction_dofs();
    double support_reaction(const VelocityUpdate& c) const;
    void damp_vibration(double dt);
    void advance_velocity_split_damping(const VelocityUpdate& c);

    PileMesh mesh_;
    LinearElasticSteel steel_;
    PileOperators ops_;
    ToeSupport toe_;
    std::vector<double> u_, v_, f_int_, f_ext_;
    std::vector<double> damping_;       // N s/m per DOF (toe dashpot)
    std::vector<char> fixed_;           // per DOF
    std::vector<int> reaction_dofs_;    // fixed or damped DOFs, ascending
    bool reaction_dofs_listed_ = false;
    VelocityUpdate update_cache_[2];
    int next_slot_ = 0;
    std::vector<int> head_dofs_;
    bool rod_chain_ = false;            // one rod block, element e on nodes e, e + 1
    double head_mass_ = 0.0;
    double toe_reaction_ = 0.0;
    double stiffness_damping_ = 0.0;  // beta, s
    double vibration_damping_ = 0.0;  // 1/s (set_vibration_damping)
    double local_damping_ = 0.0;      // Cundall's alpha
    double split_damping_ = 0.0;      // Cundall's alpha, split: rigid motion and vibration
    std::vector<double> damped_u_;     // u + beta v (scratch)
    std::vector<double> damping_scratch_;  // split damping's vibration forces (scratch)
};

}  // namespace pilempm::fem
