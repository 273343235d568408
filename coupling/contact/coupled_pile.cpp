#include "coupling/contact/coupled_pile.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace pilempm::coupling {

CoupledPile::CoupledPile(fem::ExplicitPile& pile, ContactSettings contact, PileFrame frame, double gravity,
                         bool cut_fields)
    : pile_(pile), contact_(contact), frame_(frame), gravity_(gravity), cut_fields_(cut_fields),
      surface_(pile_contact_surface(pile.mesh())) {}

void CoupledPile::step(mpm::MpmSolver<2>& soil, mpm::MpmModel<2>& m, double dt) {
    place_pile_surface(surface_, pile_.mesh(), pile_.displacement(), pile_.velocity(), frame_);
    if (cut_fields_) {
        const int offset = m.grid.water ? 2 : 1;
        if (m.grid.fields < 2 * offset)
            throw std::invalid_argument("the soil either side of the pile's wall needs a grid of " +
                                        std::to_string(2 * offset) + " velocity fields");
        m.field_cuts = {mpm::FieldCut{pile_mid_line(pile_.mesh(), pile_.displacement(), frame_), offset}};
    }
    contact_.compute(m.particles, m.shape, surface_, dt);
    // Subcycles of the pile inside the soil's step, the contact force held over them.
    substeps_ = std::max(1, static_cast<int>(std::ceil(dt / (0.95 * pile_.stable_time_step()))));
    const double h = dt / substeps_;
    const auto& f = contact_.nodal_force();
    const auto& mass = pile_.operators().lumped_mass;
    const int nodes = pile_.mesh().num_nodes();
    for (int s = 0; s < substeps_; ++s) {
        pile_.compute_internal_force();
        pile_.clear_external_force();
        for (int i = 0; i < nodes; ++i) {
            pile_.add_nodal_force(2 * i, f[2 * i]);
            pile_.add_nodal_force(2 * i + 1, f[2 * i + 1] - mass[2 * i + 1] * gravity_);
        }
        pile_.advance_velocity(h);
        pile_.advance_displacement(h);
    }
    for (int c = 0; c < 2; ++c) impulse_[c] += contact_.totals().force_on_master[c] * dt;
    soil.step(dt);
}

std::array<double, 2> CoupledPile::momentum() const {
    std::array<double, 2> p{};
    const auto& v = pile_.velocity();
    const auto& mass = pile_.operators().lumped_mass;
    for (std::size_t k = 0; k < v.size(); ++k) p[k % 2] += mass[k] * v[k];
    return p;
}

}  // namespace pilempm::coupling
