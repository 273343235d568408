#include "coupling/wave_equation/smith_soil.hpp"

#include <algorithm>
#include <cmath>

namespace pilempm::coupling {

void SmithSoil::add_point(int pile_node, double r_u, double q, double c, bool is_toe) {
    node.push_back(pile_node);
    ultimate.push_back(r_u);
    quake.push_back(q);
    dashpot.push_back(c);
    toe.push_back(is_toe ? 1 : 0);
    plastic.push_back(0.0);
    force.push_back(0.0);
}

double SmithSoil::total_ultimate() const {
    double r = 0.0;
    for (double x : ultimate) r += x;
    return r;
}

double SmithSoil::elastic_energy() const {
    double e = 0.0;
    for (std::size_t i = 0; i < size(); ++i)
        if (ultimate[i] > 0.0) e += 0.5 * force[i] * force[i] * quake[i] / ultimate[i];
    return e;
}

double SmithSoil::stable_time_step(const fem::ExplicitPile& pile) const {
    double dt = 1e300;
    const auto& m = pile.operators().lumped_mass;
    for (std::size_t i = 0; i < size(); ++i) {
        if (ultimate[i] <= 0.0) continue;
        const double k = ultimate[i] / quake[i];
        // Spring and pile element add up on the node: halve the spring's own limit.
        dt = std::min(dt, 0.5 * 2.0 / std::sqrt(k / m[pile.mesh().axial_dof(node[i])]));
    }
    return dt;
}

void SmithSoil::attach_dashpots(fem::ExplicitPile& pile) const {
    for (std::size_t i = 0; i < size(); ++i)
        if (dashpot[i] > 0.0) pile.add_nodal_damping(pile.mesh().axial_dof(node[i]), dashpot[i]);
}

void SmithSoil::add_forces(fem::ExplicitPile& pile) {
    const auto& u = pile.displacement();
    for (std::size_t i = 0; i < size(); ++i) {
        const int dof = pile.mesh().axial_dof(node[i]);
        const double down = -u[dof];
        const double k = ultimate[i] / quake[i];
        double r = k * (down - plastic[i]);  // resistance, positive against downward motion
        if (r > ultimate[i]) {
            const double slip = down - quake[i] - plastic[i];
            plastic_work += ultimate[i] * slip;
            plastic[i] += slip;
            r = ultimate[i];
        } else if (toe[i]) {
            r = std::max(r, 0.0);  // the toe lifts off instead of pulling
        } else if (r < -ultimate[i]) {
            const double slip = down + quake[i] - plastic[i];
            plastic_work -= ultimate[i] * slip;
            plastic[i] += slip;
            r = -ultimate[i];
        }
        force[i] = r;
        pile.add_nodal_force(dof, r);  // the soil pushes the pile up (z up)
    }
}

}  // namespace pilempm::coupling
