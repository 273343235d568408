#include "fem/hammer/blow_stepper.hpp"

#include <algorithm>
#include <cmath>

namespace pilempm::fem {

BlowStepper::BlowStepper(ExplicitPile& pile, const HammerSpec& hammer, double ram_element_size,
                         PileSoilReaction* soil)
    : pile_(pile), hammer_(hammer), soil_(soil), ram_element_size_(ram_element_size) {
    if (hammer.kind == HammerKind::RamCushion)
        chain_.emplace(hammer.ram_cushion, ram_element_size, pile.head_displacement());
    v_mid_.assign(pile.mesh().num_dofs(), 0.0);
}

double blow_stable_time_step(const ExplicitPile& pile, const HammerSpec& hammer,
                             double ram_element_size, const PileSoilReaction* soil) {
    double dt = pile.stable_time_step();
    if (hammer.kind == HammerKind::RamCushion) {
        const HammerChain chain(hammer.ram_cushion, ram_element_size);
        dt = std::min(dt, chain.stable_time_step(pile.head_mass(), pile.operators().max_frequency));
    }
    if (soil) dt = std::min(dt, soil->stable_time_step(pile));
    return dt;
}

double BlowStepper::stable_time_step() const {
    return blow_stable_time_step(pile_, hammer_, ram_element_size_, soil_);
}

void BlowStepper::kick(double t, double dt) {
    pile_.compute_internal_force();
    pile_.clear_external_force();
    applied_ = 0.0;
    if (chain_) {
        chain_->compute_forces(pile_);
    } else {
        applied_ = hammer_.force.at(t);
        pile_.add_head_force(-applied_);
    }
    if (soil_) soil_->add_forces(pile_);
    v_old_ = pile_.velocity();
    const double dt_kick = restart_ ? 0.5 * dt : dt;
    restart_ = false;
    pile_.advance_velocity(dt_kick);
    if (chain_) {
        chain_->advance_velocity(dt_kick);
        chain_->resolve_contacts(dt, pile_);
    }
    const auto& v_new = pile_.velocity();
    for (std::size_t i = 0; i < v_mid_.size(); ++i) v_mid_[i] = 0.5 * (v_old_[i] + v_new[i]);
}

void BlowStepper::drift(double dt) {
    pile_.advance_displacement(dt);
    if (chain_) chain_->advance_displacement(dt);
}

}  // namespace pilempm::fem

namespace pilempm::fem {

double BlowStepper::kinetic_energy() const {
    return pile_.kinetic_energy(v_mid_) + (chain_ ? chain_->kinetic_energy() : 0.0);
}

void BlowStepper::stop() {
    pile_.stop();
    std::fill(v_mid_.begin(), v_mid_.end(), 0.0);
    if (chain_) chain_->stop();
    restart_ = true;
}

}  // namespace pilempm::fem
