#pragma once
// Hammer models acting on the pile head: a prescribed force history, or a ram-cushion-
// helmet chain. The chain is a handful of axial DOFs (ram nodes, helmet) joined by rod
// springs, cushions (compression-only, coefficient of restitution) or direct contact
// (kinematic, compression-only), integrated with the pile's central-difference step.
#include <algorithm>
#include <optional>
#include <vector>

#include "fem/dynamics/explicit_pile.hpp"

namespace pilempm::fem {

// Peak force of the half-sine pulse of seed 001, eq. 1: f = pi eta m sqrt(2 g h) / (2 t_i).
double half_sine_peak_force(double ram_mass, double drop_height, double efficiency,
                            double impulse_time, double gravity);

struct PrescribedForce {
    // Half-sine f_max sin(pi t / duration) when `table_time` is empty, else the
    // piecewise-linear table; zero outside. Compression (downward on the head) positive.
    double peak = 0.0;      // N
    double duration = 0.0;  // s
    std::vector<double> table_time, table_force;
    double at(double t) const;
    double end_time() const;
};

struct CushionSpec {
    double stiffness = 0.0;    // N/m, loading
    double restitution = 1.0;  // e: unloading stiffness is stiffness / e^2
};

struct RamSpec {
    double mass = 0.0;         // kg
    bool elastic = false;      // rod elements instead of a rigid mass
    double length = 0.0;       // m (elastic ram)
    double youngs_modulus = 0.0;
    double density = 0.0;
    int elements = 0;          // rod elements along the ram; 0: from the pile's element size
};

struct RamCushionSpec {
    RamSpec ram;
    double impact_velocity = 0.0;  // m/s, downward, at first contact
    std::optional<CushionSpec> hammer_cushion;  // between ram and helmet (or head)
    double helmet_mass = 0.0;                   // kg; 0: no helmet
    std::optional<CushionSpec> pile_cushion;    // between helmet and head
    double gravity = 9.81;                      // m/s^2, acting on ram and helmet
};

enum class HammerKind { PrescribedForce, RamCushion };

struct HammerSpec {
    HammerKind kind = HammerKind::PrescribedForce;
    PrescribedForce force;
    RamCushionSpec ram_cushion;
};

// A ram-cushion-helmet chain acting on the head of an ExplicitPile.
class HammerChain {
public:
    // head_displacement: where the pile head is (m, up positive) when the ram strikes.
    HammerChain(const RamCushionSpec& spec, double ram_element_size, double head_displacement = 0.0);

    // Gershgorin bound over the chain's nodes and the pile head, whose own highest
    // frequency is pile_max_frequency (rad/s).
    double stable_time_step(double pile_head_mass, double pile_max_frequency) const;
    // Forces at t_n from the current positions; adds the head force to the pile.
    void compute_forces(fem::ExplicitPile& pile);
    void advance_velocity(double dt);
    // Kinematic contacts: exchange impulses so no contact pair overlaps at t_{n+1}.
    void resolve_contacts(double dt, fem::ExplicitPile& pile);
    void advance_displacement(double dt);

    double force_on_head() const { return head_force_; }  // N, compression positive
    // At t_n, from the mean of the half-step velocities (as the pile's is reported).
    double kinetic_energy() const;
    double stored_energy() const;    // recoverable energy of springs and cushions, J
    // Lost in cushion hysteresis and inelastic contact so far, J.
    double dissipated_energy() const;
    // Work gravity has done on ram and helmet so far, J.
    double gravity_work() const { return gravity_work_; }
    // Kinetic energy at impact, J.
    double impact_energy() const { return impact_energy_; }
    double ram_velocity() const { return v_.front(); }   // up positive
    void stop() {  // kinetic damping between blows
        std::fill(v_.begin(), v_.end(), 0.0);
        std::fill(v_previous_.begin(), v_previous_.end(), 0.0);
    }
    double ram_impedance() const { return ram_impedance_; }
    int ram_nodes() const { return ram_nodes_; }
    const std::vector<double>& velocity() const { return v_; }
    // The whole state (positions, velocities, forces, the cushions' history, the energy
    // ledger) as one array, and back into a chain built from the same spec: a run stopped
    // inside a blow resumes exactly.
    std::vector<double> state() const;
    void restore(const std::vector<double>& state);

private:
    enum class LinkKind { Rod, Cushion, Contact };
    struct Link {
        LinkKind kind;
        int upper, lower;  // chain node indices; lower = -1: the pile head
        double stiffness = 0.0, restitution = 1.0;
        double max_compression = 0.0;  // cushion loading history
        double force = 0.0;            // compression positive, at the last evaluation
        double compression = 0.0;      // at the last evaluation
        double absorbed = 0.0;         // work done on a cushion so far, J
        double approach = 0.0;         // closing speed at the end of the last step, m/s
    };
    double compression(const Link& l, const fem::ExplicitPile& pile) const;
    double cushion_force(Link& l, double c) const;

    std::vector<double> m_, u_, v_, f_;
    std::vector<double> v_previous_;  // v at t_{n-1/2}
    std::vector<Link> links_;
    std::vector<char> struck_;        // resolve_contacts: the contacts that took an impulse
    int ram_nodes_ = 1;
    double gravity_ = 9.81;
    double head_force_ = 0.0;
    double ram_impedance_ = 0.0;
    double contact_loss_ = 0.0;
    double gravity_work_ = 0.0;
    double impact_energy_ = 0.0;
};

}  // namespace pilempm::fem
