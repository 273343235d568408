#include "mpm/grid/shape_functions.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pilempm::mpm {

template <int D>
int Stencil<D>::slot(int n) {
    for (int k = 0; k < count; ++k)
        if (e[k].node == n) return k;
    return append(n);
}

template <int D>
int Stencil<D>::append(int n) {
    if (count >= kMax) throw std::logic_error("shape function stencil overflow");
    e[count].node = n;
    e[count].N = 0.0;
    hoop[count] = 0.0;
    for (int d = 0; d < D; ++d) e[count].dN[d] = 0.0;
    return count++;
}

namespace {

// 1D hat of node at xi reaching hl to its left and hr to its right (the neighbouring
// cells; equal on a uniform axis), and its slope.
inline double hat(double s, double xi, double hl, double hr) {
    const double d = s - xi;
    return std::max(0.0, d >= 0.0 ? 1.0 - d / hr : 1.0 + d / hl);
}
inline double hat_slope(double s, double xi, double hl, double hr) {
    const double d = s - xi;
    if (d >= hr || -d >= hl) return 0.0;
    return d > 0.0 ? -1.0 / hr : 1.0 / hl;
}

struct Hat1D {
    double value;  // int N w ds
    double slope;  // int N' w ds
    double plain;  // int N ds
};

// Exact integrals of the hat over [a, b] with weight w(s) = s (weighted) or 1, piece by
// piece between the hat's kinks, where the hat is linear: the trapezoid for int N ds, its
// two-point product rule for int N s ds, and the piece's constant slope times int w ds.
// Closed forms, a third of the hat evaluations of Gauss points (profile: the graded and
// axisymmetric weights spent 16 % of a step here).
Hat1D integrate_hat(double xi, double hl, double hr, double a, double b, bool weighted) {
    const double kinks[3] = {xi - hl, xi, xi + hr};
    double cuts[5] = {a, 0, 0, 0, b};
    int n = 1;
    for (double k : kinks)
        if (k > a && k < b) cuts[n++] = k;
    cuts[n] = b;
    Hat1D r{0.0, 0.0, 0.0};
    double n_lo = hat(cuts[0], xi, hl, hr);
    for (int p = 0; p < n; ++p) {
        const double lo = cuts[p], hi = cuts[p + 1], length = hi - lo;
        const double n_hi = hat(hi, xi, hl, hr);
        const double slope = hat_slope(0.5 * (lo + hi), xi, hl, hr);
        const double plain = 0.5 * length * (n_lo + n_hi);
        r.plain += plain;
        if (weighted) {
            r.value += length / 6.0 * (n_lo * (2.0 * lo + hi) + n_hi * (lo + 2.0 * hi));
            r.slope += slope * 0.5 * length * (lo + hi);
        } else {
            r.value += plain;
            r.slope += slope * length;
        }
        n_lo = n_hi;
    }
    return r;
}

// A domain that reaches past an open grid edge (material moving through an absorbing
// boundary) must not lose the weight of the node beyond it: S and grad S would no longer
// sum to 1 and 0, and the point's stress would push on the edge like a spring (a
// reflector that grows with displacement / cell size). That node takes the edge cell's
// field extrapolated, v_beyond = 2 v_edge - v_next, as linear and CPDI shapes extrapolate
// it. Past a closed edge (fixed, roller, frictional) its weight is dropped: it is at rest.
// Adds the share (s, g; G may be null) of the node beyond edge `side` to a stencil whose
// first node is lo and last is hi.
inline void extrapolate_past_edge(int side, int lo, int hi, double s, double g, double* S, double* G) {
    const int edge = side == 0 ? 0 : hi - lo, next = side == 0 ? 1 : hi - lo - 1;
    S[edge] += 2.0 * s;
    S[next] -= s;
    if (G) {
        G[edge] += 2.0 * g;
        G[next] -= g;
    }
}

// uGIMP weight and slope of the node xi cells from the point (cell units, half-length lam).
inline void ugimp_node(double xi, double lam, double inv_lam, double inv_h, double& S, double& G) {
    const double a = std::abs(xi), sgn = xi >= 0.0 ? 1.0 : -1.0;
    if (a < lam) {
        S = 1.0 - 0.5 * (xi * xi + lam * lam) * inv_lam;
        G = -xi * inv_lam * inv_h;
    } else if (a <= 1.0 - lam) {
        S = 1.0 - a;
        G = -sgn * inv_h;
    } else if (a < 1.0 + lam) {
        const double d = 1.0 + lam - a;
        S = 0.25 * d * d * inv_lam;
        G = -0.5 * sgn * d * inv_lam * inv_h;
    } else {
        S = G = 0.0;
    }
}

// uGIMP along one axis for a half-length l <= h/2 without a radial weight: the nodes
// first.. that the domain [x - l, x + l] reaches (2 or 3; 4 only on a knife edge), with
// the closed-form weight and slope of Bardenhagen & Kober (2004), the values
// integrate_hat gives, written in cell units so that no division is left in the loop.
// open: whether the low and high edges may be crossed.
inline int ugimp_axis(double x, double l, double origin, double h, int cells, const bool* open, int& first, double* S,
                      double* G) {
    const double inv_h = 1.0 / h, u = (x - origin) * inv_h, lam = l * inv_h;
    const double inv_lam = 1.0 / lam;
    const int lo_all = static_cast<int>(std::floor(u - lam)), hi_all = static_cast<int>(std::ceil(u + lam));
    const int lo = std::max(0, lo_all), hi = std::min(cells, hi_all);
    first = lo;
    for (int i = 0; i <= hi - lo; ++i) ugimp_node(u - (lo + i), lam, inv_lam, inv_h, S[i], G[i]);
    double s, g;
    if (lo_all < lo && open[0]) {
        ugimp_node(u - lo_all, lam, inv_lam, inv_h, s, g);
        extrapolate_past_edge(0, lo, hi, s, g, S, G);
    }
    if (hi_all > hi && open[1]) {
        ugimp_node(u - hi_all, lam, inv_lam, inv_h, s, g);
        extrapolate_past_edge(1, lo, hi, s, g, S, G);
    }
    return hi - lo + 1;
}

template <int D>
void linear(const Grid<D>& g, bool axisymmetric, const double* x, Stencil<D>& s) {
    std::array<int, D> base{};
    std::array<double, D> f{};
    for (int d = 0; d < D; ++d) {
        base[d] = g.cell_of(d, x[d]);
        f[d] = (x[d] - g.coordinate(d, base[d])) / g.width(d, base[d]);
    }
    for (int corner = 0; corner < (1 << D); ++corner) {
        std::array<int, D> c{};
        double w[D], dw[D];
        for (int d = 0; d < D; ++d) {
            const int bit = (corner >> d) & 1;
            c[d] = base[d] + bit;
            w[d] = bit ? f[d] : 1.0 - f[d];
            dw[d] = (bit ? 1.0 : -1.0) / g.width(d, base[d]);
        }
        const int k = s.append(g.index(c));
        double N = 1.0;
        for (int d = 0; d < D; ++d) N *= w[d];
        s.e[k].N += N;
        for (int d = 0; d < D; ++d) {
            double grad = dw[d];
            for (int e = 0; e < D; ++e)
                if (e != d) grad *= w[e];
            s.e[k].dN[d] += grad;
        }
        if (axisymmetric) s.hoop[k] += N / x[0];
    }
}

template <int D>
void gimp(const Grid<D>& g, bool axisymmetric, const double* x, const double* half_domain, Stencil<D>& s) {
    // Per axis: weights of the (up to 3) nodes the particle domain overlaps.
    int first[D], n_axis[D];
    double S[D][4], G[D][4], H[4] = {0, 0, 0, 0};
    for (int d = 0; d < D; ++d) {
        const double l = half_domain[d * D + d], h = g.spacing[d];
        const bool weighted = axisymmetric && d == 0;
        const bool open[2] = {!g.closed[2 * d], !g.closed[2 * d + 1]};
        const bool graded = g.graded(d);
        if (!weighted && !graded && l <= 0.5 * h) {
            n_axis[d] = ugimp_axis(x[d], l, g.origin[d], h, g.cells[d], open, first[d], S[d], G[d]);
            continue;
        }
        const double a = x[d] - l, b = x[d] + l;
        const double W = weighted ? 2.0 * l * x[d] : 2.0 * l;  // int w ds over the domain
        int lo_all, hi_all;
        if (graded) {
            lo_all = g.cell_beyond(d, a);
            const int c = g.cell_beyond(d, b);
            hi_all = b > g.coordinate(d, c) ? c + 1 : c;
        } else {
            lo_all = static_cast<int>(std::floor((a - g.origin[d]) / h));
            hi_all = static_cast<int>(std::ceil((b - g.origin[d]) / h));
        }
        // The hat of node i reaches its neighbouring cells (h each on a uniform axis).
        auto node_hat = [&](int i) {
            if (!graded) return integrate_hat(g.coordinate(d, i), h, h, a, b, weighted);
            const double xi = g.coordinate(d, i);
            return integrate_hat(xi, xi - g.coordinate(d, i - 1), g.coordinate(d, i + 1) - xi, a, b, weighted);
        };
        const int lo = std::max(0, lo_all), hi = std::min(g.cells[d], hi_all);
        first[d] = lo;
        n_axis[d] = hi - lo + 1;
        if (n_axis[d] > 4) throw std::logic_error("GIMP domain larger than a cell");
        for (int i = 0; i < n_axis[d]; ++i) {
            const Hat1D r = node_hat(lo + i);
            S[d][i] = r.value / W;
            G[d][i] = r.slope / W;
            if (weighted) H[i] = r.plain / W;
        }
        for (int side = 0; side < 2; ++side) {
            const int beyond = side == 0 ? lo_all : hi_all;
            if (beyond == (side == 0 ? lo : hi) || !open[side]) continue;
            const Hat1D r = node_hat(beyond);
            extrapolate_past_edge(side, lo, hi, r.value / W, r.slope / W, S[d], G[d]);
            if (weighted) extrapolate_past_edge(side, lo, hi, r.plain / W, 0.0, H, nullptr);
        }
    }
    // Tensor product of the per-axis weights, written straight into the stencil: the
    // nodes are distinct, so nothing accumulates. Entries with no weight and no gradient
    // are left out. x runs fastest. A node's stored index is its block's slot and its place
    // in the block; when the stencil lies in one block (most do) that is the first node's
    // index plus an offset, else each node looks its block up.
    constexpr int B = Grid<D>::kBlockEdge, shift = Grid<D>::kBlockShift;
    bool one_block = true;
    std::array<int, D> first_node;
    int local_stride[D];
    for (int d = 0, stride = 1; d < D; ++d, stride *= B) {
        first_node[d] = first[d];
        local_stride[d] = stride;
        one_block = one_block && (first[d] >> shift) == ((first[d] + n_axis[d] - 1) >> shift);
    }
    auto emit = [&](int node, const int* idx) {
        double N = 1.0, grad[D];
        for (int d = 0; d < D; ++d) N *= S[d][idx[d]];
        bool any = N != 0.0;
        for (int d = 0; d < D; ++d) {
            grad[d] = G[d][idx[d]];
            for (int e = 0; e < D; ++e)
                if (e != d) grad[d] *= S[e][idx[e]];
            any = any || grad[d] != 0.0;
        }
        if (!any) return;
        const int k = s.count++;
        s.e[k].node = node;
        s.e[k].N = N;
        for (int d = 0; d < D; ++d) s.e[k].dN[d] = grad[d];
        if (axisymmetric) {
            double hoop = H[idx[0]];
            for (int e = 1; e < D; ++e) hoop *= S[e][idx[e]];
            s.hoop[k] = hoop;
        }
    };
    // The nodes in order, x fastest, by nested loops (no integer division per node).
    auto walk = [&](auto&& node_of) {
        int idx[D];
        if constexpr (D == 2) {
            for (idx[1] = 0; idx[1] < n_axis[1]; ++idx[1])
                for (idx[0] = 0; idx[0] < n_axis[0]; ++idx[0]) emit(node_of(idx), idx);
        } else {
            for (idx[2] = 0; idx[2] < n_axis[2]; ++idx[2])
                for (idx[1] = 0; idx[1] < n_axis[1]; ++idx[1])
                    for (idx[0] = 0; idx[0] < n_axis[0]; ++idx[0]) emit(node_of(idx), idx);
        }
    };
    if (one_block) {
        const int corner = g.index(first_node);
        walk([&](const int* idx) {
            int offset = corner;
            for (int d = 0; d < D; ++d) offset += idx[d] * local_stride[d];
            return offset;
        });
    } else {
        walk([&](const int* idx) {
            std::array<int, D> c;
            for (int d = 0; d < D; ++d) c[d] = first[d] + idx[d];
            return g.index(c);
        });
    }
}

template <int D>
void cpdi(const Grid<D>& g, bool axisymmetric, const double* x, const double* r, Stencil<D>& s) {
    constexpr int nc = 1 << D;
    // Corner stencils of the linear hats.
    Stencil<D> corner[nc];
    double xc[nc][D];
    for (int c = 0; c < nc; ++c) {
        for (int d = 0; d < D; ++d) {
            xc[c][d] = x[d];
            for (int k = 0; k < D; ++k) xc[c][d] += (((c >> k) & 1) ? 1.0 : -1.0) * r[k * D + d];
        }
        corner[c].clear();
        linear<D>(g, false, xc[c], corner[c]);
    }
    // Affine map x(xi) = x + sum_k xi_k r_k on [-1, 1]^D; J[d][k] = r_k[d].
    double J[D][D], Jinv[D][D];
    for (int d = 0; d < D; ++d)
        for (int k = 0; k < D; ++k) J[d][k] = r[k * D + d];
    double det;
    if constexpr (D == 2) {
        det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
        Jinv[0][0] = J[1][1] / det;
        Jinv[0][1] = -J[0][1] / det;
        Jinv[1][0] = -J[1][0] / det;
        Jinv[1][1] = J[0][0] / det;
    } else {
        det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
              J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
                Jinv[i][j] = (J[i1][j1] * J[i2][j2] - J[i1][j2] * J[i2][j1]) / det;
            }
    }
    if (!(det > 0.0)) throw std::runtime_error("CPDI particle domain inverted");
    // 2^D Gauss points: exact for the multilinear interpolant times a linear weight.
    const double gp = 1.0 / std::sqrt(3.0);
    double W = 0.0;
    for (int q = 0; q < nc; ++q) {
        double xi[D];
        for (int k = 0; k < D; ++k) xi[k] = ((q >> k) & 1) ? gp : -gp;
        double xq0 = x[0];
        for (int k = 0; k < D; ++k) xq0 += xi[k] * r[k * D + 0];
        const double w = axisymmetric ? xq0 : 1.0;  // Gauss weights are 1; |J| cancels in 1/W
        W += w;
        for (int c = 0; c < nc; ++c) {
            // Multilinear corner function L_c(xi) and its parametric gradient.
            double L = 1.0, dL[D];
            for (int k = 0; k < D; ++k) {
                const double sgn = ((c >> k) & 1) ? 1.0 : -1.0;
                L *= 0.5 * (1.0 + sgn * xi[k]);
            }
            for (int k = 0; k < D; ++k) {
                double v = 0.5 * (((c >> k) & 1) ? 1.0 : -1.0);
                for (int m = 0; m < D; ++m)
                    if (m != k) v *= 0.5 * (1.0 + (((c >> m) & 1) ? 1.0 : -1.0) * xi[m]);
                dL[k] = v;
            }
            double gradL[D];  // d L / d x = J^-T dL/dxi
            for (int d = 0; d < D; ++d) {
                gradL[d] = 0.0;
                for (int k = 0; k < D; ++k) gradL[d] += Jinv[k][d] * dL[k];
            }
            for (int e = 0; e < corner[c].count; ++e) {
                const int k = s.slot(corner[c].e[e].node);
                const double Nc = corner[c].e[e].N;
                s.e[k].N += L * Nc * w;
                for (int d = 0; d < D; ++d) s.e[k].dN[d] += gradL[d] * Nc * w;
                if (axisymmetric) s.hoop[k] += L * Nc;
            }
        }
    }
    for (int k = 0; k < s.count; ++k) {
        s.e[k].N /= W;
        for (int d = 0; d < D; ++d) s.e[k].dN[d] /= W;
        s.hoop[k] /= W;
    }
}

}  // namespace

template <int D>
void evaluate_shape(const Grid<D>& grid, ShapeKind kind, bool axisymmetric, const double* x,
                    const double* half_domain, Stencil<D>& s, int field) {
    s.clear();
    for (int d = 0; d < D; ++d) s.x[d] = x[d];
    switch (kind) {
        case ShapeKind::Linear: linear<D>(grid, axisymmetric, x, s); break;
        case ShapeKind::GIMP: gimp<D>(grid, axisymmetric, x, half_domain, s); break;
        case ShapeKind::CPDI: cpdi<D>(grid, axisymmetric, x, half_domain, s); break;
    }
    // Stored nodes to grid entries: the point's own velocity field at each node.
    if (grid.fields > 1)
        for (int k = 0; k < s.count; ++k) s.e[k].node = s.e[k].node * grid.fields + field;
    // APIC carries v + C (x_node - s.x) to the nodes; it conserves momentum only when
    // sum_k N_k (x_k - s.x) = 0. With the r-weighted axisymmetric weights the weights'
    // centroid sum_k N_k x_k / sum_k N_k lies outside the point, by l^2 / (3 r) along r for a
    // uGIMP domain of half-length l: the affine term taken about the point itself then adds
    // radial momentum C (l^2 / 3r) every step, strongest at the axis. It is taken about the
    // centroid instead.
    if (axisymmetric && s.count > 0) {
        double w = 0.0, c[D] = {};
        for (int k = 0; k < s.count; ++k) {
            w += s.e[k].N;
            for (int d = 0; d < D; ++d) c[d] += s.e[k].N * grid.position[D * s.e[k].node + d];
        }
        if (w > 0.0)
            for (int d = 0; d < D; ++d) s.x[d] = c[d] / w;
    }
}

template struct Stencil<2>;
template struct Stencil<3>;
template void evaluate_shape<2>(const Grid<2>&, ShapeKind, bool, const double*, const double*, Stencil<2>&, int);
template void evaluate_shape<3>(const Grid<3>&, ShapeKind, bool, const double*, const double*, Stencil<3>&, int);

}  // namespace pilempm::mpm
