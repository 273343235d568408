#include "mpm/solver/mpm_solver.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <limits>
#include <utility>
#include <cmath>
#include <stdexcept>
#include <string>

#include "mpm/points/deformation.hpp"
#include "mpm/grid/field_contact.hpp"
#include "mpm/solver/objective_rotation.hpp"
#include "mpm/solver/solver_passes.hpp"

namespace pilempm::mpm {

template <int D>
MpmSolver<D>::MpmSolver(MpmModel<D>& model) : m_(model) {
    if (m_.axisymmetric && D != 2) throw std::invalid_argument("axisymmetry needs D = 2");
    if (m_.grid.block_count() == 0) m_.grid.allocate();
    points_of_material_.assign(m_.materials.size(), {});
    for (const auto& mat : m_.materials) tensor_states_.push_back(mat->num_tensor_state());
    for (std::size_t p = 0; p < m_.particles.size(); ++p) {
        const int mat = m_.particles.material[p];
        if (mat < 0 || mat >= static_cast<int>(m_.materials.size()))
            throw std::invalid_argument("material point with an unknown material");
        points_of_material_[mat].push_back(static_cast<int>(p));
        if (m_.particles.field[p] >= m_.grid.fields)
            throw std::invalid_argument("material point on velocity field " + std::to_string(m_.particles.field[p]) +
                                        " of a grid with " + std::to_string(m_.grid.fields));
    }
    drainage_ = m_.drainage;
    if (drainage_.empty()) drainage_.assign(m_.materials.size(), MaterialDrainage{});
    if (drainage_.size() != m_.materials.size())
        throw std::invalid_argument("drainage given for " + std::to_string(drainage_.size()) + " of " +
                                    std::to_string(m_.materials.size()) + " materials");
    for (const auto& dr : drainage_) {
        saturated_ = saturated_ || dr.saturated();
        coupled_ = coupled_ || dr.drainage == Drainage::Coupled;
        if (dr.saturated() && !(dr.porosity > 0.0 && dr.porosity < 1.0))
            throw std::invalid_argument("a saturated material needs a porosity between 0 and 1");
        if (dr.drainage == Drainage::Coupled && !(dr.darcy_resistance > 0.0))
            throw std::invalid_argument("a coupled material needs a permeability");
    }
    for (const auto& mat : m_.materials) void_ratio_state_.push_back(void_ratio_state(*mat));
    if (coupled_ && !m_.grid.water)
        throw std::invalid_argument("coupled (v-w) materials need a grid with water fields (Grid::water)");
    if (m_.grid.water && m_.particles.field.size() > 0)
        for (const int f : m_.particles.field)
            if (f % 2 != 0) throw std::invalid_argument("material points move with solid (even) fields of a grid with water");
    int top_field = 0;
    for (const int f : m_.particles.field) top_field = std::max(top_field, f);
    for (const auto& cut : m_.field_cuts) {
        if (D != 2) throw std::invalid_argument("field cuts are two-dimensional (a wall's mid-line)");
        if (cut.offset <= 0 || top_field + cut.offset >= m_.grid.fields || (m_.grid.water && cut.offset % 2 != 0))
            throw std::invalid_argument("a field cut of offset " + std::to_string(cut.offset) + " needs a grid of more than " +
                                        std::to_string(top_field + cut.offset) + " fields (in pairs with water), it has " +
                                        std::to_string(m_.grid.fields));
    }
    stencil_.resize(m_.particles.size());
    mass_ = total_mass();  // points keep their mass: the grid's "empty node" threshold is fixed
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
        double speed = 0.0;
        for (int d = 0; d < D; ++d) speed += p.v[D * i + d] * p.v[D * i + d];
        c_max = std::max(c_max, point_wave_speed(i) + std::sqrt(speed));
    }
    return c_max > 0.0 ? m_.cfl * h / c_max : 1e300;
}

template <int D>
SolverState MpmSolver<D>::state() const {
    SolverState s{time_, steps_, absorbed_, external_work_, {}, {}};
    for (const auto& c : m_.grid.conditions) {
        s.held_force.insert(s.held_force.end(), c.held_force, c.held_force + 3);
        s.boundary_displacement.insert(s.boundary_displacement.end(), c.displacement, c.displacement + 3);
    }
    return s;
}

template <int D>
void MpmSolver<D>::restore(const SolverState& s) {
    time_ = s.time;
    steps_ = s.steps;
    absorbed_ = s.absorbed_energy;
    external_work_ = s.external_work;
    auto& conditions = m_.grid.conditions;
    if (s.held_force.empty()) return;  // a checkpoint from before held boundaries: none held
    if (s.held_force.size() != 3 * conditions.size())
        throw std::invalid_argument("held boundary forces for " + std::to_string(s.held_force.size() / 3) + " of " +
                                    std::to_string(conditions.size()) + " boundary nodes");
    for (std::size_t c = 0; c < conditions.size(); ++c)
        std::copy_n(s.held_force.begin() + 3 * c, 3, conditions[c].held_force);
    // A checkpoint from before the far field's springs: the boundary anchored where it is.
    if (s.boundary_displacement.size() == 3 * conditions.size())
        for (std::size_t c = 0; c < conditions.size(); ++c)
            std::copy_n(s.boundary_displacement.begin() + 3 * c, 3, conditions[c].displacement);
}

template <int D>
void MpmSolver<D>::set_drained(bool drained) {
    if (drained == drained_) return;
    drained_ = drained;
    coupled_ = false;
    for (std::size_t k = 0; k < drainage_.size(); ++k) {
        drainage_[k] = m_.drainage.empty() ? MaterialDrainage{} : m_.drainage[k];
        if (drained && drainage_[k].drainage == Drainage::Coupled) drainage_[k].drainage = Drainage::Drained;
        coupled_ = coupled_ || drainage_[k].drainage == Drainage::Coupled;
    }
    auto& p = m_.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (m_.drainage.empty() || m_.drainage[p.material[i]].drainage != Drainage::Coupled) continue;
        p.pore_pressure[i] = 0.0;
        for (int d = 0; d < D; ++d) p.w[D * i + d] = 0.0;
    }
}

template <int D>
double MpmSolver<D>::point_wave_speed(long i) const {
    const auto& p = m_.particles;
    const double rho = p.mass[i] / p.volume[i];
    const double M = m_.materials[p.material[i]]->p_wave_modulus_at(&p.stress[6 * i], p.state.data() + p.state_stride * i);
    const MaterialDrainage& dr = drainage_[p.material[i]];
    if (!dr.saturated()) return std::sqrt(M / rho);
    const double n = p.porosity[i];
    if (dr.drainage == Drainage::Drained) return std::sqrt(M / (rho + n * m_.water.density));
    const SaturatedWaveSpeeds c = saturated_wave_speeds(M, n, rho, m_.water);
    return dr.drainage == Drainage::Undrained ? c.undrained : c.fastest;
}

template <int D>
TimeStepLimit MpmSolver<D>::time_step_limit() const {
    const auto& p = m_.particles;
    double h = m_.grid.spacing[0];
    for (int d = 1; d < D; ++d) h = std::min(h, m_.grid.spacing[d]);
    TimeStepLimit limit;
    long at = -1;
    for (long i = 0; i < static_cast<long>(p.size()); ++i) {
        double speed = 0.0;
        for (int d = 0; d < D; ++d) speed += p.v[D * i + d] * p.v[D * i + d];
        const double c = point_wave_speed(i) + std::sqrt(speed);
        if (c > limit.wave_speed) limit.wave_speed = c, at = i;
        const MaterialDrainage& dr = drainage_[p.material[i]];
        if (dr.drainage == Drainage::Coupled) {
            // Drag relaxation time rho_w / (n mu/kappa) = k / (n g); explicit Euler needs dt < twice it.
            const double explicit_drag = 2.0 * m_.water.density / (p.porosity[i] * dr.darcy_resistance);
            limit.explicit_drag_limit =
                limit.explicit_drag_limit > 0.0 ? std::min(limit.explicit_drag_limit, explicit_drag) : explicit_drag;
        }
    }
    limit.dt = limit.wave_speed > 0.0 ? m_.cfl * h / limit.wave_speed : 1e300;
    if (at >= 0) {
        const Drainage d = drainage_[p.material[at]].drainage;
        limit.limited_by = std::string(d == Drainage::Coupled ? "fastest v-w P-wave" : d == Drainage::Undrained
                                                                                          ? "undrained P-wave"
                                                                                          : "P-wave") +
                           " of material " + std::to_string(p.material[at]) + " (" + drainage_name(d) + ")";
    }
    return limit;
}

// The D half-edge vectors of point i's domain (row k = vector k): undeformed for uGIMP,
// F-deformed for CPDI.
template <int D>
void MpmSolver<D>::half_edges(long i, double* half) const {
    half_domain_edges<D>(m_.particles, i, m_.shape, half);
}

// Marks the blocks holding the nodes whose hats reach the box x +- extent (x in the grid);
// returns the first and the last block marked.
template <int D>
inline std::pair<int, int> mark_blocks(const Grid<D>& g, const double* x, const double* extent, const double* inv_h,
                                       unsigned char* marks) {
    int lo[D], hi[D];
    for (int d = 0; d < D; ++d) {
        int a, b;
        if (g.graded(d)) {
            a = g.cell_beyond(d, x[d] - extent[d]);
            b = g.cell_beyond(d, x[d] + extent[d]) + 1;
        } else {
            a = static_cast<int>(std::floor((x[d] - extent[d] - g.origin[d]) * inv_h[d]));
            b = static_cast<int>((x[d] + extent[d] - g.origin[d]) * inv_h[d]) + 1;
        }
        lo[d] = std::max(0, a) >> Grid<D>::kBlockShift;
        hi[d] = std::min(g.cells[d], b) >> Grid<D>::kBlockShift;
    }
    const auto& along = g.blocks_along();
    int b[D], first = -1, last = -1;
    for (int d = 0; d < D; ++d) b[d] = lo[d];
    while (true) {
        int block = 0;
        for (int d = D - 1; d >= 0; --d) block = block * along[d] + b[d];
        std::atomic_ref<unsigned char>(marks[block]).store(1, std::memory_order_relaxed);
        if (first < 0) first = block;
        last = block;
        int d = 0;
        while (d < D && ++b[d] > hi[d]) b[d] = lo[d], ++d;
        if (d == D) break;
    }
    return {first, last};
}

// Every point must lie in the grid before its stencil is built (checked first, since
// nothing may throw inside a parallel region). The same pass marks the blocks of nodes each
// point's domain reaches, and the loaded faces': only those blocks hold node data this step.
template <int D>
void MpmSolver<D>::activate_grid() {
    const auto& p = m_.particles;
    auto& g = m_.grid;
    const long n = static_cast<long>(p.size());
    block_marks_.assign(g.block_count(), 0);
    unsigned char* marks = block_marks_.data();
    // Locals: the byte stores into the marks may alias anything, so nothing they need may
    // be read through a pointer.
    double inv_h[D], top[D], origin[D];
    int cells[D], along[D];
    bool graded = false;
    for (int d = 0; d < D; ++d) {
        origin[d] = g.origin[d];
        inv_h[d] = 1.0 / g.spacing[d];
        top[d] = g.top(d);
        graded = graded || g.graded(d);
        cells[d] = g.cells[d];
        along[d] = g.blocks_along()[d];
    }
    const bool cpdi = m_.shape == ShapeKind::CPDI;
    // The nodes a point's hats reach from its cell c: c..c+1 (linear), c-1..c+2 (uGIMP, whose
    // domain is at most a cell); CPDI's deformed domain is measured.
    const int below = m_.shape == ShapeKind::GIMP ? 1 : 0, above = below + 1;
    // The points are cut into one chunk per thread; each chunk's scatter buffer covers only
    // the blocks its points reach (points lie cell by cell, so a chunk is a slab of the
    // body), and the chunks are the same in every pass of the step.
    const int chunks = n > kParallelPoints ? omp_get_max_threads() : 1;
    chunk_blocks_.assign(2 * chunks, -1);
    int outside = 0;
    long first_outside = n;
#pragma omp parallel for schedule(static, 1) num_threads(chunks) reduction(+ : outside) reduction(min : first_outside)
    for (int chunk = 0; chunk < chunks; ++chunk) {
        // Points come cell by cell: a point in the cell of the one before marks nothing new.
        int last[D];
        for (int d = 0; d < D; ++d) last[d] = -1;
        int lowest = std::numeric_limits<int>::max(), highest = -1;
        for (long i = chunk_begin(chunk, chunks); i < chunk_begin(chunk + 1, chunks); ++i) {
            const double* x = &p.x[D * i];
            bool in = true;
            for (int d = 0; d < D; ++d) in = in && x[d] >= origin[d] && x[d] <= top[d];
            if (!in) {
                ++outside;
                first_outside = std::min(first_outside, i);
                continue;
            }
            if (cpdi) {
                double half[D * D], extent[D] = {};
                half_edges(i, half);
                for (int d = 0; d < D; ++d)
                    for (int k = 0; k < D; ++k) extent[d] += std::abs(half[D * k + d]);
                const auto [a, b] = mark_blocks<D>(g, x, extent, inv_h, marks);
                lowest = std::min(lowest, a);
                highest = std::max(highest, b);
                continue;
            }
            int c[D];
            bool same = true;
            for (int d = 0; d < D; ++d) {
                // x >= origin: truncation is floor
                c[d] = graded ? g.cell_of(d, x[d]) : static_cast<int>((x[d] - origin[d]) * inv_h[d]);
                same = same && c[d] == last[d];
            }
            if (same) continue;
            int lo[D], hi[D];
            for (int d = 0; d < D; ++d) {
                last[d] = c[d];
                lo[d] = std::max(0, c[d] - below) >> Grid<D>::kBlockShift;
                hi[d] = std::min(cells[d], c[d] + above) >> Grid<D>::kBlockShift;
            }
            int first_block, last_block;
            if constexpr (D == 2) {
                first_block = lo[0] + along[0] * lo[1];
                last_block = hi[0] + along[0] * hi[1];
                for (int by = lo[1]; by <= hi[1]; ++by)
                    for (int bx = lo[0]; bx <= hi[0]; ++bx)
                        std::atomic_ref<unsigned char>(marks[bx + along[0] * by]).store(1, std::memory_order_relaxed);
            } else {
                first_block = lo[0] + along[0] * (lo[1] + along[1] * lo[2]);
                last_block = hi[0] + along[0] * (hi[1] + along[1] * hi[2]);
                for (int bz = lo[2]; bz <= hi[2]; ++bz)
                    for (int by = lo[1]; by <= hi[1]; ++by)
                        for (int bx = lo[0]; bx <= hi[0]; ++bx)
                            std::atomic_ref<unsigned char>(marks[bx + along[0] * (by + along[1] * bz)])
                                .store(1, std::memory_order_relaxed);
            }
            lowest = std::min(lowest, first_block);
            highest = std::max(highest, last_block);
        }
        chunk_blocks_[2 * chunk] = highest >= 0 ? lowest : -1;
        chunk_blocks_[2 * chunk + 1] = highest;
    }
    if (outside > 0) {
        std::string where;
        for (int d = 0; d < D; ++d) where += (d ? ", " : "") + std::to_string(p.x[D * first_outside + d]);
        throw std::runtime_error(std::to_string(outside) + " material point(s) left the grid, the first (point " +
                                 std::to_string(first_outside) + ") at (" + where + ") m at t = " +
                                 std::to_string(time_) + " s");
    }
    const double none[D] = {};
    for (const auto& load : m_.surface_loads) {
        double x[D];
        face_of(load, x);
        if (g.inside(x)) mark_blocks<D>(g, x, none, inv_h, marks);
    }
    g.set_active_blocks(block_marks_);
    // Blocks are stored in block order: a chunk's blocks lie between its first's and last's slots.
    for (int chunk = 0; chunk < chunks; ++chunk)
        if (chunk_blocks_[2 * chunk] >= 0)
            for (int k = 0; k < 2; ++k) chunk_blocks_[2 * chunk + k] = g.slot_of_block(chunk_blocks_[2 * chunk + k]);
}

// Where a surface load acts: the point's face, x_p + F offset.
template <int D>
void MpmSolver<D>::face_of(const SurfaceLoad& load, double* x) const {
    const auto& p = m_.particles;
    for (int d = 0; d < D; ++d) {
        x[d] = p.x[D * load.point + d];
        for (int e = 0; e < D; ++e) x[d] += p.F[D * D * load.point + D * d + e] * load.offset[e];
    }
}

template <int D>
void MpmSolver<D>::build_stencil(long i) {
    double half[D * D];
    half_edges(i, half);
    evaluate_shape<D>(m_.grid, m_.shape, m_.axisymmetric, &m_.particles.x[D * i], half, stencil_[i],
                      m_.particles.field[i]);
    if constexpr (D == 2)
        if (!m_.field_cuts.empty()) apply_field_cuts(m_.grid, m_.field_cuts, &m_.particles.x[D * i], half, stencil_[i]);
}

// Per grid entry: mass, momentum, total force, and (PointForces) the forces applied to points
// (contact), which the external force of the equilibrium measure needs besides m_i g.
template <int D>
template <bool PointForces>
void MpmSolver<D>::scatter_to_grid() {
    auto& p = m_.particles;
    auto& g = m_.grid;
    constexpr int V = PointForces ? 1 + 3 * D : 1 + 2 * D;
    const int fields = g.fields;
    // Each point's stencil is built here and used at once, while it is in cache.
    scatter(V * fields, [&](long i, double* buf) {
        build_stencil(i);
        const Stencil<D>& s = stencil_[i];
        // The point's loads, read once: the writes to buf could alias them otherwise.
        const double mass = p.mass[i], vol = p.volume[i];
        const double* sg = &p.stress[6 * i];
        double VS[D][D], body[D], v[D], C[D * D], applied[D];  // vol x stress rows [xx xy xz; xy yy yz; xz yz zz]
        VS[0][0] = vol * sg[0];
        VS[1][1] = vol * sg[1];
        VS[0][1] = VS[1][0] = vol * sg[3];
        if constexpr (D == 3) {
            VS[2][2] = vol * sg[2];
            VS[1][2] = VS[2][1] = vol * sg[4];
            VS[0][2] = VS[2][0] = vol * sg[5];
        }
        for (int d = 0; d < D; ++d) {
            applied[d] = p.external_force[D * i + d];
            body[d] = mass * m_.gravity[d] + applied[d];
            v[d] = p.v[D * i + d];
        }
        for (int k = 0; k < D * D; ++k) C[k] = p.C[D * D * i + k];
        const double hoop_force = m_.axisymmetric ? vol * sg[2] : 0.0;
        for (int k = 0; k < s.count; ++k) {
            double* b = buf + V * s.e[k].node;
            const double N = s.e[k].N;
            b[0] += N * mass;
            double vn[D];
            velocity_toward_node(s, k, v, C, vn);
            for (int d = 0; d < D; ++d) {
                b[1 + d] += N * mass * vn[d];
                double f = N * body[d];
                for (int e = 0; e < D; ++e) f -= VS[d][e] * s.e[k].dN[e];
                b[1 + D + d] += f;
                if constexpr (PointForces) b[1 + 2 * D + d] += N * applied[d];
            }
            if (hoop_force != 0.0) b[1 + D] -= hoop_force * s.hoop[k];  // hoop stress on f_r (axisymmetric)
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
            external_[D * k + d] = b[0] * m_.gravity[d];
            if constexpr (PointForces) external_[D * k + d] += b[1 + 2 * D + d];
        }
    }
}

template <int D>
void MpmSolver<D>::particles_to_grid() {
    auto& p = m_.particles;
    auto& g = m_.grid;
    if (saturated_)
        scatter_saturated();
    else if (std::any_of(p.external_force.begin(), p.external_force.end(), [](double f) { return f != 0.0; }))
        scatter_to_grid<true>();
    else
        scatter_to_grid<false>();
    // Surface loads at the loaded faces (few points: serial), on the point's field.
    Stencil<D> at_face;
    for (const auto& load : m_.surface_loads) {
        double x[D];
        face_of(load, x);
        evaluate_shape<D>(g, ShapeKind::Linear, false, x, nullptr, at_face, p.field[load.point]);
        for (int k = 0; k < at_face.count; ++k)
            for (int d = 0; d < D; ++d) {
                const int at = D * at_face.e[k].node + d;
                g.force[at] += at_face.e[k].N * load.force[d];
                external_[at] += at_face.e[k].N * load.force[d];
            }
    }
}

template <int D>
void MpmSolver<D>::update_grid(double dt) {
    if (coupled_) {
        update_grid_coupled(dt);
        return;
    }
    auto& g = m_.grid;
    const int fields = g.fields, nodes = g.stored_nodes(), nf = nodes * fields;
    const double tiny = empty_node_mass();
    double applied = 0.0;
    residual_.assign(D * nf, 0.0);
    for (int n = 0; n < nodes; ++n) {
        NodeCondition* cond = g.condition_at[n] >= 0 ? &g.conditions[g.condition_at[n]] : nullptr;
        if (cond) cond->begin_update(static_boundaries_);
        bool held_given = false;  // a node's held force goes to its first field with mass
        for (int f = 0; f < fields; ++f) {
            const int nodef = n * fields + f;
            const double mass = g.mass[nodef];
            const double held_share = cond && !held_given && mass > tiny && !static_boundaries_ ? 1.0 : 0.0;
            held_given = held_given || held_share > 0.0;
            for (int d = 0; d < D; ++d) {
                const int k = D * nodef + d;
                if (mass <= tiny) {
                    g.velocity[k] = g.acceleration[k] = 0.0;
                    continue;
                }
                const double v0 = g.momentum[k] / mass;
                // The far field's push: the force it held at rest plus its spring.
                const double spring = held_share > 0.0 ? cond->spring_force(d) : 0.0;
                const double held_at_rest = held_share > 0.0 ? cond->held_force[d] : 0.0;
                const double held = held_at_rest + spring;
                double force = g.force[k] + held;
                const bool absorbing_held = cond && static_boundaries_ && cond->absorbing[d];
                if (cond && (cond->fixed[d] || absorbing_held)) {
                    if (absorbing_held) cond->held_force[d] -= force;
                    // The force the support (or moving boundary) exerts to hold v: from the
                    // undamped nodal force, so damping never shows up as a reaction.
                    cond->reaction[d] += mass * (cond->prescribed[d] - v0) / dt - force;
                    g.velocity[k] = cond->prescribed[d];
                    g.acceleration[k] = (cond->prescribed[d] - v0) / dt;
                    continue;
                }
                residual_[k] = force;  // what equilibrium must bring to zero (walls add their reaction)
                applied += external_[k] * external_[k];
                // Cundall's local damping: a force against the motion, in proportion to the
                // unbalanced force, so equilibrium is reached without a global viscosity.
                if (m_.local_damping > 0.0 && v0 != 0.0)
                    force -= m_.local_damping * std::abs(force) * (v0 > 0.0 ? 1.0 : -1.0);
                // Absorbing dashpot taken at mid-step: stable for any impedance.
                const double c = cond ? cond->dashpot[d] : 0.0;
                double v1 = ((mass / dt - 0.5 * c) * v0 + force) / (mass / dt + 0.5 * c);
                if (c > 0.0) absorbed_ += 0.25 * c * (v0 + v1) * (v0 + v1) * dt;
                if (held_share > 0.0) absorbed_ += cond->move_far_field(d, spring, v0, v1, dt);
                external_work_ += 0.5 * (external_[k] + held_at_rest) * (v0 + v1) * dt;
                g.velocity[k] = v1;
                g.acceleration[k] = (v1 - v0) / dt;
            }
        }
    }
    if constexpr (D == 2)
        if (any_contact_cut(m_.field_cuts)) contact_across_cuts(g, m_.field_cuts, tiny, dt, &residual_);
    walls_and_balance(dt, applied);
}

// Rigid walls, then the unbalanced force ratio. The skeleton slides on a wall with its
// friction; pore water may not enter it either (no friction: its push acts on the water's
// inertia in the mixture).
template <int D>
void MpmSolver<D>::walls_and_balance(double dt, double applied) {
    auto& g = m_.grid;
    const int fields = g.fields, nodes = g.stored_nodes();
    const double tiny = empty_node_mass();
    for (int n = 0; n < nodes; ++n) {
        if (g.condition_at[n] < 0) continue;
        NodeCondition& cond = g.conditions[g.condition_at[n]];
        if (cond.wall < 0) continue;
        for (int f = 0; f < fields; ++f) {
            const int nodef = n * fields + f;
            if (g.mass[nodef] <= tiny) continue;
            const bool water = g.water && f % 2 == 1;
            double v[D];
            for (int d = 0; d < D; ++d) v[d] = g.velocity[D * nodef + d];
            apply_wall<D>(cond.wall, water ? 0.0 : cond.wall_friction, v);
            const double inertia = water ? g.water_inertia[nodef - 1] : g.mass[nodef];
            for (int d = 0; d < D; ++d) {
                const int k = D * nodef + d;
                const double push = inertia * (v[d] - g.velocity[k]) / dt;  // the wall's push and friction
                cond.reaction[d] += push;
                residual_[k] += push;
                g.acceleration[k] += (v[d] - g.velocity[k]) / dt;
                g.velocity[k] = v[d];
            }
        }
    }
    double unbalanced = 0.0;
    for (int n = 0; n < nodes; ++n) {
        const NodeCondition* cond = g.condition_at[n] >= 0 ? &g.conditions[g.condition_at[n]] : nullptr;
        for (int f = 0; f < fields; ++f) {
            const int nodef = n * fields + f;
            if (g.mass[nodef] <= tiny) continue;
            for (int d = 0; d < D; ++d)
                if (!(cond && cond->fixed[d])) unbalanced += residual_[D * nodef + d] * residual_[D * nodef + d];
        }
    }
    unbalanced_ratio_ = applied > 0.0 ? std::sqrt(unbalanced / applied) : 0.0;
}

// Point i takes its velocity (FLIP/PIC blend or APIC) and position from the updated grid,
// from its own velocity field.
template <int D>
void MpmSolver<D>::grid_to_point(long i, double dt) {
    auto& p = m_.particles;
    const auto& g = m_.grid;
    prefetch_stencil(stencil_, i);
    const Stencil<D>& s = stencil_[i];
    double a[D] = {}, vg[D] = {};
    for (int k = 0; k < s.count; ++k) {
        const int at = D * s.e[k].node;
        for (int d = 0; d < D; ++d) {
            a[d] += s.e[k].N * g.acceleration[at + d];
            vg[d] += s.e[k].N * g.velocity[at + d];
        }
    }
    if (m_.apic) {
        double* C = &p.C[D * D * i];
        for (int k = 0; k < D * D; ++k) C[k] = 0.0;
        for (int k = 0; k < s.count; ++k) {
            const int at = D * s.e[k].node;
            for (int a = 0; a < D; ++a)
                for (int b = 0; b < D; ++b) C[D * a + b] += g.velocity[at + a] * s.e[k].dN[b];
        }
    }
    const double flip = m_.flip;
    for (int d = 0; d < D; ++d) {
        double& v = p.v[D * i + d];
        v = m_.apic ? vg[d] : flip * (v + a[d] * dt) + (1.0 - flip) * vg[d];
        double& x = p.x[D * i + d];
        x += vg[d] * dt;
        if (g.closed[2 * d] && x < g.origin[d]) x = g.origin[d];
        const double top = g.top(d);
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
    const int fields = g.fields;
    if (!saturated_) {
        scatter(D * fields, [&](long i, double* buf) {
            grid_to_point(i, dt);
            const Stencil<D>& s = stencil_[i];
            const double* C = &p.C[D * D * i];
            for (int k = 0; k < s.count; ++k) {
                double vn[D];
                velocity_toward_node(s, k, &p.v[D * i], C, vn);
                double* b = buf + D * s.e[k].node;
                for (int d = 0; d < D; ++d) b[d] += s.e[k].N * p.mass[i] * vn[d];
            }
        }, scratch_);
    } else {
        // The solid field carries the mass the scatter gave it (with the water of drained and
        // undrained points); a coupled point's water goes to its water field.
        const double rho_w = m_.water.density;
        scatter(D * fields, [&](long i, double* buf) {
            if (coupled_) water_to_point(i, dt);
            grid_to_point(i, dt);
            const Stencil<D>& s = stencil_[i];
            const double* C = &p.C[D * D * i];
            const Drainage dr = drainage_[p.material[i]].drainage;
            const double water = p.porosity[i] * rho_w * p.volume[i];
            const double inertia = dr == Drainage::Dry || dr == Drainage::Coupled ? p.mass[i] : p.mass[i] + water;
            const double water_mass = dr == Drainage::Coupled ? water : 0.0;
            for (int k = 0; k < s.count; ++k) {
                double vn[D];
                velocity_toward_node(s, k, &p.v[D * i], C, vn);
                double* b = buf + D * s.e[k].node;
                for (int d = 0; d < D; ++d) b[d] += s.e[k].N * inertia * vn[d];
                if (water_mass > 0.0)
                    for (int d = 0; d < D; ++d) b[D + d] += s.e[k].N * water_mass * p.w[D * i + d];
            }
        }, scratch_);
    }
    const int nodes = g.stored_nodes();
    const double tiny = empty_node_mass();
    for (int n = 0; n < nodes; ++n) {
        const NodeCondition* cond = g.condition_at[n] >= 0 ? &g.conditions[g.condition_at[n]] : nullptr;
        for (int f = 0; f < fields; ++f) {
            const int nodef = n * fields + f;
            for (int d = 0; d < D; ++d) {
                const int k = D * nodef + d;
                // A water field at a drained boundary is free; at any other it is held with the solid.
                const bool water_entry = g.water && f % 2 == 1;
                const bool held = cond && cond->fixed[d] && !(water_entry && cond->drained);
                // The water's momentum came with its own mass (the water inertia), not the
                // water equation's.
                const double inertia = water_entry ? g.water_inertia[nodef - 1] : g.mass[nodef];
                g.velocity[k] = held ? cond->prescribed[d] : (g.mass[nodef] > tiny ? scratch_[k] / inertia : 0.0);
            }
            // The remapped velocities may not enter a wall either (friction was applied above).
            if (cond && cond->wall >= 0) {
                double& vn = g.velocity[D * nodef + cond->wall / 2];
                if (cond->wall % 2 == 0 ? vn < 0.0 : vn > 0.0) vn = 0.0;
            }
        }
    }
    // Nor interpenetrate across a slip line.
    if constexpr (D == 2)
        if (any_contact_cut(m_.field_cuts)) contact_across_cuts(g, m_.field_cuts, tiny, 0.0, nullptr);
    // Nor cross an impermeable body's surface.
    if (coupled_) hold_water_at_walls(0.0);
}

template <int D>
void MpmSolver<D>::update_stress(double dt) {
    auto& p = m_.particles;
    const auto& g = m_.grid;
    const long n = static_cast<long>(p.size());
    int inverted = 0;
    if (saturated_) volume_before_.resize(p.size());
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
        double J = determinant<D>(Fn);
        if (!(J > 0.0)) ++inverted;
        // Volume per radian in axisymmetry grows with the hoop stretch too.
        if (saturated_) volume_before_[i] = p.volume[i];
        if (m_.axisymmetric) p.volume[i] *= 1.0 + de[0] + de[1] + de[2];
        else p.volume[i] = p.volume0[i] * J;
        for (int k = 0; k < 6; ++k) p.strain[6 * i + k] += de[k];
    }
    if (inverted > 0) {
        // Where, for the user: the first such point (found again, off the hot loop).
        long first = 0;
        for (long i = 0; i < n; ++i) {
            if (!(determinant<D>(&p.F[D * D * i]) > 0.0)) {
                first = i;
                break;
            }
        }
        std::string where;
        for (int d = 0; d < D; ++d) where += (d ? ", " : "") + std::to_string(p.x[D * first + d]);
        throw std::runtime_error(std::to_string(inverted) + " material point(s) turned inside out (J <= 0), the first (point " +
                                 std::to_string(first) + ", material " + std::to_string(p.material[first]) + ") at (" +
                                 where + ") m at t = " + std::to_string(time_) + " s");
    }
    if (m_.smooth_dilatation) smooth_dilatation();
    if (saturated_) update_pore_water(dt);
    for (std::size_t mat = 0; mat < m_.materials.size(); ++mat) {
        const auto& pts = points_of_material_[mat];
        const int count = static_cast<int>(pts.size());
        m_.materials[mat]->set_time(time_, dt);
        // Points cost unevenly (a yielding HS-small point substeps, an elastic one does not,
        // and the yielding ones cluster by the pile), so threads take small chunks in turn
        // rather than one even slice each; each point's update is its own, the bits the same.
        constexpr int kChunk = 64;
        const int chunks = (count + kChunk - 1) / kChunk;
#pragma omp parallel for schedule(dynamic, 1) if (count > kParallelPoints)
        for (int c = 0; c < chunks; ++c) {
            const int lo = c * kChunk, hi = std::min(count, lo + kChunk);
            m_.materials[mat]->update(hi - lo, pts.data() + lo, p.dstrain.data(), p.stress.data(), p.state.data(),
                                      p.state_stride);
        }
    }
}

// The nodal average of the volumetric strain increment (after Coombs et al. 2018's cell
// average, on the nodes so that it follows the field cuts): sum N m de_v / sum N m at each
// node entry, read back with the same weights. The point's normal strains take the
// difference equally (the hoop too in axisymmetry, not the out-of-plane one in plane
// strain), its volume and deformation gradient follow, and its deviatoric strain is kept.
template <int D>
void MpmSolver<D>::smooth_dilatation() {
    auto& p = m_.particles;
    const int normals = D == 3 || m_.axisymmetric ? 3 : 2;
    scatter(2 * m_.grid.fields, [&](long i, double* buf) {
        const double* de = &p.dstrain[6 * i];
        const double m_dv = p.mass[i] * (de[0] + de[1] + de[2]);
        const Stencil<D>& s = stencil_[i];
        for (int k = 0; k < s.count; ++k) {
            double* b = buf + 2 * s.e[k].node;
            b[0] += s.e[k].N * m_dv;
            b[1] += s.e[k].N * p.mass[i];
        }
    }, dilatation_);
    const long n = static_cast<long>(p.size());
    const double tiny = empty_node_mass();
#pragma omp parallel for schedule(static) if (n > kParallelPoints)
    for (long i = 0; i < n; ++i) {
        const Stencil<D>& s = stencil_[i];
        double sum = 0.0, weight = 0.0;
        for (int k = 0; k < s.count; ++k) {
            const double* b = &dilatation_[2 * s.e[k].node];
            if (b[1] <= tiny) continue;
            sum += s.e[k].N * b[0] / b[1];
            weight += s.e[k].N;
        }
        if (!(weight > 0.0)) continue;
        double* de = &p.dstrain[6 * i];
        const double own = de[0] + de[1] + de[2], smoothed = sum / weight;
        const double shift = (smoothed - own) / normals;
        for (int c = 0; c < normals; ++c) {
            de[c] += shift;
            p.strain[6 * i + c] += shift;
        }
        p.volume[i] *= (1.0 + smoothed) / (1.0 + own);
        // The in-plane stretch of the deformation gradient by the same normal shift.
        double* F = &p.F[D * D * i];
        for (int k = 0; k < D * D; ++k) F[k] *= 1.0 + shift;
    }
}

template <int D>
void MpmSolver<D>::step(double dt) {
    activate_grid();
    particles_to_grid();
    update_grid(dt);
    update_points_and_remap(dt);
    update_stress(dt);
    time_ += dt;
    ++steps_;
}

template <int D>
MpmMemory MpmSolver<D>::memory() const {
    const auto& g = m_.grid;
    MpmMemory mem;
    mem.points = m_.particles.size();
    mem.stored_nodes = static_cast<std::size_t>(g.stored_nodes());
    mem.grid_nodes = static_cast<std::size_t>(g.num_nodes());
    mem.bytes_per_point = m_.particles.bytes_per_point() + sizeof(Stencil<D>);
    // external_ and residual_ (D per field), and the scatter's result and chunk buffers as
    // allocated (before the first step: one chunk over every block).
    std::size_t scatter = scratch_.capacity();
    for (const auto& b : thread_buffer_) scatter += b.capacity();
    const std::size_t nodes = std::max<std::size_t>(1, mem.stored_nodes);
    if (scatter == 0) scatter = 2 * nodes * g.fields * (1 + 2 * D);
    mem.bytes_per_stored_node = g.bytes_per_stored_node() + 2 * D * g.fields * sizeof(double) +
                                (scatter * sizeof(double) + nodes - 1) / nodes;
    return mem;
}

// The pore water of saturated points moves with the skeleton (drained, undrained) or at
// its own velocity w (coupled); both count.
template <int D>
double MpmSolver<D>::kinetic_energy() const {
    const auto& p = m_.particles;
    double e = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Drainage dr = drainage_[p.material[i]].drainage;
        const double water = dr == Drainage::Dry ? 0.0 : p.porosity[i] * m_.water.density * p.volume[i];
        const double with_skeleton = dr == Drainage::Coupled ? p.mass[i] : p.mass[i] + water;
        for (int d = 0; d < D; ++d) {
            e += 0.5 * with_skeleton * p.v[D * i + d] * p.v[D * i + d];
            if (dr == Drainage::Coupled) e += 0.5 * water * p.w[D * i + d] * p.w[D * i + d];
        }
    }
    return e;
}

template <int D>
std::array<double, D> MpmSolver<D>::momentum() const {
    std::array<double, D> q{};
    const auto& p = m_.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Drainage dr = drainage_[p.material[i]].drainage;
        const double water = dr == Drainage::Dry ? 0.0 : p.porosity[i] * m_.water.density * p.volume[i];
        const double with_skeleton = dr == Drainage::Coupled ? p.mass[i] : p.mass[i] + water;
        for (int d = 0; d < D; ++d) {
            q[d] += with_skeleton * p.v[D * i + d];
            if (dr == Drainage::Coupled) q[d] += water * p.w[D * i + d];
        }
    }
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
