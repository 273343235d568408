#include "mpm/setup/model_setup.hpp"

#include <algorithm>
#include <cmath>

namespace pilempm::mpm {

template <int D>
int fill_region(const Grid<D>& g, Particles<D>& p, const std::function<bool(const double*)>& inside,
                int per_cell, double density, int material, bool axisymmetric) {
    int added = 0;
    const int nn = g.num_nodes();
    std::array<int, D> n_sub{};
    int sub_total = 1;
    for (int d = 0; d < D; ++d) {
        n_sub[d] = per_cell;
        sub_total *= per_cell;
    }
    for (int node = 0; node < nn; ++node) {
        const auto c = g.ijk(node);
        bool is_cell = true;  // a cell is named by its lowest node
        for (int d = 0; d < D; ++d) is_cell = is_cell && c[d] < g.cells[d];
        if (!is_cell) continue;
        for (int m = 0; m < sub_total; ++m) {
            double x[D], len[D];
            int rem = m;
            double vol = 1.0;
            for (int d = 0; d < D; ++d) {
                const int k = rem % n_sub[d];
                rem /= n_sub[d];
                len[d] = g.width(d, c[d]) / n_sub[d];
                x[d] = g.coordinate(d, c[d]) + (k + 0.5) * len[d];
                vol *= len[d];
            }
            if (!inside(x)) continue;
            if (axisymmetric) vol *= x[0];
            p.add(x, density * vol, vol, len, material);
            ++added;
        }
    }
    return added;
}

template <int D>
void apply_boundary(Grid<D>& g, int axis, int side, BoundaryKind kind, double density, double cp, double cs,
                    bool axisymmetric, double friction, double water_impedance, bool drained,
                    double far_field_distance) {
    const int nn = g.num_nodes();
    const int plane = side == 0 ? 0 : g.cells[axis];
    if (kind != BoundaryKind::Absorbing) g.closed[2 * axis + side] = true;
    for (int n = 0; n < nn; ++n) {
        const auto c = g.ijk(n);
        if (c[axis] != plane) continue;
        NodeCondition& cond = g.condition(n);
        if (kind != BoundaryKind::Absorbing) cond.drained = cond.drained || drained;
        if (kind == BoundaryKind::Fixed) {
            for (int d = 0; d < D; ++d) cond.fixed[d] = 1;
        } else if (kind == BoundaryKind::Roller) {
            cond.fixed[axis] = 1;
        } else if (kind == BoundaryKind::Frictional) {
            cond.wall = 2 * axis + side;
            cond.wall_friction = friction;
        } else {
            // Tributary face area of the node: half of each cell beside it.
            double area = 1.0;
            for (int d = 0; d < D; ++d)
                if (d != axis) area *= g.tributary(d, c[d]);
            if (axisymmetric) area *= g.coordinate(0, c[0]);
            for (int d = 0; d < D; ++d) cond.dashpot[d] += density * (d == axis ? cp : cs) * area;
            if (far_field_distance > 0.0)
                for (int d = 0; d < D; ++d)
                    cond.spring[d] += (d == axis ? 2.0 : 1.0) * density * cs * cs / far_field_distance * area;
            cond.absorbing[axis] = 1;
            cond.water_dashpot[axis] += water_impedance * area;
        }
    }
}

template <int D>
void apply_k0_stress(Particles<D>& p, double surface, double gravity, const std::function<double(double)>& density,
                     const std::function<double(double)>& k0, double surcharge) {
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double z = p.x[D * i + D - 1];
        // Integrate rho g over the depth with a fine midpoint rule (layers are piecewise constant).
        const int n = 200;
        const double dz = (surface - z) / n;
        double sv = -surcharge;
        for (int k = 0; k < n; ++k) sv -= gravity * density(z + (k + 0.5) * dz) * dz;
        const double kk = k0(z);
        double* s = &p.stress[6 * i];
        s[0] = kk * sv;
        s[1] = D == 2 ? sv : kk * sv;
        s[2] = D == 2 ? kk * sv : sv;
        s[3] = s[4] = s[5] = 0.0;
    }
}

template int fill_region<2>(const Grid<2>&, Particles<2>&, const std::function<bool(const double*)>&, int, double, int, bool);
template int fill_region<3>(const Grid<3>&, Particles<3>&, const std::function<bool(const double*)>&, int, double, int, bool);
template void apply_boundary<2>(Grid<2>&, int, int, BoundaryKind, double, double, double, bool, double, double, bool,
                                double);
template void apply_boundary<3>(Grid<3>&, int, int, BoundaryKind, double, double, double, bool, double, double, bool,
                                double);
template void apply_k0_stress<2>(Particles<2>&, double, double, const std::function<double(double)>&,
                                 const std::function<double(double)>&, double);
template void apply_k0_stress<3>(Particles<3>&, double, double, const std::function<double(double)>&,
                                 const std::function<double(double)>&, double);

}  // namespace pilempm::mpm
