#include "mpm/solver/mpm_solver.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "mpm/solver/objective_rotation.hpp"

namespace pilempm::mpm {

// Below this many points a step is too short to pay for waking threads.
constexpr long kParallelPoints = 4000;

template <int D>
MpmSolver<D>::MpmSolver(MpmModel<D>& model) : m_(model) {
    if (m_.axisymmetric && D != 2) throw std::invalid_argument("axisymmetry needs D = 2");
    if (m_.grid.mass.empty()) m_.grid.allocate();
    points_of_material_.assign(m_.materials.size(), {});
    for (const auto& mat : m_.materials) tensor_states_.push_back(mat->num_tensor_state());
    for (std::size_t p = 0; p < m_.particles.size(); ++p) {
        const int mat = m_.particles.material[p];
        if (mat < 0 || mat >= static_cast<int>(m_.materials.size()))
            throw std::invalid_argument("material point with an unknown material");
        points_of_material_[mat].push_back(static_cast<int>(p));
    }
    stencil_.resize(m_.particles.size());
    mass_ = total_mass();  // points keep their mass: the grid's "empty node" threshold is fixed
}

namespace {

// Coulomb wall on node velocity v (D values): if v moves into the wall, the normal part is
// stopped and the tangential part loses at most friction x that normal change.
template <int D>
void apply_wall(int wall, double friction, double* v) {
    const int axis = wall / 2;
    const bool min_side = wall % 2 == 0;  // the wall lies below (x_axis = min): v_axis >= 0
    const double vn = v[axis];
    if (min_side ? vn >= 0.0 : vn <= 0.0) return;  // separating: free
    v[axis] = 0.0;
    double vt2 = 0.0;
    for (int d = 0; d < D; ++d)
        if (d != axis) vt2 += v[d] * v[d];
    const double vt = std::sqrt(vt2), cap = friction * std::abs(vn);
    const double keep = vt > cap ? 1.0 - cap / vt : 0.0;  // slip, or stick
    for (int d = 0; d < D; ++d)
        if (d != axis) v[d] *= keep;
}

}  // namespace

// Asks for the stencil of a point a few ahead: the passes after the scatter find the
// stencils in memory, not in cache, and would otherwise wait on each.
template <int D>
inline void prefetch_stencil(const std::vector<Stencil<D>>& stencils, long i) {
    constexpr long kAhead = 4;
    constexpr std::size_t kBytes = sizeof(typename Stencil<D>::Entry) * (D == 2 ? 9 : 27) + 64;  // a uGIMP stencil
    if (i + kAhead >= static_cast<long>(stencils.size())) return;
    const char* at = reinterpret_cast<const char*>(&stencils[i + kAhead]);
    for (std::size_t b = 0; b < kBytes; b += 64) __builtin_prefetch(at + b);
}

// The velocity a point carries to node k of its stencil: its own, plus with APIC its
// affine field C (x_node - x_point).
template <int D>
inline void MpmSolver<D>::velocity_toward_node(const Stencil<D>& s, int k, const double* v, const double* C,
                                        double* out) const {
    for (int d = 0; d < D; ++d) out[d] = v[d];
    if (!m_.apic) return;
    const double* xn = &m_.grid.position[D * s.e[k].node];
    double dx[D];
    for (int d = 0; d < D; ++d) dx[d] = xn[d] - s.x[d];
    for (int d = 0; d < D; ++d)
        for (int e = 0; e < D; ++e) out[d] += C[D * d + e] * dx[e];
}

template <int D>
double MpmSolver<D>::stable_time_step() const {
    const auto& p = m_.particles;
    double h = m_.grid.spacing[0];
    for (int d = 1; d < D; ++d) h = std::min(h, m_.grid.spacing[d]);
    double c_max = 0.0;
    const long n = static_cast<long>(p.size());
#pragma omp parallel for schedule(static) reduction(max : c_max) if (n > kParallelPoints)
    for (long i = 0; i < n; ++i) {
        const double rho = p.mass[i] / p.volume[i];
        double speed = 0.0;
        for (int d = 0; d < D; ++d) speed += p.v[D * i + d] * p.v[D * i + d];
        const double M = m_.materials[p.material[i]]->p_wave_modulus_at(&p.stress[6 * i],
                                                                       p.state.data() + p.state_stride * i);
        c_max = std::max(c_max, std::sqrt(M / rho) + std::sqrt(speed));
    }
    return c_max > 0.0 ? m_.cfl * h / c_max : 1e300;
}

// Every point must lie in the grid before its stencil is built (checked first, since
// nothing may throw inside a parallel region).
template <int D>
void MpmSolver<D>::check_points_inside() const {
    const auto& p = m_.particles;
    const long n = static_cast<long>(p.size());
    int outside = 0;
    long first_outside = n;
#pragma omp parallel for schedule(static) reduction(+ : outside) reduction(min : first_outside) if (n > kParallelPoints)
    for (long i = 0; i < n; ++i) {
        if (m_.grid.inside(&p.x[D * i])) continue;
        ++outside;
        first_outside = std::min(first_outside, i);
    }
    if (outside > 0) {
        std::string where;
        for (int d = 0; d < D; ++d) where += (d ? ", " : "") + std::to_string(p.x[D * first_outside + d]);
        throw std::runtime_error(std::to_string(outside) + " material point(s) left the grid, the first (point " +
                                 std::to_string(first_outside) + ") at (" + where + ") m at t = " +
                                 std::to_string(time_) + " s");
    }
}

template <int D>
void MpmSolver<D>::build_stencil(long i) {
    const auto& p = m_.particles;
    // Half-edge vectors of the domain: undeformed for uGIMP, F-deformed for CPDI.
    double half[D * D];
    for (int k = 0; k < D; ++k)
        for (int d = 0; d < D; ++d) {
            double v = 0.0;
            if (m_.shape == ShapeKind::CPDI) {
                for (int e = 0; e < D; ++e) v += p.F[D * D * i + D * d + e] * p.domain0[D * D * i + D * k + e];
            } else {
                v = p.domain0[D * D * i + D * k + d];
            }
            half[D * k + d] = 0.5 * v;
        }
    evaluate_shape<D>(m_.grid, m_.shape, m_.axisymmetric, &p.x[D * i], half, stencil_[i]);
}

// Each thread accumulates into its own copy of `fields` values per node; then they are
// summed: scatter without atomics, deterministic for a fixed thread count.
template <int D>
template <class Accumulate>
void MpmSolver<D>::scatter(int fields, Accumulate&& accumulate, std::vector<double>& out) {
    const std::size_t size = static_cast<std::size_t>(fields) * m_.grid.num_nodes();
    const int threads = omp_get_max_threads();
    thread_buffer_.resize(threads);
    const long n = static_cast<long>(m_.particles.size());
    int used = 1;  // threads that ran: only their buffers hold this step's sums
#pragma omp parallel if (n > kParallelPoints)
    {
#pragma omp single
        used = omp_get_num_threads();
        auto& buf = thread_buffer_[omp_get_thread_num()];
        buf.assign(size, 0.0);
#pragma omp for schedule(static)
        for (long i = 0; i < n; ++i) accumulate(i, buf.data());
    }
    out.assign(size, 0.0);
    for (int t = 0; t < used; ++t) {
        const auto& buf = thread_buffer_[t];
        for (std::size_t k = 0; k < size; ++k) out[k] += buf[k];
    }
}

template <int D>
void MpmSolver<D>::particles_to_grid() {
    auto& p = m_.particles;
    auto& g = m_.grid;
    constexpr int F = 1 + 3 * D;  // mass, momentum, total force, external force
    // Each point's stencil is built here and used at once, while it is in cache.
    scatter(F, [&](long i, double* buf) {
        build_stencil(i);
        const Stencil<D>& s = stencil_[i];
        // The point's loads, read once: the writes to buf could alias them otherwise.
        const double mass = p.mass[i], vol = p.volume[i];
        const double* sg = &p.stress[6 * i];
        double VS[D][D], body[D], v[D], C[D * D];  // vol x stress rows [xx xy xz; xy yy yz; xz yz zz]
        VS[0][0] = vol * sg[0];
        VS[1][1] = vol * sg[1];
        VS[0][1] = VS[1][0] = vol * sg[3];
        if constexpr (D == 3) {
            VS[2][2] = vol * sg[2];
            VS[1][2] = VS[2][1] = vol * sg[4];
            VS[0][2] = VS[2][0] = vol * sg[5];
        }
        for (int d = 0; d < D; ++d) {
            body[d] = mass * m_.gravity[d] + p.external_force[D * i + d];
            v[d] = p.v[D * i + d];
        }
        for (int k = 0; k < D * D; ++k) C[k] = p.C[D * D * i + k];
        const double hoop_force = m_.axisymmetric ? vol * sg[2] : 0.0;
        for (int k = 0; k < s.count; ++k) {
            double* b = buf + F * s.e[k].node;
            const double N = s.e[k].N;
            b[0] += N * mass;
            double vn[D];
            velocity_toward_node(s, k, v, C, vn);
            for (int d = 0; d < D; ++d) {
                b[1 + d] += N * mass * vn[d];
                const double external = N * body[d];
                double f = external;
                for (int e = 0; e < D; ++e) f -= VS[d][e] * s.e[k].dN[e];
                b[1 + D + d] += f;
                b[1 + 2 * D + d] += external;
            }
            if (hoop_force != 0.0) b[1 + D] -= hoop_force * s.hoop[k];  // hoop stress on f_r (axisymmetric)
        }
    }, scratch_);
    const int nn = g.num_nodes();
    for (int n = 0; n < nn; ++n) {
        g.mass[n] = scratch_[F * n];
        for (int d = 0; d < D; ++d) {
            g.momentum[D * n + d] = scratch_[F * n + 1 + d];
            g.force[D * n + d] = scratch_[F * n + 1 + D + d];
        }
    }
    external_.resize(D * nn);
    for (int n = 0; n < nn; ++n)
        for (int d = 0; d < D; ++d) external_[D * n + d] = scratch_[F * n + 1 + 2 * D + d];
    // Surface loads at the loaded faces (few points: serial).
    Stencil<D> at_face;
    for (const auto& load : m_.surface_loads) {
        double x[D];
        for (int d = 0; d < D; ++d) {
            x[d] = p.x[D * load.point + d];
            for (int e = 0; e < D; ++e) x[d] += p.F[D * D * load.point + D * d + e] * load.offset[e];
        }
        evaluate_shape<D>(g, ShapeKind::Linear, false, x, nullptr, at_face);
        for (int k = 0; k < at_face.count; ++k)
            for (int d = 0; d < D; ++d) {
                g.force[D * at_face.e[k].node + d] += at_face.e[k].N * load.force[d];
                external_[D * at_face.e[k].node + d] += at_face.e[k].N * load.force[d];
            }
    }
}

template <int D>
void MpmSolver<D>::update_grid(double dt) {
    auto& g = m_.grid;
    const int nn = g.num_nodes();
    const double tiny = 1e-12 * (mass_ / std::max(1, nn));
    double unbalanced = 0.0, applied = 0.0;
    residual_.assign(D * nn, 0.0);
    for (int n = 0; n < nn; ++n) {
        const double mass = g.mass[n];
        for (int d = 0; d < D; ++d) {
            const int k = D * n + d;
            if (mass <= tiny) {
                g.velocity[k] = g.acceleration[k] = g.reaction[k] = 0.0;
                continue;
            }
            const double v0 = g.momentum[k] / mass;
            double f = g.force[k];
            if (g.fixed[k]) {
                // The force the support (or moving boundary) exerts to hold v: from the
                // undamped nodal force, so damping never shows up as a reaction.
                g.reaction[k] = mass * (g.prescribed[k] - v0) / dt - f;
                g.velocity[k] = g.prescribed[k];
                g.acceleration[k] = (g.prescribed[k] - v0) / dt;
                continue;
            }
            residual_[k] = f;  // what equilibrium must bring to zero (walls add their reaction)
            applied += external_[k] * external_[k];
            // Cundall's local damping: a force against the motion, in proportion to the
            // unbalanced force, so equilibrium is reached without a global viscosity.
            if (m_.local_damping > 0.0 && v0 != 0.0) f -= m_.local_damping * std::abs(f) * (v0 > 0.0 ? 1.0 : -1.0);
            // Absorbing dashpot taken at mid-step: stable for any impedance.
            const double c = g.dashpot[k];
            double v1 = ((mass / dt - 0.5 * c) * v0 + f) / (mass / dt + 0.5 * c);
            g.reaction[k] = 0.0;
            if (c > 0.0) absorbed_ += 0.25 * c * (v0 + v1) * (v0 + v1) * dt;
            external_work_ += 0.5 * external_[k] * (v0 + v1) * dt;
            g.velocity[k] = v1;
            g.acceleration[k] = (v1 - v0) / dt;
        }
    }
    for (int n = 0; n < nn; ++n) {
        if (g.wall[n] < 0 || g.mass[n] <= tiny) continue;
        double v[D];
        for (int d = 0; d < D; ++d) v[d] = g.velocity[D * n + d];
        apply_wall<D>(g.wall[n], g.wall_friction[n], v);
        for (int d = 0; d < D; ++d) {
            const int k = D * n + d;
            const double push = g.mass[n] * (v[d] - g.velocity[k]) / dt;  // the wall's push and friction
            g.reaction[k] += push;
            residual_[k] += push;
            g.acceleration[k] += (v[d] - g.velocity[k]) / dt;
            g.velocity[k] = v[d];
        }
    }
    for (int k = 0; k < D * nn; ++k)
        if (!g.fixed[k] && g.mass[k / D] > tiny) unbalanced += residual_[k] * residual_[k];
    unbalanced_ratio_ = applied > 0.0 ? std::sqrt(unbalanced / applied) : 0.0;
}

// Point i takes its velocity (FLIP/PIC blend or APIC) and position from the updated grid.
template <int D>
void MpmSolver<D>::grid_to_point(long i, double dt) {
    auto& p = m_.particles;
    const auto& g = m_.grid;
    prefetch_stencil(stencil_, i);
    const Stencil<D>& s = stencil_[i];
    double a[D] = {}, vg[D] = {};
    for (int k = 0; k < s.count; ++k)
        for (int d = 0; d < D; ++d) {
            a[d] += s.e[k].N * g.acceleration[D * s.e[k].node + d];
            vg[d] += s.e[k].N * g.velocity[D * s.e[k].node + d];
        }
    if (m_.apic) {
        double* C = &p.C[D * D * i];
        for (int k = 0; k < D * D; ++k) C[k] = 0.0;
        for (int k = 0; k < s.count; ++k)
            for (int a = 0; a < D; ++a)
                for (int b = 0; b < D; ++b) C[D * a + b] += g.velocity[D * s.e[k].node + a] * s.e[k].dN[b];
    }
    const double flip = m_.flip;
    for (int d = 0; d < D; ++d) {
        double& v = p.v[D * i + d];
        v = m_.apic ? vg[d] : flip * (v + a[d] * dt) + (1.0 - flip) * vg[d];
        double& x = p.x[D * i + d];
        x += vg[d] * dt;
        if (g.closed[2 * d] && x < g.origin[d]) x = g.origin[d];
        const double top = g.origin[d] + g.spacing[d] * g.cells[d];
        if (g.closed[2 * d + 1] && x > top) x = top;
    }
}

// MUSL: the points' new momentum goes back to the grid for the velocities the stress
// update uses. One pass over the points does both their update and this scatter (the
// grid is only read until the scatter's sums are in).
template <int D>
void MpmSolver<D>::update_points_and_remap(double dt) {
    auto& p = m_.particles;
    auto& g = m_.grid;
    scatter(D, [&](long i, double* buf) {
        grid_to_point(i, dt);
        const Stencil<D>& s = stencil_[i];
        const double* C = &p.C[D * D * i];
        for (int k = 0; k < s.count; ++k) {
            double vn[D];
            velocity_toward_node(s, k, &p.v[D * i], C, vn);
            for (int d = 0; d < D; ++d) buf[D * s.e[k].node + d] += s.e[k].N * p.mass[i] * vn[d];
        }
    }, scratch_);
    const int nn = g.num_nodes();
    const double tiny = 1e-12 * (mass_ / std::max(1, nn));
    for (int n = 0; n < nn; ++n)
        for (int d = 0; d < D; ++d) {
            const int k = D * n + d;
            g.velocity[k] = g.fixed[k] ? g.prescribed[k] : (g.mass[n] > tiny ? scratch_[k] / g.mass[n] : 0.0);
        }
    // The remapped velocities may not enter a wall either (friction was applied above).
    for (int n = 0; n < nn; ++n) {
        if (g.wall[n] < 0) continue;
        const int axis = g.wall[n] / 2;
        double& vn = g.velocity[D * n + axis];
        if (g.wall[n] % 2 == 0 ? vn < 0.0 : vn > 0.0) vn = 0.0;
    }
}

template <int D>
void MpmSolver<D>::update_stress(double dt) {
    auto& p = m_.particles;
    const auto& g = m_.grid;
    const long n = static_cast<long>(p.size());
    int inverted = 0;
#pragma omp parallel for schedule(static) reduction(+ : inverted) if (n > kParallelPoints)
    for (long i = 0; i < n; ++i) {
        prefetch_stencil(stencil_, i);
        const Stencil<D>& s = stencil_[i];
        double L[D][D] = {}, hoop = 0.0;
        for (int k = 0; k < s.count; ++k) {
            const double* v = &g.velocity[D * s.e[k].node];
            for (int a = 0; a < D; ++a)
                for (int b = 0; b < D; ++b) L[a][b] += v[a] * s.e[k].dN[b];
            if (m_.axisymmetric) hoop += v[0] * s.hoop[k];
        }
        double* de = &p.dstrain[6 * i];
        de[0] = L[0][0] * dt;
        de[1] = L[1][1] * dt;
        de[3] = (L[0][1] + L[1][0]) * dt;
        if constexpr (D == 3) {
            de[2] = L[2][2] * dt;
            de[4] = (L[1][2] + L[2][1]) * dt;
            de[5] = (L[2][0] + L[0][2]) * dt;
        } else {
            de[2] = m_.axisymmetric ? hoop * dt : 0.0;
            de[4] = de[5] = 0.0;
        }
        // Objective rotation of the stress and the material's tensor state by the spin.
        double* st = p.state.data() + static_cast<std::size_t>(p.state_stride) * i;
        const int tensor_states = tensor_states_[p.material[i]];
        if constexpr (D == 2) {
            const double w = 0.5 * (L[0][1] - L[1][0]) * dt;
            rotate_tensor_in_plane(w, &p.stress[6 * i]);
            for (int t = 0; t < tensor_states; ++t) rotate_tensor_in_plane(w, st + 6 * t);
        } else {
            double W[3][3] = {};
            for (int a = 0; a < D; ++a)
                for (int b = 0; b < D; ++b) W[a][b] = 0.5 * (L[a][b] - L[b][a]) * dt;
            const Rotation rot = rotation_of_spin(W);
            rotate_tensor(rot, &p.stress[6 * i]);
            for (int t = 0; t < tensor_states; ++t) rotate_tensor(rot, st + 6 * t);
        }
        // Deformation gradient, volume and the accumulated strain.
        double Fn[D * D];
        for (int a = 0; a < D; ++a)
            for (int b = 0; b < D; ++b) {
                double v = p.F[D * D * i + D * a + b];
                for (int c = 0; c < D; ++c) v += L[a][c] * dt * p.F[D * D * i + D * c + b];
                Fn[D * a + b] = v;
            }
        for (int k = 0; k < D * D; ++k) p.F[D * D * i + k] = Fn[k];
        double J = D == 2 ? Fn[0] * Fn[3] - Fn[1] * Fn[2]
                          : Fn[0] * (Fn[4] * Fn[8] - Fn[5] * Fn[7]) - Fn[1] * (Fn[3] * Fn[8] - Fn[5] * Fn[6]) +
                                Fn[2] * (Fn[3] * Fn[7] - Fn[4] * Fn[6]);
        if (!(J > 0.0)) ++inverted;
        // Volume per radian in axisymmetry grows with the hoop stretch too.
        if (m_.axisymmetric) p.volume[i] *= 1.0 + de[0] + de[1] + de[2];
        else p.volume[i] = p.volume0[i] * J;
        for (int k = 0; k < 6; ++k) p.strain[6 * i + k] += de[k];
    }
    if (inverted > 0) throw std::runtime_error(std::to_string(inverted) + " material point(s) turned inside out (J <= 0)");
    for (std::size_t mat = 0; mat < m_.materials.size(); ++mat) {
        const auto& pts = points_of_material_[mat];
        const int count = static_cast<int>(pts.size());
        m_.materials[mat]->set_time(time_, dt);
        const int threads = count > kParallelPoints ? omp_get_max_threads() : 1;
#pragma omp parallel for schedule(static) if (threads > 1)
        for (int t = 0; t < threads; ++t) {
            const int lo = count * t / threads, hi = count * (t + 1) / threads;
            if (hi > lo)
                m_.materials[mat]->update(hi - lo, pts.data() + lo, p.dstrain.data(), p.stress.data(), p.state.data(),
                                          p.state_stride);
        }
    }
}

template <int D>
void MpmSolver<D>::step(double dt) {
    check_points_inside();
    particles_to_grid();
    update_grid(dt);
    update_points_and_remap(dt);
    update_stress(dt);
    time_ += dt;
    ++steps_;
}

template <int D>
double MpmSolver<D>::kinetic_energy() const {
    const auto& p = m_.particles;
    double e = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
        for (int d = 0; d < D; ++d) e += 0.5 * p.mass[i] * p.v[D * i + d] * p.v[D * i + d];
    return e;
}

template <int D>
std::array<double, D> MpmSolver<D>::momentum() const {
    std::array<double, D> q{};
    const auto& p = m_.particles;
    for (std::size_t i = 0; i < p.size(); ++i)
        for (int d = 0; d < D; ++d) q[d] += p.mass[i] * p.v[D * i + d];
    return q;
}

template <int D>
double MpmSolver<D>::total_mass() const {
    double m = 0.0;
    for (double x : m_.particles.mass) m += x;
    return m;
}

template class MpmSolver<2>;
template class MpmSolver<3>;

}  // namespace pilempm::mpm
