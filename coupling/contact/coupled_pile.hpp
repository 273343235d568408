#pragma once
// The FE pile in the MPM soil, one MPM step at a time: the contact forces from the points
// and the pile at t_n, then the pile subcycled over the step (its stable step is smaller)
// with those forces held, then the soil's step with the same forces on its points. The
// interface impulse f dt is therefore the same on both sides: pile + soil momentum is
// conserved to round-off.
#include <array>

#include "coupling/contact/penalty_contact.hpp"
#include "coupling/contact/pile_surface.hpp"
#include "fem/dynamics/explicit_pile.hpp"
#include "mpm/solver/mpm_solver.hpp"

namespace pilempm::coupling {

class CoupledPile {
public:
    // gravity: the pile's own weight, m/s^2 down (n g in a centrifuge). cut_fields: the
    // soil inside and outside an open wall on their own grid fields (a grid of 2 fields, 4
    // with water), the cut along the wall's mid-line moving with it.
    CoupledPile(fem::ExplicitPile& pile, ContactSettings contact, PileFrame frame, double gravity = 0.0,
                bool cut_fields = true);

    void step(mpm::MpmSolver<2>& soil, mpm::MpmModel<2>& m, double dt);

    fem::ExplicitPile& pile() { return pile_; }
    const PenaltyContact& contact() const { return contact_; }
    const ContactSurface& surface() const { return surface_; }
    int substeps() const { return substeps_; }
    // The pile's momentum (the whole ring; velocities at the last half step), N s.
    std::array<double, 2> momentum() const;
    // The impulse the contact gave the pile since the start (the whole ring), N s.
    const std::array<double, 2>& contact_impulse() const { return impulse_; }

private:
    fem::ExplicitPile& pile_;
    PenaltyContact contact_;
    PileFrame frame_;
    double gravity_;
    bool cut_fields_;
    ContactSurface surface_;
    int substeps_ = 1;
    std::array<double, 2> impulse_{};
};

}  // namespace pilempm::coupling
