#pragma once
// Grid shape functions seen by a material point: linear (point particle), uGIMP (the
// hat functions averaged over the undeformed particle domain, Bardenhagen & Kober 2004)
// and CPDI1 (the multilinear interpolation of the hats at the corners of the deformed
// parallelogram/parallelepiped domain, Sadeghirad et al. 2011). All three are built one
// way: S_i = (1/W) int chi N_i w dV and grad S_i = (1/W) int chi grad N_i w dV, with
// w = r in axisymmetry (Nairn & Guilkey 2013) and w = 1 otherwise, integrated exactly.
// The hoop weight is (1/W) int chi N_i dV, so that u_r/r at the point is sum v_ri hoop_i.
#include "mpm/grid/grid.hpp"
#include "mpm/points/particles.hpp"

namespace pilempm::mpm {

enum class ShapeKind { Linear, GIMP, CPDI };

template <int D>
struct Stencil {
    static constexpr int kMax = D == 2 ? 16 : 64;
    // One entry per node, its fields together: the passes over the points read the first
    // `count` entries as one contiguous block.
    struct Entry {
        int node;  // the grid entry: stored node x the grid's fields + the point's field
        double N;
        double dN[D];
    };
    int count = 0;
    Entry e[kMax];
    double hoop[kMax];  // axisymmetric only (not written otherwise: nothing reads it)
    double x[D];        // centre of the affine (APIC) term: the point, or in axisymmetry the weights' centroid
    void clear() { count = 0; }
    int slot(int n);    // the entry for node n, created zeroed if new (searches: CPDI)
    int append(int n);  // a new entry for a node known not to be there yet (linear, GIMP)
};

// x: point position; domain: D half-edge vectors of the particle domain (row k = vector k),
// current for CPDI, undeformed for GIMP, unused for linear; field: the velocity field the
// point moves with. The nodes must be in active blocks.
template <int D>
void evaluate_shape(const Grid<D>& grid, ShapeKind kind, bool axisymmetric, const double* x,
                    const double* half_domain, Stencil<D>& s, int field = 0);

// The D half-edge vectors of point i's domain (row k = vector k): undeformed for uGIMP (and
// linear, which does not use them), F-deformed for CPDI.
template <int D>
inline void half_domain_edges(const Particles<D>& p, long i, ShapeKind kind, double* half) {
    for (int k = 0; k < D; ++k)
        for (int d = 0; d < D; ++d) {
            double v = 0.0;
            if (kind == ShapeKind::CPDI) {
                for (int e = 0; e < D; ++e) v += p.F[D * D * i + D * d + e] * p.domain0[D * D * i + D * k + e];
            } else {
                v = p.domain0[D * D * i + D * k + d];
            }
            half[D * k + d] = 0.5 * v;
        }
}

}  // namespace pilempm::mpm
