#include "fem/dynamics/explicit_pile.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace pilempm::fem {

namespace {

// f_int of a lone rod block whose elements chain the nodes in order (element e joins
// nodes e and e + 1, as mesh_rod makes them). The same sums as add_block_forces, in the
// same order (node i: element i - 1, then element i), so bit-identical; but with no call
// per element and no store-to-load chain through f, several times faster.
void rod_chain_forces(const ElementBlock& block, const std::vector<double>& u, std::vector<double>& f) {
    const int ne = block.num_elements();
    const double* K = block.stiffness.data();
    auto lower = [&](int e) { return 0.0 + K[4 * e] * u[e] + K[4 * e + 1] * u[e + 1]; };
    auto upper = [&](int e) { return 0.0 + K[4 * e + 2] * u[e] + K[4 * e + 3] * u[e + 1]; };
    f[0] = 0.0 + lower(0);
    for (int i = 1; i < ne; ++i) f[i] = (0.0 + upper(i - 1)) + lower(i);
    f[ne] = 0.0 + upper(ne - 1);
}

// Any block: gather u_e, multiply by the stored K_e, scatter.
void add_block_forces(const ElementBlock& block, int ndn, const std::vector<double>& u,
                      std::vector<double>& f) {
    const int nen = block.nodes_per_element;
    const int nde = nen * ndn;
    const int ne = block.num_elements();
    double ue[32], fe[32];
    for (int e = 0; e < ne; ++e) {
        const int* conn = &block.connectivity[static_cast<std::size_t>(e) * nen];
        for (int a = 0; a < nen; ++a)
            for (int d = 0; d < ndn; ++d) ue[a * ndn + d] = u[conn[a] * ndn + d];
        const double* K = &block.stiffness[static_cast<std::size_t>(e) * nde * nde];
        for (int i = 0; i < nde; ++i) {
            double s = 0.0;
            for (int j = 0; j < nde; ++j) s += K[i * nde + j] * ue[j];
            fe[i] = s;
        }
        for (int a = 0; a < nen; ++a)
            for (int d = 0; d < ndn; ++d) f[conn[a] * ndn + d] += fe[a * ndn + d];
    }
}

bool is_rod_block(const ElementBlock& block, int ndn) {
    return block.kind == ElementKind::Rod2 && block.nodes_per_element == 2 && ndn == 1;
}

bool is_rod_chain(const PileMesh& mesh) {
    if (mesh.blocks.size() != 1 || !is_rod_block(mesh.blocks[0], mesh.dofs_per_node())) return false;
    const auto& block = mesh.blocks[0];
    if (block.num_elements() < 1 || block.num_elements() + 1 != mesh.num_dofs()) return false;
    for (int e = 0; e < block.num_elements(); ++e)
        if (block.connectivity[2 * e] != e || block.connectivity[2 * e + 1] != e + 1) return false;
    return true;
}

}  // namespace

ExplicitPile::ExplicitPile(PileMesh mesh, const LinearElasticSteel& steel, ToeSupport toe)
    : mesh_(std::move(mesh)), steel_(steel), toe_(toe) {
    ops_ = assemble_pile_operators(mesh_, steel);
    rod_chain_ = is_rod_chain(mesh_);
    const int n = mesh_.num_dofs();
    u_.assign(n, 0.0);
    v_.assign(n, 0.0);
    f_int_.assign(n, 0.0);
    f_ext_.assign(n, 0.0);
    damping_.assign(n, 0.0);
    fixed_.assign(n, 0);
    if (mesh_.head_nodes.empty() || mesh_.toe_nodes.empty())
        throw std::invalid_argument("pile mesh lacks head or toe nodes");
    // compute_internal_force gathers each element into a fixed 32-value buffer.
    for (const auto& b : mesh_.blocks)
        if (b.nodes_per_element * mesh_.dofs_per_node() > 32)
            throw std::invalid_argument("element with more than 32 DOFs");
    for (int node : mesh_.head_nodes) {
        head_dofs_.push_back(mesh_.axial_dof(node));
        head_mass_ += ops_.lumped_mass[mesh_.axial_dof(node)];
    }
    // A solid (closed-ended) axisymmetric pile: its nodes on the axis cannot move radially.
    if (mesh_.dim == 2) {
        double r_max = 0.0;
        for (int i = 0; i < mesh_.num_nodes(); ++i) r_max = std::max(r_max, mesh_.coordinates[2 * i]);
        for (int i = 0; i < mesh_.num_nodes(); ++i)
            if (mesh_.coordinates[2 * i] <= 1e-12 * r_max) fixed_[2 * i] = 1;
    }
    double toe_mass = 0.0;
    for (int node : mesh_.toe_nodes) toe_mass += ops_.lumped_mass[mesh_.axial_dof(node)];
    for (int node : mesh_.toe_nodes) {
        const int d = mesh_.axial_dof(node);
        if (toe_.condition == ToeCondition::Fixed) fixed_[d] = 1;
        // Sharing the dashpot by nodal mass is sharing it by tributary area of the annulus.
        if (toe_.condition == ToeCondition::Dashpot)
            damping_[d] = toe_.impedance * ops_.lumped_mass[d] / toe_mass;
    }
}

void ExplicitPile::restore(const std::vector<double>& u, const std::vector<double>& v,
                           const std::vector<double>& f_int) {
    if (u.size() != u_.size() || v.size() != v_.size())
        throw std::invalid_argument("pile state of " + std::to_string(u.size()) + " DOFs for a mesh of " +
                                    std::to_string(u_.size()));
    u_ = u;
    v_ = v;
    if (f_int.size() == u_.size())
        f_int_ = f_int;
    else
        compute_internal_force();
}

void ExplicitPile::compute_internal_force() {
    if (rod_chain_ && stiffness_damping_ == 0.0) {
        rod_chain_forces(mesh_.blocks[0], u_, f_int_);
        return;
    }
    std::fill(f_int_.begin(), f_int_.end(), 0.0);
    const int ndn = mesh_.dofs_per_node();
    if (stiffness_damping_ > 0.0) {
        // K (u + beta v): the elastic force and the stiffness-proportional damping together.
        damped_u_.resize(u_.size());
        for (std::size_t i = 0; i < u_.size(); ++i) damped_u_[i] = u_[i] + stiffness_damping_ * v_[i];
        for (const auto& block : mesh_.blocks) add_block_forces(block, ndn, damped_u_, f_int_);
        return;
    }
    for (const auto& block : mesh_.blocks) add_block_forces(block, ndn, u_, f_int_);
}

double ExplicitPile::damped_stable_time_step() const {
    // Central differences with damping beta K: omega dt <= 2 (sqrt(1 + xi^2) - xi), xi = beta omega / 2.
    // Local damping adds up to alpha |f| to a force that brakes the motion: the stiffness
    // seen is (1 + alpha) K at worst.
    const double omega = 2.0 / ops_.stable_time_step * std::sqrt(1.0 + std::max(local_damping_, split_damping_));
    const double xi = 0.5 * stiffness_damping_ * omega;
    return 2.0 / omega * (std::sqrt(1.0 + xi * xi) - xi);
}

void ExplicitPile::clear_external_force() { std::fill(f_ext_.begin(), f_ext_.end(), 0.0); }

void ExplicitPile::add_head_force(double force_up) {
    for (int d : head_dofs_) f_ext_[d] += force_up * ops_.lumped_mass[d] / head_mass_;
}

// m / dt costs a division per DOF: computed once per time step, not every step. A blow
// alternates full steps and the half steps of kinetic-damping restarts: keep both.
const ExplicitPile::VelocityUpdate& ExplicitPile::velocity_update(double dt) {
    for (auto& c : update_cache_)
        if (c.dt == dt) return c;
    VelocityUpdate& c = update_cache_[next_slot_];
    next_slot_ = 1 - next_slot_;
    const auto& m = ops_.lumped_mass;
    c.dt = dt;
    c.keep.resize(v_.size());
    c.scale.resize(v_.size());
    for (std::size_t i = 0; i < v_.size(); ++i) {
        c.keep[i] = m[i] / dt - 0.5 * damping_[i];
        c.scale[i] = m[i] / dt + 0.5 * damping_[i];
    }
    return c;
}

void ExplicitPile::add_nodal_damping(int dof, double c) {
    damping_[dof] += c;
    update_cache_[0].dt = update_cache_[1].dt = 0.0;  // their coefficients hold the damping
    reaction_dofs_listed_ = false;
}

void ExplicitPile::list_reaction_dofs() {
    reaction_dofs_.clear();
    for (int i = 0; i < mesh_.num_dofs(); ++i)
        if (fixed_[i] || damping_[i] > 0.0) reaction_dofs_.push_back(i);
    reaction_dofs_listed_ = true;
}

// What the supports and dashpots take over the step, from v_{n-1/2} (DOF order, as summed
// before the velocities had a loop of their own).
double ExplicitPile::support_reaction(const VelocityUpdate& c) const {
    double r = 0.0;
    for (int i : reaction_dofs_) {
        if (i % mesh_.dim != mesh_.dim - 1) continue;  // the toe's reaction is axial (not the axis's radial hold)
        const double f = f_ext_[i] - f_int_[i];
        if (fixed_[i]) {
            r -= f;  // the support holds the node still: reaction balances f
            continue;
        }
        const double v_new = (c.keep[i] * v_[i] + f) / c.scale[i];
        r -= 0.5 * damping_[i] * (v_[i] + v_new);
    }
    return r;
}

void ExplicitPile::advance_velocity(double dt) {
    const int n = mesh_.num_dofs();
    const auto& m = ops_.lumped_mass;
    if (!reaction_dofs_listed_) list_reaction_dofs();
    const VelocityUpdate& c = velocity_update(dt);
    toe_reaction_ = support_reaction(c);
    // Dashpot taken at mid-step: unconditionally stable for any impedance. One branch-free
    // loop over all DOFs; the fixed ones are put back to rest after it.
    if (split_damping_ > 0.0) {
        damping_scratch_.resize(n);
        advance_velocity_split_damping(c);
    } else if (local_damping_ > 0.0) {
        for (int i = 0; i < n; ++i) {
            const double f = f_ext_[i] - f_int_[i];
            const double against = v_[i] > 0.0 ? -local_damping_ * std::abs(f) : v_[i] < 0.0 ? local_damping_ * std::abs(f) : 0.0;
            v_[i] = (c.keep[i] * v_[i] + f + against) / c.scale[i];
        }
    } else {
        for (int i = 0; i < n; ++i) v_[i] = (c.keep[i] * v_[i] + (f_ext_[i] - f_int_[i])) / c.scale[i];
    }
    if (vibration_damping_ > 0.0) damp_vibration(dt);
    for (int i : reaction_dofs_)
        if (fixed_[i]) v_[i] = 0.0;
    // Rigid head plate: the head DOFs share the momentum of the plate.
    double p = 0.0;
    for (int d : head_dofs_) p += m[d] * v_[d];
    for (int d : head_dofs_) v_[d] = p / head_mass_;
}

// Cundall's damping of the rigid axial motion and, zero-sum, of the vibration about it.
void ExplicitPile::advance_velocity_split_damping(const VelocityUpdate& c) {
    const int n = mesh_.num_dofs(), dim = mesh_.dim;
    const auto& m = ops_.lumped_mass;
    double resultant = 0.0, p = 0.0, mass = 0.0;
    for (int i = dim - 1; i < n; i += dim)
        if (!fixed_[i]) resultant += f_ext_[i] - f_int_[i], p += m[i] * v_[i], mass += m[i];
    if (mass == 0.0) return;
    const double mean = p / mass, per_mass = resultant / mass;
    auto sign = [](double x) { return x > 0.0 ? 1.0 : x < 0.0 ? -1.0 : 0.0; };
    double vibration_sum = 0.0;  // of the axial DOFs' vibration damping, to be taken out
    for (int i = 0; i < n; ++i) {
        const bool axial = i % dim == dim - 1 && !fixed_[i];
        const double f = f_ext_[i] - f_int_[i] - (axial ? m[i] * per_mass : 0.0);
        damping_scratch_[i] = -split_damping_ * std::abs(f) * sign(v_[i] - (axial ? mean : 0.0));
        if (axial) vibration_sum += damping_scratch_[i];
    }
    const double rigid = -split_damping_ * std::abs(resultant) * sign(mean);
    for (int i = 0; i < n; ++i) {
        const bool axial = i % dim == dim - 1 && !fixed_[i];
        const double d = damping_scratch_[i] + (axial ? m[i] / mass * (rigid - vibration_sum) : 0.0);
        v_[i] = (c.keep[i] * v_[i] + f_ext_[i] - f_int_[i] + d) / c.scale[i];
    }
}

// v <- v_rigid + (v - v_rigid) exp(-c dt), v_rigid the mass-weighted mean axial velocity
// (0 radially): the momentum is kept to round-off.
void ExplicitPile::damp_vibration(double dt) {
    const int n = mesh_.num_dofs(), dim = mesh_.dim;
    const auto& m = ops_.lumped_mass;
    double p = 0.0, mass = 0.0;
    for (int i = dim - 1; i < n; i += dim) {
        if (fixed_[i]) continue;
        p += m[i] * v_[i];
        mass += m[i];
    }
    const double rigid = mass > 0.0 ? p / mass : 0.0, keep = std::exp(-vibration_damping_ * dt);
    for (int i = 0; i < n; ++i) {
        if (fixed_[i]) continue;
        const double about = i % dim == dim - 1 ? rigid : 0.0;
        v_[i] = about + (v_[i] - about) * keep;
    }
}

void ExplicitPile::translate_axially(double delta) {
    for (int i = mesh_.dim - 1; i < mesh_.num_dofs(); i += mesh_.dim) u_[i] += delta;
}

void ExplicitPile::add_head_velocity(double dv_up) {
    for (int d : head_dofs_) v_[d] += dv_up;
}

void ExplicitPile::advance_displacement(double dt) {
    const int n = mesh_.num_dofs();
    for (int i = 0; i < n; ++i) u_[i] += dt * v_[i];
}

double ExplicitPile::toe_velocity() const {
    double p = 0.0, m = 0.0;
    for (int node : mesh_.toe_nodes) {
        const int d = mesh_.axial_dof(node);
        p += ops_.lumped_mass[d] * v_[d];
        m += ops_.lumped_mass[d];
    }
    return p / m;
}

double ExplicitPile::toe_displacement() const {
    double s = 0.0, m = 0.0;
    for (int node : mesh_.toe_nodes) {
        const int d = mesh_.axial_dof(node);
        s += ops_.lumped_mass[d] * u_[d];
        m += ops_.lumped_mass[d];
    }
    return s / m;
}

void ExplicitPile::axial_stress(std::vector<double>& out) const {
    out.resize(mesh_.num_elements());
    const int ndn = mesh_.dofs_per_node();
    std::size_t k = 0;
    for (const auto& block : mesh_.blocks) {
        const int nen = block.nodes_per_element;
        const int nde = nen * ndn;
        const int ne = block.num_elements();
        if (is_rod_block(block, ndn)) {  // the loop below unrolled, same operations
            const int* conn = block.connectivity.data();
            const double* S = block.axial_stress.data();
            for (int e = 0; e < ne; ++e, ++k)
                out[k] = 0.0 + S[2 * e] * u_[conn[2 * e]] + S[2 * e + 1] * u_[conn[2 * e + 1]];
            continue;
        }
        for (int e = 0; e < ne; ++e, ++k) {
            const int* conn = &block.connectivity[static_cast<std::size_t>(e) * nen];
            const double* S = &block.axial_stress[static_cast<std::size_t>(e) * nde];
            double s = 0.0;
            for (int a = 0; a < nen; ++a)
                for (int d = 0; d < ndn; ++d) s += S[a * ndn + d] * u_[conn[a] * ndn + d];
            out[k] = s;
        }
    }
}

double ExplicitPile::strain_energy() const {
    double w = 0.0;
    for (std::size_t i = 0; i < u_.size(); ++i) w += u_[i] * f_int_[i];
    return 0.5 * w;
}

double ExplicitPile::kinetic_energy(const std::vector<double>& v) const {
    double w = 0.0;
    for (std::size_t i = 0; i < v.size(); ++i) w += ops_.lumped_mass[i] * v[i] * v[i];
    return 0.5 * w;
}

double ExplicitPile::dashpot_power(const std::vector<double>& v) const {
    double w = 0.0;
    for (std::size_t i = 0; i < v.size(); ++i) w += damping_[i] * v[i] * v[i];
    return w;
}

}  // namespace pilempm::fem
