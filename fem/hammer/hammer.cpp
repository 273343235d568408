#include "fem/hammer/hammer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace pilempm::fem {

double half_sine_peak_force(double ram_mass, double drop_height, double efficiency,
                            double impulse_time, double gravity) {
    return std::numbers::pi * efficiency * ram_mass * std::sqrt(2.0 * gravity * drop_height) /
           (2.0 * impulse_time);
}

double PrescribedForce::at(double t) const {
    if (table_time.empty()) {
        if (t < 0.0 || t > duration) return 0.0;
        return peak * std::sin(std::numbers::pi * t / duration);
    }
    if (t < table_time.front() || t > table_time.back()) return 0.0;
    const auto it = std::upper_bound(table_time.begin(), table_time.end(), t);
    if (it == table_time.end()) return table_force.back();
    const auto i = static_cast<std::size_t>(it - table_time.begin());
    const double w = (t - table_time[i - 1]) / (table_time[i] - table_time[i - 1]);
    return (1.0 - w) * table_force[i - 1] + w * table_force[i];
}

double PrescribedForce::end_time() const {
    return table_time.empty() ? duration : table_time.back();
}

HammerChain::HammerChain(const RamCushionSpec& spec, double ram_element_size, double head_displacement)
    : gravity_(spec.gravity) {
    const auto& ram = spec.ram;
    if (ram.elastic) {
        const int n = ram.elements > 0
                          ? ram.elements
                          : std::max(1, static_cast<int>(std::lround(ram.length / ram_element_size)));
        const double area = ram.mass / (ram.density * ram.length);
        const double le = ram.length / n;
        const double k = ram.youngs_modulus * area / le;
        ram_nodes_ = n + 1;
        m_.assign(ram_nodes_, 0.0);
        for (int e = 0; e < n; ++e) {
            m_[e] += 0.5 * ram.mass / n;
            m_[e + 1] += 0.5 * ram.mass / n;
            links_.push_back({LinkKind::Rod, e, e + 1, k});
        }
        ram_impedance_ = area * std::sqrt(ram.youngs_modulus * ram.density);
    } else {
        ram_nodes_ = 1;
        m_.assign(1, ram.mass);
    }
    // Below the ram: [hammer cushion | contact] -> [helmet] -> [pile cushion | contact] -> head.
    const int ram_bottom = ram_nodes_ - 1;
    const bool helmet = spec.helmet_mass > 0.0;
    const int below_ram = helmet ? ram_nodes_ : -1;
    auto connect = [&](int upper, int lower, const std::optional<CushionSpec>& c) {
        if (c) links_.push_back({LinkKind::Cushion, upper, lower, c->stiffness, c->restitution});
        else links_.push_back({LinkKind::Contact, upper, lower});
    };
    connect(ram_bottom, below_ram, spec.hammer_cushion);
    if (helmet) {
        m_.push_back(spec.helmet_mass);
        connect(ram_nodes_, -1, spec.pile_cushion);
    } else if (spec.pile_cushion) {
        throw std::invalid_argument("a pile cushion needs a helmet mass above it");
    }
    u_.assign(m_.size(), head_displacement);
    // Ram moves down at impact velocity; the helmet rests on the pile.
    v_.assign(m_.size(), 0.0);
    for (int i = 0; i < ram_nodes_; ++i) v_[i] = -spec.impact_velocity;
    f_.assign(m_.size(), 0.0);
    v_previous_ = v_;
    impact_energy_ = kinetic_energy();
}

double HammerChain::stable_time_step(double pile_head_mass, double pile_max_frequency) const {
    // lambda_i = sum over the springs at node i of 2 k / m_i bounds w^2 of the chain.
    std::vector<double> lambda(m_.size(), 0.0);
    double head = 0.0;
    for (const auto& l : links_) {
        if (l.kind == LinkKind::Contact) continue;
        const double k = l.kind == LinkKind::Cushion ? l.stiffness / (l.restitution * l.restitution)
                                                     : l.stiffness;
        lambda[l.upper] += 2.0 * k / m_[l.upper];
        if (l.lower < 0) head += 2.0 * k / pile_head_mass;
        else lambda[l.lower] += 2.0 * k / m_[l.lower];
    }
    double w2 = pile_max_frequency * pile_max_frequency + head;
    for (double x : lambda) w2 = std::max(w2, x);
    return 2.0 / std::sqrt(w2);
}

double HammerChain::compression(const Link& l, const fem::ExplicitPile& pile) const {
    const double u_low = l.lower < 0 ? pile.head_displacement() : u_[l.lower];
    return u_low - u_[l.upper];
}

double HammerChain::cushion_force(Link& l, double c) const {
    if (c >= l.max_compression) {
        l.max_compression = c;
        return l.stiffness * c;
    }
    // Unloading (and reloading) on the stiffer line k/e^2 from the peak: the cushion
    // returns e^2 of the energy it took.
    const double unloading = l.stiffness / (l.restitution * l.restitution);
    return std::max(0.0, l.stiffness * l.max_compression - unloading * (l.max_compression - c));
}

void HammerChain::compute_forces(fem::ExplicitPile& pile) {
    for (std::size_t i = 0; i < m_.size(); ++i) f_[i] = -m_[i] * gravity_;
    head_force_ = 0.0;
    for (auto& l : links_) {
        if (l.kind == LinkKind::Contact) {
            l.force = 0.0;
            continue;
        }
        const double c = compression(l, pile);
        const double previous = l.force;
        l.force = l.kind == LinkKind::Rod ? l.stiffness * c : cushion_force(l, c);
        l.absorbed += 0.5 * (previous + l.force) * (c - l.compression);  // trapezoidal work
        l.compression = c;
        f_[l.upper] += l.force;  // compression pushes the upper body up...
        if (l.lower < 0) head_force_ += l.force;
        else f_[l.lower] -= l.force;  // ...and the lower body down
    }
    if (head_force_ != 0.0) pile.add_head_force(-head_force_);
}

void HammerChain::advance_velocity(double dt) {
    v_previous_ = v_;
    for (std::size_t i = 0; i < m_.size(); ++i) v_[i] += dt * f_[i] / m_[i];
}

void HammerChain::resolve_contacts(double dt, fem::ExplicitPile& pile) {
    auto lower_mass = [&](const Link& l) { return l.lower < 0 ? pile.head_mass() : m_[l.lower]; };
    auto lower_velocity = [&](const Link& l) { return l.lower < 0 ? pile.head_velocity() : v_[l.lower]; };
    std::vector<char>& struck = struck_;  // a member: no allocation per step
    struck.assign(links_.size(), 0);
    // Gauss-Seidel over the contact pairs: few pairs, converges in a few sweeps.
    for (int sweep = 0; sweep < 50; ++sweep) {
        bool changed = false;
        for (std::size_t k = 0; k < links_.size(); ++k) {
            Link& l = links_[k];
            if (l.kind != LinkKind::Contact) continue;
            const double m_low = lower_mass(l), v_low = lower_velocity(l);
            const double gap = -compression(l, pile);
            // Impulse that closes the gap exactly at t_{n+1}, if the pair would overlap.
            const double gap_next = gap + dt * (v_[l.upper] - v_low);
            if (gap_next >= -1e-15 * std::max(1.0, std::abs(gap))) continue;
            const double impulse = -gap_next / dt / (1.0 / m_[l.upper] + 1.0 / m_low);
            v_[l.upper] += impulse / m_[l.upper];
            if (l.lower < 0) pile.add_head_velocity(-impulse / m_low);
            else v_[l.lower] -= impulse / m_low;
            l.force += impulse / dt;
            struck[k] = 1;
            changed = true;
        }
        if (!changed) break;
    }
    for (std::size_t k = 0; k < links_.size(); ++k) {
        Link& l = links_[k];
        if (l.kind != LinkKind::Contact) continue;
        const double approach = lower_velocity(l) - v_[l.upper];
        // Held in contact the constraint does no work; what is lost is the closing speed the
        // pair carried into the step: an inelastic impact, 1/2 mu (v_in^2 - v_out^2).
        if (struck[k]) {
            const double mu = 1.0 / (1.0 / m_[l.upper] + 1.0 / lower_mass(l));
            const double in = std::max(0.0, l.approach), out = std::max(0.0, approach);
            contact_loss_ += 0.5 * mu * (in * in - out * out);
        }
        l.approach = approach;
        if (l.lower < 0) head_force_ += l.force;
    }
}

void HammerChain::advance_displacement(double dt) {
    for (std::size_t i = 0; i < m_.size(); ++i) {
        u_[i] += dt * v_[i];
        gravity_work_ -= m_[i] * gravity_ * dt * v_[i];
    }
}

std::vector<double> HammerChain::state() const {
    std::vector<double> s;
    for (const auto* a : {&u_, &v_, &v_previous_, &f_}) s.insert(s.end(), a->begin(), a->end());
    for (const auto& l : links_) s.insert(s.end(), {l.max_compression, l.force, l.compression, l.absorbed, l.approach});
    s.insert(s.end(), {head_force_, contact_loss_, gravity_work_, impact_energy_});
    return s;
}

void HammerChain::restore(const std::vector<double>& s) {
    const std::size_t n = m_.size(), expected = 4 * n + 5 * links_.size() + 4;
    if (s.size() != expected)
        throw std::invalid_argument("the hammer's state has " + std::to_string(s.size()) + " values, its chain " +
                                    std::to_string(expected));
    auto at = s.begin();
    for (auto* a : {&u_, &v_, &v_previous_, &f_}) {
        std::copy(at, at + static_cast<long>(n), a->begin());
        at += static_cast<long>(n);
    }
    for (auto& l : links_) {
        l.max_compression = *at++, l.force = *at++, l.compression = *at++, l.absorbed = *at++, l.approach = *at++;
    }
    head_force_ = *at++, contact_loss_ = *at++, gravity_work_ = *at++, impact_energy_ = *at++;
}

double HammerChain::kinetic_energy() const {
    double e = 0.0;
    for (std::size_t i = 0; i < m_.size(); ++i) {
        const double v = 0.5 * (v_previous_[i] + v_[i]);
        e += 0.5 * m_[i] * v * v;
    }
    return e;
}

double HammerChain::dissipated_energy() const {
    double e = contact_loss_;
    for (const auto& l : links_)
        if (l.kind == LinkKind::Cushion)  // absorbed minus what unloading on k/e^2 would return
            e += l.absorbed - 0.5 * l.force * l.force * l.restitution * l.restitution / l.stiffness;
    return e;
}

double HammerChain::stored_energy() const {
    double e = 0.0;
    for (const auto& l : links_) {
        if (l.kind == LinkKind::Rod) e += 0.5 * l.force * l.force / l.stiffness;
        if (l.kind == LinkKind::Cushion && l.force > 0.0)
            e += 0.5 * l.force * l.force * l.restitution * l.restitution / l.stiffness;
    }
    return e;
}

}  // namespace pilempm::fem
