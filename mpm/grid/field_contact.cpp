#include "mpm/grid/field_contact.hpp"

#include <cmath>
#include <stdexcept>

namespace pilempm::mpm {

namespace {

// The contact of side a (velocity va, mass ma) with side b along n (from a toward b): the
// new velocity of a, or false when a is leaving b (no contact).
bool contact_velocity(const double* va, double ma, const double* vb, double mb, const double* n, double mu,
                      double* out) {
    const double total = ma + mb;
    double dv[2];
    for (int d = 0; d < 2; ++d) dv[d] = va[d] - (ma * va[d] + mb * vb[d]) / total;
    const double approach = dv[0] * n[0] + dv[1] * n[1];
    if (approach <= 0.0) return false;
    const double tx = dv[0] - approach * n[0], ty = dv[1] - approach * n[1];
    const double slip = std::sqrt(tx * tx + ty * ty);
    // Sticks when friction can stop the relative slip; else slides with mu times the normal change.
    const double keep = slip > mu * approach ? 1.0 - mu * approach / slip : 0.0;
    out[0] = va[0] - dv[0] + keep * tx;
    out[1] = va[1] - dv[1] + keep * ty;
    return true;
}

}  // namespace

bool any_contact_cut(const std::vector<FieldCut>& cuts) {
    for (const auto& cut : cuts)
        if (cut.has_contact()) return true;
    return false;
}

void contact_across_cuts(Grid<2>& g, const std::vector<FieldCut>& cuts, double empty_mass, double dt,
                         std::vector<double>* residual) {
    const int fields = g.fields, nodes = g.stored_nodes();
    for (const auto& cut : cuts) {
        if (!cut.has_contact()) continue;
        if (g.water) throw std::invalid_argument("a slip line (a field cut with contact) on a grid with water fields is not supported");
        const int o = cut.offset;
        for (int n = 0; n < nodes; ++n) {
            if (g.condition_at[n] >= 0) continue;  // supports and walls set these velocities themselves
            for (int a = 0; a + o < fields; ++a) {
                if ((a / o) % 2 != 0) continue;  // a on this node's side of the cut, b = a + o across it
                const int ea = n * fields + a, eb = ea + o;
                const double ma = g.mass[ea], mb = g.mass[eb];
                if (ma <= empty_mass || mb <= empty_mass) continue;
                double normal[2], va[2];
                if (cut.normal_away_from(&g.position[2 * ea], normal) >= cut.contact_segments) continue;  // a wall there
                double* vel_a = &g.velocity[2 * ea];
                double* vel_b = &g.velocity[2 * eb];
                if (!contact_velocity(vel_a, ma, vel_b, mb, normal, cut.friction, va)) continue;
                for (int d = 0; d < 2; ++d) {
                    const double change_a = va[d] - vel_a[d];
                    const double change_b = -ma / mb * change_a;  // equal and opposite momentum
                    vel_a[d] = va[d];
                    vel_b[d] += change_b;
                    if (dt > 0.0) {
                        g.acceleration[2 * ea + d] += change_a / dt;
                        g.acceleration[2 * eb + d] += change_b / dt;
                        if (residual) {
                            (*residual)[2 * ea + d] += ma * change_a / dt;
                            (*residual)[2 * eb + d] += mb * change_b / dt;
                        }
                    }
                }
            }
        }
    }
}

}  // namespace pilempm::mpm
