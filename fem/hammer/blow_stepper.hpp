#pragma once
// The central-difference step of one hammer blow, shared by the pile wave analysis, the
// drivability study and the coupled model: pile, hammer and (optionally) the soil. kick() takes the forces
// at t_n and gives v_{n+1/2}; the state at t_n may be read before drift() moves u on.
#include <optional>
#include <vector>

#include "fem/hammer/hammer.hpp"
#include "fem/dynamics/explicit_pile.hpp"
#include "fem/dynamics/pile_soil_reaction.hpp"

namespace pilempm::fem {

// Stable step of pile, hammer and soil together (before any safety factor).
double blow_stable_time_step(const ExplicitPile& pile, const HammerSpec& hammer,
                             double ram_element_size, const PileSoilReaction* soil = nullptr);

class BlowStepper {
public:
    // The pile is the caller's and keeps its state between blows; the hammer starts at
    // impact on the pile head where it now is.
    BlowStepper(ExplicitPile& pile, const HammerSpec& hammer, double ram_element_size,
                PileSoilReaction* soil = nullptr);

    double stable_time_step() const;
    void kick(double t, double dt);
    void drift(double dt);

    // State at t_n, valid between kick() and drift().
    const std::vector<double>& velocity_at_step() const { return v_mid_; }
    double applied_force() const { return applied_; }  // prescribed hammer force, compression
    const HammerChain* chain() const { return chain_ ? &*chain_ : nullptr; }
    ExplicitPile& pile() { return pile_; }
    // Kinetic energy of pile and hammer at t_n; stop() zeroes all velocities.
    // After stop() the next kick is a half step, as at the start of a leapfrog: a full
    // kick from rest is explicit gradient descent, unstable above dt = sqrt(2) / w_max.
    double kinetic_energy() const;
    void stop();

private:
    ExplicitPile& pile_;
    const HammerSpec& hammer_;
    std::optional<HammerChain> chain_;
    PileSoilReaction* soil_;
    double ram_element_size_;
    std::vector<double> v_old_, v_mid_;
    double applied_ = 0.0;
    bool restart_ = false;
};

}  // namespace pilempm::fem
