#include "mpm/implicit/consolidation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mpm/points/deformation.hpp"

namespace pilempm::mpm {

namespace {

// The linear strain of node k's displacement at a point, Voigt with engineering shear:
// B (6 x D), column d = the strain of a unit u_d. In axisymmetry eps_zz is the hoop strain.
template <int D>
void strain_matrix(const Stencil<D>& s, int k, bool axisymmetric, double B[6][D]) {
    for (int r = 0; r < 6; ++r)
        for (int d = 0; d < D; ++d) B[r][d] = 0.0;
    const double* g = s.e[k].dN;
    B[0][0] = g[0];
    B[1][1] = g[1];
    B[3][0] = g[1];
    B[3][1] = g[0];
    if constexpr (D == 3) {
        B[2][2] = g[2];
        B[4][1] = g[2];
        B[4][2] = g[1];
        B[5][0] = g[2];
        B[5][2] = g[0];
    } else {
        if (axisymmetric) B[2][0] = s.hoop[k];
    }
}

}  // namespace

template <int D>
ConsolidationSolver<D>::ConsolidationSolver(MpmModel<D>& model, core::SolverOptions options, int direct_below)
    : m_(model), activator_(model), options_(options), direct_below_(direct_below) {
    points_of_material_.assign(m_.materials.size(), {});
    for (std::size_t i = 0; i < m_.particles.size(); ++i) points_of_material_[m_.particles.material[i]].push_back(static_cast<int>(i));
    for (const auto& mat : m_.materials) void_ratio_state_.push_back(void_ratio_state(*mat));
    if (m_.drainage.size() != m_.materials.size())
        throw std::invalid_argument("consolidation needs the drainage of every material");
}

template <int D>
ConsolidationStepReport ConsolidationSolver<D>::step(double dt) {
    auto& p = m_.particles;
    auto& g = m_.grid;
    const long n_points = static_cast<long>(p.size());
    // The blocks the points reach, and their stencils (the same shape functions as the
    // explicit steps).
    activator_.activate_grid();
    stencil_.resize(p.size());
    for (long i = 0; i < n_points; ++i) {
        double half[D * D];
        half_domain_edges<D>(p, i, m_.shape, half);
        evaluate_shape<D>(g, m_.shape, m_.axisymmetric, &p.x[D * i], half, stencil_[i], p.field[i]);
        if constexpr (D == 2)
            if (!m_.field_cuts.empty()) apply_field_cuts(g, m_.field_cuts, &p.x[D * i], half, stencil_[i]);
    }
    // Unknowns: D displacements per node any point reaches, one pressure per node a coupled
    // point reaches (the others: dp = 0).
    const int fields = g.fields, stored = g.stored_nodes();
    std::vector<int> node_index(stored, -1);
    std::vector<int> nodes;
    for (long i = 0; i < n_points; ++i)
        for (int k = 0; k < stencil_[i].count; ++k) {
            const int node = stencil_[i].e[k].node / fields;
            if (node_index[node] < 0) {
                node_index[node] = static_cast<int>(nodes.size());
                nodes.push_back(node);
            }
        }
    // Nodes in the grid's global order (x fastest): neighbours are numbered close together,
    // so the matrix stays banded (about a row of nodes wide) for the factorisation.
    std::vector<long> global(nodes.size());
    for (std::size_t k = 0; k < nodes.size(); ++k) global[k] = g.node(g.stored_ijk(nodes[k]));
    std::vector<int> order(nodes.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return global[a] < global[b]; });
    {
        std::vector<int> sorted(nodes.size());
        for (std::size_t k = 0; k < order.size(); ++k) sorted[k] = nodes[order[k]];
        nodes.swap(sorted);
        for (std::size_t k = 0; k < nodes.size(); ++k) node_index[nodes[k]] = static_cast<int>(k);
    }
    // Unknowns node by node, (u_1 .. u_D, p): each pressure beside its node's displacements,
    // which keeps the factorisation's pivots on the diagonal and its fill low.
    const int N = static_cast<int>(nodes.size()), n_dof = (D + 1) * N;
    auto u_of = [](int k, int d) { return (D + 1) * k + d; };
    auto p_of = [](int k) { return (D + 1) * k + D; };
    auto is_pressure = [](int dof) { return dof % (D + 1) == D; };
    auto u_dof = [&](int node, int d) { return u_of(node_index[node], d); };
    auto p_dof = [&](int node) { return p_of(node_index[node]); };
    // Pressure unknowns in units of a modulus, p = alpha p~, and the mass rows times alpha:
    // the four blocks are then of one size.
    double alpha = 0.0;
    for (const auto& mat : m_.materials) alpha = std::max(alpha, mat->p_wave_modulus());
    const double Kw = m_.water.bulk_modulus;

    // The triplets' buffers are the solver's, kept from step to step: some 650 entries a
    // point (hundreds of MB on a large domain) paged in afresh each step cost as much as
    // filling them.
    auto& triplets = triplets_;
    auto& flow = flow_;  // H, unscaled, to form -dt H p_n
    triplets.clear();
    flow.clear();
    std::vector<double> rhs(n_dof, 0.0), external(n_dof, 0.0), filled(N, 0.0), projected(N, 0.0), weight(N, 0.0), storage(N, 0.0);
    std::vector<unsigned char> has_water(N, 0);
    for (long i = 0; i < n_points; ++i) {
        const Stencil<D>& s = stencil_[i];
        const int mat = p.material[i];
        const MaterialDrainage& dr = m_.drainage[mat];
        const bool coupled = dr.drainage == Drainage::Coupled, undrained = dr.drainage == Drainage::Undrained;
        const double vol = p.volume[i], n = p.porosity[i];
        const double* st = p.state.data() + static_cast<std::size_t>(p.state_stride) * i;
        const double M = m_.materials[mat]->p_wave_modulus_at(&p.stress[6 * i], st);
        // The shear modulus at the same stress: a pressure-dependent model states G at its
        // reference pressure, and that G beside a low-stress M gave a negative bulk modulus
        // (soil near the surface pushed through itself in the first step of a pause).
        const double G = m_.materials[mat]->shear_modulus() * M / m_.materials[mat]->p_wave_modulus();
        double lambda = M - 2.0 * G;
        if (undrained) lambda += Kw / n;  // its water cannot leave: the undrained bulk modulus
        const double pe = coupled || undrained ? p.pore_pressure[i] : 0.0;
        const double water_mass = dr.saturated() ? n * m_.water.density * vol : 0.0;
        const double buoyancy = dr.saturated() && m_.water.submerged(p.x[D * i + D - 1]) ? m_.water.density * vol : 0.0;
        double sigma[6];
        for (int r = 0; r < 6; ++r) sigma[r] = p.stress[6 * i + r] - (r < 3 ? pe : 0.0);
        double body[D];
        for (int d = 0; d < D; ++d) body[d] = (p.mass[i] + water_mass - buoyancy) * m_.gravity[d] + p.external_force[D * i + d];
        double B[Stencil<D>::kMax][6][D];
        for (int a = 0; a < s.count; ++a) strain_matrix<D>(s, a, m_.axisymmetric, B[a]);
        for (int a = 0; a < s.count; ++a) {
            const int na = s.e[a].node / fields;
            const auto& Ba = B[a];
            // Out-of-balance force: f_ext - int B^T (sigma' - p I).
            for (int d = 0; d < D; ++d) {
                double f = s.e[a].N * body[d];
                external[u_dof(na, d)] += f;
                for (int r = 0; r < 6; ++r) f -= vol * Ba[r][d] * sigma[r];
                rhs[u_dof(na, d)] += f;
            }
            filled[node_index[na]] += s.e[a].N * vol;
            double div_a[D];  // m . B_a
            for (int d = 0; d < D; ++d) div_a[d] = Ba[0][d] + Ba[1][d] + Ba[2][d];
            for (int b = 0; b < s.count; ++b) {
                const int nb = s.e[b].node / fields;
                const auto& Bb = B[b];
                for (int d = 0; d < D; ++d)
                    for (int e = 0; e < D; ++e) {
                        // B_a^T D B_b with isotropic D: lambda (m.B_a)(m.B_b) + mu (2 normal + shear) terms.
                        double k = 0.0;
                        double div_b = Bb[0][e] + Bb[1][e] + Bb[2][e];
                        k += lambda * div_a[d] * div_b;
                        for (int r = 0; r < 3; ++r) k += 2.0 * G * Ba[r][d] * Bb[r][e];
                        for (int r = 3; r < 6; ++r) k += G * Ba[r][d] * Bb[r][e];
                        if (k != 0.0) triplets.push_back({u_dof(na, d), u_dof(nb, e), vol * k});
                    }
                if (!coupled) continue;
                // Coupling and flow: -Q (u rows), Q^T (p rows), dt H (p rows), all scaled by alpha.
                for (int d = 0; d < D; ++d) {
                    const double q = vol * div_a[d] * s.e[b].N;
                    if (q != 0.0) {
                        triplets.push_back({u_dof(na, d), p_dof(nb), -alpha * q});
                        triplets.push_back({p_dof(nb), u_dof(na, d), alpha * q});
                    }
                }
                double h = 0.0;
                for (int d = 0; d < D; ++d) h += s.e[a].dN[d] * s.e[b].dN[d];
                h *= vol / dr.darcy_resistance;
                if (h != 0.0) flow.push_back({p_dof(na), p_dof(nb), h});
            }
            if (coupled) {
                const int ka = node_index[na];
                has_water[ka] = 1;
                storage[ka] += s.e[a].N * vol * n / Kw;
                projected[ka] += s.e[a].N * vol * pe;
                weight[ka] += s.e[a].N * vol;
            }
        }
    }
    // Surface loads at the loaded faces (linear hats, as in the explicit steps).
    Stencil<D> at_face;
    for (const auto& load : m_.surface_loads) {
        double x[D];
        for (int d = 0; d < D; ++d) {
            x[d] = p.x[D * load.point + d];
            for (int e = 0; e < D; ++e) x[d] += p.F[D * D * load.point + D * d + e] * load.offset[e];
        }
        if (!g.inside(x)) continue;
        evaluate_shape<D>(g, ShapeKind::Linear, false, x, nullptr, at_face, p.field[load.point]);
        for (int k = 0; k < at_face.count; ++k) {
            const int node = at_face.e[k].node / fields;
            if (node_index[node] < 0) continue;
            for (int d = 0; d < D; ++d) {
                rhs[u_dof(node, d)] += at_face.e[k].N * load.force[d];
                external[u_dof(node, d)] += at_face.e[k].N * load.force[d];
            }
        }
    }
    // Nodal pressures of the last state (projected from the points) and the flow they drive.
    std::vector<double> p_node(N, 0.0);
    for (int k = 0; k < N; ++k)
        if (weight[k] > 0.0) p_node[k] = projected[k] / weight[k];
    for (const auto& t : flow) {
        triplets.push_back({t.row, t.col, alpha * alpha * dt * t.value});
        rhs[t.row] -= alpha * dt * t.value * p_node[t.col / (D + 1)];
    }
    for (int k = 0; k < N; ++k)
        if (has_water[k]) triplets.push_back({p_of(k), p_of(k), alpha * alpha * storage[k]});
    // Prescribed unknowns: supports (du = v dt), drained faces and the soil's free surface
    // (p = 0), pressures where no coupled point reaches (dp = 0).
    std::vector<double> fixed_value(n_dof, 0.0);
    std::vector<unsigned char> fixed(n_dof, 0);
    for (int k = 0; k < N; ++k) {
        const int node = nodes[k];
        const int ci = g.condition_at[node];
        const NodeCondition* cond = ci >= 0 ? &g.conditions[ci] : nullptr;
        if (cond)
            for (int d = 0; d < D; ++d)
                // Walls hold the normal; an absorbing boundary's far field is at rest in a pause.
                if (cond->fixed[d] || (cond->wall >= 0 && cond->wall / 2 == d) || cond->dashpot[d] > 0.0) {
                    fixed[u_of(k, d)] = 1;
                    fixed_value[u_of(k, d)] = cond->fixed[d] ? cond->prescribed[d] * dt : 0.0;
                }
        // The node's volume inside the grid, and how much of it the soil fills: a node at the
        // soil's free surface has about half of it filled.
        const auto ijk = g.stored_ijk(node);
        double tributary = 1.0;
        for (int d = 0; d < D; ++d) tributary *= g.tributary(d, ijk[d]);
        if (m_.axisymmetric) {
            const double r = g.coordinate(0, ijk[0]);
            tributary *= ijk[0] == 0 ? 0.25 * g.width(0, 0) : r;
        }
        // A node the soil barely reaches (a point's domain just over a cell face) would give a
        // row of almost no stiffness, which the factorisation pivots away from at great cost:
        // it is held (its displacement moves the points by less than this share).
        if (filled[k] < 1e-3 * tributary)
            for (int d = 0; d < D; ++d) fixed[u_of(k, d)] = 1, fixed_value[u_of(k, d)] = 0.0;
        if (!has_water[k]) {
            fixed[p_of(k)] = 1;
            continue;
        }
        const bool surface = filled[k] < 0.75 * tributary;
        if (surface || (cond && cond->drained)) {
            fixed[p_of(k)] = 1;
            fixed_value[p_of(k)] = -p_node[k] / alpha;  // p = 0 after the step
        }
    }
    // The state's out-of-balance force over the external force, on the free displacements.
    double unbalanced = 0.0, applied = 0.0;
    for (int k = 0; k < n_dof; ++k)
        if (!is_pressure(k) && !fixed[k]) unbalanced += rhs[k] * rhs[k], applied += external[k] * external[k];
    const double unbalanced_ratio = applied > 0.0 ? std::sqrt(unbalanced / applied) : 0.0;
    bool supported = false;
    for (int k = 0; k < n_dof; ++k) supported = supported || (!is_pressure(k) && fixed[k]);
    if (!supported)
        throw std::runtime_error("consolidation needs the soil supported: no grid node its points reach has a "
                                 "prescribed displacement (add fixed or roller boundaries)");
    // Eliminate the prescribed columns into the right-hand side, then the rows (the kept
    // triplets moved to the front, in order).
    std::size_t kept = 0;
    for (const auto& t : triplets) {
        if (fixed[t.row]) continue;
        if (fixed[t.col]) {
            rhs[t.row] -= t.value * fixed_value[t.col];
            continue;
        }
        triplets[kept++] = t;
    }
    triplets.resize(kept);
    for (int k = 0; k < n_dof; ++k)
        if (fixed[k]) {
            triplets.push_back({k, k, 1.0});
            rhs[k] = fixed_value[k];
        }
    const core::SparseMatrix A(n_dof, triplets);
    std::vector<double> x(n_dof, 0.0);
    ConsolidationStepReport report;
    report.unknowns = n_dof;
    report.unbalanced_ratio = unbalanced_ratio;
    core::SolverOptions options = options_;
    if (n_dof < direct_below_) options.method = core::KrylovMethod::direct;
    report.solve = linear_.solve(A, rhs, x, options);
    if (!report.solve.converged && options.method != core::KrylovMethod::direct) {
        core::SolverOptions direct = options_;
        direct.method = core::KrylovMethod::direct;
        x.assign(n_dof, 0.0);
        report.solve = fallback_.solve(A, rhs, x, direct);
        if (!report.solve.converged)
            throw std::runtime_error("consolidation step: the linear solve did not converge (relative residual " +
                                     std::to_string(report.solve.relative_residual) + " with " + report.solve.method +
                                     "); is the soil held in every direction (fixed, roller or absorbing boundaries)?");
    }
    for (int k = 0; k < N; ++k) x[p_of(k)] *= alpha;
    // The points take the increments: strain and stress, position, pore pressure, porosity.
    for (long i = 0; i < n_points; ++i) {
        const Stencil<D>& s = stencil_[i];
        double Gd[D][D] = {}, hoop = 0.0, du[D] = {}, p_new = 0.0;
        for (int k = 0; k < s.count; ++k) {
            const int node = s.e[k].node / fields;
            const double* u = &x[u_dof(node, 0)];
            for (int a = 0; a < D; ++a) {
                du[a] += s.e[k].N * u[a];
                for (int b = 0; b < D; ++b) Gd[a][b] += u[a] * s.e[k].dN[b];
            }
            if (m_.axisymmetric) hoop += u[0] * s.hoop[k];
            p_new += s.e[k].N * (p_node[node_index[node]] + x[p_dof(node)]);
        }
        double* de = &p.dstrain[6 * i];
        de[0] = Gd[0][0];
        de[1] = Gd[1][1];
        de[3] = Gd[0][1] + Gd[1][0];
        if constexpr (D == 3) {
            de[2] = Gd[2][2];
            de[4] = Gd[1][2] + Gd[2][1];
            de[5] = Gd[2][0] + Gd[0][2];
        } else {
            de[2] = m_.axisymmetric ? hoop : 0.0;
            de[4] = de[5] = 0.0;
        }
        double Fn[D * D];
        for (int a = 0; a < D; ++a)
            for (int b = 0; b < D; ++b) {
                double v = p.F[D * D * i + D * a + b];
                for (int c = 0; c < D; ++c) v += Gd[a][c] * p.F[D * D * i + D * c + b];
                Fn[D * a + b] = v;
            }
        for (int k = 0; k < D * D; ++k) p.F[D * D * i + k] = Fn[k];
        const double before = p.volume[i];
        if (m_.axisymmetric) {
            p.volume[i] *= 1.0 + de[0] + de[1] + de[2];
        } else {
            const double J = determinant<D>(Fn);
            p.volume[i] = p.volume0[i] * J;
        }
        for (int k = 0; k < 6; ++k) p.strain[6 * i + k] += de[k];
        for (int d = 0; d < D; ++d) {
            p.x[D * i + d] += du[d];
            p.v[D * i + d] = 0.0;  // the pause ends at rest
            p.w[D * i + d] = 0.0;
        }
        for (int k = 0; k < D * D; ++k) p.C[D * D * i + k] = 0.0;
        const Drainage dr = m_.drainage[p.material[i]].drainage;
        const double n = p.porosity[i];
        // The pressure is the nodal field's at the point (as at an integration point of u-p
        // finite elements): variations finer than the grid, which no nodal flow could
        // drain, do not survive a consolidation step.
        if (dr == Drainage::Coupled) p.pore_pressure[i] = p_new;
        else if (dr == Drainage::Undrained) p.pore_pressure[i] -= Kw / n * (de[0] + de[1] + de[2]);
        if (dr != Drainage::Dry) {
            // The porosity is the point's: a model's void ratio starts the step from it.
            if (void_ratio_state_[p.material[i]] >= 0)
                p.state[static_cast<std::size_t>(p.state_stride) * i + void_ratio_state_[p.material[i]]] = n / (1.0 - n);
            p.porosity[i] = 1.0 - (1.0 - n) * before / p.volume[i];
        }
    }
    for (std::size_t mat = 0; mat < m_.materials.size(); ++mat) {
        const auto& pts = points_of_material_[mat];
        if (pts.empty()) continue;
        m_.materials[mat]->set_time(0.0, dt);
        m_.materials[mat]->update(static_cast<int>(pts.size()), pts.data(), p.dstrain.data(), p.stress.data(),
                                  p.state.data(), p.state_stride);
    }
    for (long i = 0; i < n_points; ++i) report.max_excess_pressure = std::max(report.max_excess_pressure, std::abs(p.pore_pressure[i]));
    return report;
}

template class ConsolidationSolver<2>;
template class ConsolidationSolver<3>;

}  // namespace pilempm::mpm
