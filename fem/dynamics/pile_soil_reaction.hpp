#pragma once
// Whatever the soil does to the pile during a blow, seen from the pile: forces added to its
// nodes before each velocity update, and the bound the soil puts on the stable step. Smith
// springs (coupling/wave_equation) are one; the MPM contact of the coupled model another.
#include "fem/dynamics/explicit_pile.hpp"

namespace pilempm::fem {

class PileSoilReaction {
public:
    virtual ~PileSoilReaction() = default;
    // Stable-step bound of the soil on the pile's lumped masses (s; a huge value: none).
    virtual double stable_time_step(const ExplicitPile& pile) const = 0;
    // Forces at u_n added to the pile's external forces; may update the soil's state.
    virtual void add_forces(ExplicitPile& pile) = 0;
};

}  // namespace pilempm::fem
