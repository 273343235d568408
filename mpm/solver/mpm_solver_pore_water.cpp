// The saturated-soil passes of the explicit solver: single-point v-w after Van Esch (2010)
// as in Anura3D, written for the excess pore pressure p (over hydrostatic, compression
// positive). Per unit volume of the mixture, with n the porosity, R = mu / kappa:
//   water:   rho_w a_w = -grad p - n R (w - v)                (+ rho_w g above the water table)
//   mixture: (1 - n) rho_s a_s + n rho_w a_w = div(sigma' - p I) + (rho_sat - rho_w) g
//   mass:    dp/dt = -(K_w / n) ((1 - n) div v + n div w)
// The grid carries v on the solid field and w on the water field; the drag is taken at the
// end of the step (semi-implicit), so a low permeability does not shorten the step.
#include <algorithm>
#include <cmath>

#include "mpm/grid/field_contact.hpp"
#include "mpm/solver/mpm_solver.hpp"
#include "mpm/solver/solver_passes.hpp"

namespace pilempm::mpm {

// Per grid entry (V values): mass, momentum (D), force (D), coupling term, external force
// (D). The coupling term is the water's inertia in the mixture's momentum on solid entries
// and the Darcy drag on water entries. A water entry's mass is the water equation's,
// sum N rho_w V; its momentum is the water's, sum N n rho_w V w, so that the mixture's
// momentum passes between points and grid exactly whatever the porosity.
template <int D>
void MpmSolver<D>::scatter_saturated() {
    auto& p = m_.particles;
    auto& g = m_.grid;
    constexpr int V = 2 + 3 * D;
    const int fields = g.fields;
    const PoreWater& water = m_.water;
    scatter(V * fields, [&](long i, double* buf) {
        build_stencil(i);
        const Stencil<D>& s = stencil_[i];
        const MaterialDrainage& dr = drainage_[p.material[i]];
        const double vol = p.volume[i], n = p.porosity[i], solid = p.mass[i];
        const bool wet = dr.saturated(), coupled = dr.drainage == Drainage::Coupled;
        const double water_mass = wet ? n * water.density * vol : 0.0;
        const double buoyancy = wet && water.submerged(p.x[D * i + D - 1]) ? water.density * vol : 0.0;
        const double inertia = coupled ? solid : solid + water_mass;
        const double pe = dr.drainage == Drainage::Undrained || coupled ? p.pore_pressure[i] : 0.0;
        const double* sg = &p.stress[6 * i];
        // The mixture's stress less the hydrostatic pressure: sigma' - p I.
        double VS[D][D], body[D], body_w[D], v[D], w[D], C[D * D];
        VS[0][0] = vol * (sg[0] - pe);
        VS[1][1] = vol * (sg[1] - pe);
        VS[0][1] = VS[1][0] = vol * sg[3];
        if constexpr (D == 3) {
            VS[2][2] = vol * (sg[2] - pe);
            VS[1][2] = VS[2][1] = vol * sg[4];
            VS[0][2] = VS[2][0] = vol * sg[5];
        }
        const double water_density_mass = coupled ? water.density * vol : 0.0;  // the water equation's "mass"
        for (int d = 0; d < D; ++d) {
            body[d] = (solid + water_mass - buoyancy) * m_.gravity[d] + p.external_force[D * i + d];
            body_w[d] = coupled ? (water_density_mass - (buoyancy > 0.0 ? water_density_mass : 0.0)) * m_.gravity[d] : 0.0;
            v[d] = p.v[D * i + d];
            w[d] = p.w[D * i + d];
        }
        for (int k = 0; k < D * D; ++k) C[k] = p.C[D * D * i + k];
        const double hoop_force = m_.axisymmetric ? vol * (sg[2] - pe) : 0.0;
        const double drag = coupled ? n * dr.darcy_resistance * vol : 0.0;
        for (int k = 0; k < s.count; ++k) {
            double* b = buf + V * s.e[k].node;
            const double N = s.e[k].N;
            double vn[D];
            velocity_toward_node(s, k, v, C, vn);
            b[0] += N * inertia;
            for (int d = 0; d < D; ++d) {
                b[1 + d] += N * inertia * vn[d];
                double f = N * body[d];
                for (int e = 0; e < D; ++e) f -= VS[d][e] * s.e[k].dN[e];
                b[1 + D + d] += f;
                b[2 + 2 * D + d] += N * body[d];
            }
            if (m_.axisymmetric) b[1 + D] -= hoop_force * s.hoop[k];
            if (!coupled) continue;
            b[1 + 2 * D] += N * water_mass;
            double* bw = b + V;  // the water field beside the solid one
            bw[0] += N * water_density_mass;
            for (int d = 0; d < D; ++d) {
                bw[1 + d] += N * water_mass * w[d];  // the water's momentum: w = this / the water inertia
                bw[1 + D + d] += N * body_w[d] + vol * pe * s.e[k].dN[d];
                bw[2 + 2 * D + d] += N * body_w[d];
            }
            if (m_.axisymmetric) bw[1 + D] += vol * pe * s.hoop[k];  // -dp/dr weighted by r: + p hoop
            bw[1 + 2 * D] += N * drag;
        }
    }, scratch_);
    const int nf = g.stored_nodes() * fields;
    external_.resize(D * nf);
    for (int k = 0; k < nf; ++k) {
        const double* b = &scratch_[V * k];
        g.mass[k] = b[0];
        for (int d = 0; d < D; ++d) {
            g.momentum[D * k + d] = b[1 + d];
            g.force[D * k + d] = b[1 + D + d];
            external_[D * k + d] = b[2 + 2 * D + d];
        }
        if (g.water) (k % 2 == 0 ? g.water_inertia : g.drag)[k] = b[1 + 2 * D];
    }
}

// Per node and solid/water pair, per component, the end-of-step velocities v1 = v0 + a,
// w1 = w0 + b from
//   mixture: Ms a + Mnw b = dt (F_mix + dashpots)
//   water:   Mw b = dt (F_w - Q (w1 - v1) + dashpots)
// with the dashpots at mid-step: the skeleton's c_s on v, the pore pressure's c_w on
// (1 - n) v + n w acting on both equations (it is part of the total traction).
template <int D>
void MpmSolver<D>::update_grid_coupled(double dt) {
    auto& g = m_.grid;
    const int fields = g.fields, nodes = g.stored_nodes(), nf = nodes * fields;
    const double tiny = empty_node_mass();
    double applied = 0.0;
    residual_.assign(D * nf, 0.0);
    for (int n = 0; n < nodes; ++n) {
        NodeCondition* cond = g.condition_at[n] >= 0 ? &g.conditions[g.condition_at[n]] : nullptr;
        if (cond) cond->begin_update(static_boundaries_);
        bool held_given = false;  // a node's held force goes to its first field pair with a skeleton
        for (int f = 0; f < fields; f += 2) {
            const int es = n * fields + f, ew = es + 1;
            const double Ms = g.mass[es], Mw = g.mass[ew];
            const bool has_solid = Ms > tiny, has_water = Mw > tiny;
            const double held_share = cond && !held_given && has_solid && !static_boundaries_ ? 1.0 : 0.0;
            held_given = held_given || held_share > 0.0;
            if (!has_solid) {
                for (int d = 0; d < D; ++d)
                    for (const int e : {es, ew}) g.velocity[D * e + d] = g.acceleration[D * e + d] = 0.0;
                continue;
            }
            const double Mnw = has_water ? g.water_inertia[es] : 0.0, Q = has_water ? g.drag[ew] : 0.0;
            const double porosity = has_water ? Mnw / Mw : 0.0;
            for (int d = 0; d < D; ++d) {
                const int ks = D * es + d, kw = D * ew + d;
                const double v0 = g.momentum[ks] / Ms, w0 = has_water ? g.momentum[kw] / Mnw : 0.0;
                // The far field's push: the force it held at rest plus its spring.
                const double spring = held_share > 0.0 ? cond->spring_force(d) : 0.0;
                const double held_at_rest = held_share > 0.0 ? cond->held_force[d] : 0.0;
                const double held = held_at_rest + spring;
                double Fs = g.force[ks] + held, Fw = has_water ? g.force[kw] : 0.0;
                const double cs = cond ? cond->dashpot[d] : 0.0, cw = cond && has_water ? cond->water_dashpot[d] : 0.0;
                const bool absorbing_held = cond && static_boundaries_ && cond->absorbing[d];
                if (absorbing_held) cond->held_force[d] -= Fs;
                const bool fixed_s = cond && (cond->fixed[d] || absorbing_held);
                const bool fixed_w = fixed_s && has_water && !cond->drained;
                if (!fixed_s) {
                    residual_[ks] = Fs;
                    applied += external_[ks] * external_[ks] + (has_water ? external_[kw] * external_[kw] : 0.0);
                    if (has_water) residual_[kw] = Fw - Q * (w0 - v0);
                    if (m_.local_damping > 0.0) {
                        if (v0 != 0.0) Fs -= m_.local_damping * std::abs(Fs) * (v0 > 0.0 ? 1.0 : -1.0);
                        if (has_water && w0 != v0) {
                            const double rel = Fw - Q * (w0 - v0);  // damp the water's unbalanced part
                            Fw -= m_.local_damping * std::abs(rel) * (w0 > v0 ? 1.0 : -1.0);
                        }
                    }
                }
                const double phi = 1.0 - porosity;
                const double pore_load = cw * (phi * v0 + porosity * w0);
                const double A11 = Ms + 0.5 * dt * (cs + cw * phi), A12 = Mnw + 0.5 * dt * cw * porosity;
                const double A21 = -dt * Q + 0.5 * dt * cw * phi, A22 = Mw + dt * Q + 0.5 * dt * cw * porosity;
                const double r1 = dt * (Fs - cs * v0 - pore_load);
                const double r2 = has_water ? dt * (Fw - pore_load) - dt * Q * (w0 - v0) : 0.0;
                double a = 0.0, b = 0.0;
                if (fixed_s) {
                    a = cond->prescribed[d] - v0;
                    b = !has_water ? 0.0 : fixed_w ? cond->prescribed[d] - w0 : (r2 - A21 * a) / A22;
                    const double on_water = fixed_w ? (A21 * a + A22 * b - r2) / dt : 0.0;
                    const double on_mixture = (A11 * a + A12 * b - r1) / dt;  // on the skeleton and the water together
                    (void)on_water;
                    cond->reaction[d] += on_mixture;
                } else if (!has_water) {
                    a = r1 / A11;
                } else {
                    const double det = A11 * A22 - A12 * A21;
                    a = (r1 * A22 - A12 * r2) / det;
                    b = (A11 * r2 - A21 * r1) / det;
                }
                const double v1 = v0 + a, w1 = has_water ? w0 + b : 0.0;
                if (cs > 0.0 || cw > 0.0) {
                    const double vm = 0.5 * (v0 + v1), wm = 0.5 * (w0 + w1), pm = phi * vm + porosity * wm;
                    absorbed_ += (cs * vm * vm + cw * pm * pm) * dt;
                }
                if (held_share > 0.0 && !fixed_s) absorbed_ += cond->move_far_field(d, spring, v0, v1, dt);
                external_work_ += 0.5 * (external_[ks] + held_at_rest) * (v0 + v1) * dt;
                if (has_water) external_work_ += 0.5 * external_[kw] * porosity * (w0 + w1 - v0 - v1) * dt;
                g.velocity[ks] = v1;
                g.acceleration[ks] = a / dt;
                g.velocity[kw] = w1;
                g.acceleration[kw] = has_water ? b / dt : 0.0;
            }
        }
    }
    hold_water_at_walls(dt);
    // Slip lines: not yet with water fields (contact_across_cuts says so).
    if constexpr (D == 2)
        if (any_contact_cut(m_.field_cuts)) contact_across_cuts(g, m_.field_cuts, tiny, dt, &residual_);
    walls_and_balance(dt, applied);
}

// An impermeable body's surface (m_.water_walls): at the nodes of the points against it
// that lie on it or behind it, the water's velocity relative to the skeleton loses its
// component along the surface's normal, the mixture's momentum Ms v + Mnw w unchanged (a
// force between the phases, none from the body: the body feels the pore pressure through
// the contact on the mixture). Nodes further into the soil, and the tangential flow, are
// left free. A component a boundary prescribes is left to the boundary. dt = 0: the
// remapped velocities (MUSL) of this step, at the nodes found for its update.
template <int D>
void MpmSolver<D>::hold_water_at_walls(double dt) {
    auto& g = m_.grid;
    if (m_.water_walls.empty() || !g.water) return;
    if (dt > 0.0) mark_water_walls();
    const double tiny = empty_node_mass();
    for (const int es : wall_entries_) {
        double n[D], norm = 0.0;
        const int node = es / g.fields;
        const NodeCondition* cond = g.condition_at[node] >= 0 ? &g.conditions[g.condition_at[node]] : nullptr;
        for (int d = 0; d < D; ++d) {
            n[d] = cond && cond->fixed[d] ? 0.0 : wall_normal_[D * es + d];
            norm += n[d] * n[d];
        }
        const int ew = es + 1;
        if (norm == 0.0 || g.mass[es] <= tiny || g.mass[ew] <= tiny) continue;
        norm = std::sqrt(norm);
        const double Ms = g.mass[es], Mnw = g.water_inertia[es];
        double relative = 0.0;
        for (int d = 0; d < D; ++d) {
            n[d] /= norm;
            relative += (g.velocity[D * ew + d] - g.velocity[D * es + d]) * n[d];
        }
        const double dv = Mnw * relative / (Ms + Mnw), dw = -Ms * relative / (Ms + Mnw);
        for (int d = 0; d < D; ++d) {
            g.velocity[D * es + d] += dv * n[d];
            g.velocity[D * ew + d] += dw * n[d];
            if (dt > 0.0) {
                g.acceleration[D * es + d] += dv * n[d] / dt;
                g.acceleration[D * ew + d] += dw * n[d] / dt;
            }
        }
    }
}

// The solid entries on or behind a wall (within a quarter cell) of the points against it,
// listed once each, with the walls' normals summed there.
template <int D>
void MpmSolver<D>::mark_water_walls() {
    auto& g = m_.grid;
    const int nf = g.stored_nodes() * g.fields;
    wall_normal_.assign(static_cast<std::size_t>(D) * nf, 0.0);
    wall_entries_.clear();
    double h = g.spacing[0];
    for (int d = 1; d < D; ++d) h = std::min(h, g.spacing[d]);
    for (const WaterWall& w : m_.water_walls) {
        const Stencil<D>& s = stencil_[w.point];
        for (int k = 0; k < s.count; ++k) {
            const int e = s.e[k].node;  // a solid entry
            double behind = 0.0;
            for (int d = 0; d < D; ++d) behind += (g.position[D * e + d] - w.on_surface[d]) * w.normal[d];
            if (behind > 0.25 * h) continue;  // inside the soil: free to drain
            bool fresh = true;
            for (int d = 0; d < D; ++d) {
                fresh = fresh && wall_normal_[D * e + d] == 0.0;
                wall_normal_[D * e + d] += w.normal[d];
            }
            if (fresh) wall_entries_.push_back(e);
        }
    }
}

// A coupled point's water velocity from its water field: the FLIP/PIC blend (APIC runs
// take the grid's velocity, PIC, since the water keeps no affine field).
template <int D>
void MpmSolver<D>::water_to_point(long i, double dt) {
    auto& p = m_.particles;
    if (drainage_[p.material[i]].drainage != Drainage::Coupled) return;
    const auto& g = m_.grid;
    const Stencil<D>& s = stencil_[i];
    double a[D] = {}, wg[D] = {};
    for (int k = 0; k < s.count; ++k) {
        const int at = D * (s.e[k].node + 1);
        for (int d = 0; d < D; ++d) {
            a[d] += s.e[k].N * g.acceleration[at + d];
            wg[d] += s.e[k].N * g.velocity[at + d];
        }
    }
    const double flip = m_.apic ? 0.0 : m_.flip;
    for (int d = 0; d < D; ++d) {
        double& w = p.w[D * i + d];
        w = flip * (w + a[d] * dt) + (1.0 - flip) * wg[d];
    }
}

// The pore water's mass balance on the points, after the strain increment is known:
// excess pressure from the volume change of the skeleton (and for coupled points the
// water's divergence), porosity from the skeleton's volume with incompressible grains.
template <int D>
void MpmSolver<D>::update_pore_water(double dt) {
    auto& p = m_.particles;
    const auto& g = m_.grid;
    const double Kw = m_.water.bulk_modulus;
    const long count = static_cast<long>(p.size());
#pragma omp parallel for schedule(static) if (count > kParallelPoints)
    for (long i = 0; i < count; ++i) {
        const Drainage dr = drainage_[p.material[i]].drainage;
        if (dr == Drainage::Dry) continue;
        const double n = p.porosity[i];
        const double* de = &p.dstrain[6 * i];
        const double solid_volumetric = de[0] + de[1] + de[2];
        if (dr == Drainage::Undrained) {
            p.pore_pressure[i] -= Kw / n * solid_volumetric;
        } else if (dr == Drainage::Coupled) {
            const Stencil<D>& s = stencil_[i];
            double div_w = 0.0;
            for (int k = 0; k < s.count; ++k) {
                const double* w = &g.velocity[D * (s.e[k].node + 1)];
                for (int d = 0; d < D; ++d) div_w += w[d] * s.e[k].dN[d];
                if (m_.axisymmetric) div_w += w[0] * s.hoop[k];
            }
            p.pore_pressure[i] -= Kw / n * ((1.0 - n) * solid_volumetric + n * div_w * dt);
        }
        // Cavitation: the water's absolute pressure does not fall below zero (it boils off
        // instead of pulling the grains together: no unbounded dilatant strength).
        if (m_.water.cavitation)
            p.pore_pressure[i] = std::max(p.pore_pressure[i], m_.water.least_excess_pressure(p.x[D * i + D - 1]));
        // The porosity is the point's: a model's void ratio starts each step from it.
        const int e_at = void_ratio_state_[p.material[i]];
        if (e_at >= 0) p.state[static_cast<std::size_t>(p.state_stride) * i + e_at] = n / (1.0 - n);
        // (1 - n) V is the grains' volume: it does not change.
        p.porosity[i] = 1.0 - (1.0 - n) * volume_before_[i] / p.volume[i];
    }
}

template void MpmSolver<2>::scatter_saturated();
template void MpmSolver<2>::update_grid_coupled(double);
template void MpmSolver<2>::water_to_point(long, double);
template void MpmSolver<2>::update_pore_water(double);
template void MpmSolver<2>::hold_water_at_walls(double);
template void MpmSolver<2>::mark_water_walls();
template void MpmSolver<3>::scatter_saturated();
template void MpmSolver<3>::update_grid_coupled(double);
template void MpmSolver<3>::water_to_point(long, double);
template void MpmSolver<3>::update_pore_water(double);
template void MpmSolver<3>::hold_water_at_walls(double);
template void MpmSolver<3>::mark_water_walls();

}  // namespace pilempm::mpm
