// Shape functions seen by a material point: partition of unity and exact gradients of
// linear fields, for every kind, in plane, axisymmetric and 3D form.
#include <gtest/gtest.h>

#include <cmath>

#include "mpm/grid/shape_functions.hpp"

using namespace pilempm::mpm;

namespace {

template <int D>
Grid<D> grid() {
    Grid<D> g;
    for (int d = 0; d < D; ++d) {
        g.origin[d] = 0.0;
        g.spacing[d] = d == 0 ? 0.5 : 0.4;
        g.cells[d] = 8;
    }
    g.allocate();
    g.activate_all();
    return g;
}

// sum N = 1, sum dN = 0, sum N x_i = x-ish, sum dN_d x_ie = delta_de, and in axisymmetry
// sum hoop r_i = 1 (a uniform radial stretch is seen as u_r / r = 1).
template <int D>
void check_consistency(ShapeKind kind, bool axisymmetric, const double* x, const double* half) {
    const Grid<D> g = grid<D>();
    Stencil<D> s;
    evaluate_shape<D>(g, kind, axisymmetric, x, half, s);
    double sumN = 0.0, sum_hoop_r = 0.0;
    double sum_dN[D] = {}, grad_x[D][D] = {};
    for (int k = 0; k < s.count; ++k) {
        const auto c = g.stored_ijk(s.e[k].node);
        sumN += s.e[k].N;
        for (int d = 0; d < D; ++d) {
            sum_dN[d] += s.e[k].dN[d];
            for (int e = 0; e < D; ++e) grad_x[d][e] += s.e[k].dN[d] * g.coordinate(e, c[e]);
        }
        sum_hoop_r += s.hoop[k] * g.coordinate(0, c[0]);
    }
    EXPECT_NEAR(sumN, 1.0, 1e-12);
    for (int d = 0; d < D; ++d) {
        EXPECT_NEAR(sum_dN[d], 0.0, 1e-10);
        for (int e = 0; e < D; ++e) {
            EXPECT_NEAR(grad_x[d][e], d == e ? 1.0 : 0.0, 1e-10);
        }
    }
    if (axisymmetric) {
        EXPECT_NEAR(sum_hoop_r, 1.0, 1e-12);
    }
}

}  // namespace

TEST(MpmShapeFunctions, PlaneStrainAllKinds) {
    const double x[2] = {1.37, 1.51};
    const double half[4] = {0.125, 0.0, 0.0, 0.1};
    const double sheared[4] = {0.12, 0.03, -0.02, 0.09};
    check_consistency<2>(ShapeKind::Linear, false, x, half);
    check_consistency<2>(ShapeKind::GIMP, false, x, half);
    check_consistency<2>(ShapeKind::CPDI, false, x, sheared);
}

TEST(MpmShapeFunctions, DomainsReachingPastTheGridEdgeStayConsistent) {
    // Material crossing an absorbing boundary: the domains reach past the grid's edges
    // (x_min and y_max here; the grid is 4 m x 3.2 m).
    const double corner[2] = {0.05, 3.15};
    const double half[4] = {0.125, 0.0, 0.0, 0.1};
    const double sheared[4] = {0.12, 0.03, -0.02, 0.09};
    check_consistency<2>(ShapeKind::Linear, false, corner, half);
    check_consistency<2>(ShapeKind::GIMP, false, corner, half);
    check_consistency<2>(ShapeKind::CPDI, false, corner, sheared);
    const double outer[2] = {3.95, 0.05};  // past r = 4 m and z = 0 in axisymmetry
    check_consistency<2>(ShapeKind::GIMP, true, outer, half);
    const double corner3[3] = {3.95, 0.05, 3.15};
    const double half3[9] = {0.125, 0, 0, 0, 0.1, 0, 0, 0, 0.1};
    check_consistency<3>(ShapeKind::GIMP, false, corner3, half3);
}

TEST(MpmShapeFunctions, AxisymmetricAllKinds) {
    const double near_axis[2] = {0.2, 1.0};  // the domain reaches within 0.075 m of the axis
    const double x[2] = {2.3, 1.23};
    const double half[4] = {0.125, 0.0, 0.0, 0.1};
    const double sheared[4] = {0.12, 0.03, -0.02, 0.09};
    for (const double* p : {near_axis, x}) {
        check_consistency<2>(ShapeKind::Linear, true, p, half);
        check_consistency<2>(ShapeKind::GIMP, true, p, half);
        check_consistency<2>(ShapeKind::CPDI, true, p, sheared);
    }
}

TEST(MpmShapeFunctions, ThreeDimensionalAllKinds) {
    const double x[3] = {1.37, 1.51, 0.93};
    const double half[9] = {0.125, 0, 0, 0, 0.1, 0, 0, 0, 0.1};
    const double sheared[9] = {0.12, 0.02, 0.0, -0.01, 0.09, 0.01, 0.0, 0.02, 0.1};
    check_consistency<3>(ShapeKind::Linear, false, x, half);
    check_consistency<3>(ShapeKind::GIMP, false, x, half);
    check_consistency<3>(ShapeKind::CPDI, false, x, sheared);
}

TEST(MpmShapeFunctions, GimpIsSmoothAcrossACellFace) {
    // The GIMP weight of a node is continuous as the point crosses a cell boundary (the
    // source of the cell-crossing noise that linear functions show in their gradients).
    const Grid<2> g = grid<2>();
    const double half[4] = {0.125, 0, 0, 0.1};
    Stencil<2> a, b;
    const double xa[2] = {1.5 - 1e-9, 1.2}, xb[2] = {1.5 + 1e-9, 1.2};
    evaluate_shape<2>(g, ShapeKind::GIMP, false, xa, half, a);
    evaluate_shape<2>(g, ShapeKind::GIMP, false, xb, half, b);
    auto grad_x_of = [](const Stencil<2>& s, int node) {
        for (int k = 0; k < s.count; ++k)
            if (s.e[k].node == node) return s.e[k].dN[0];
        return 0.0;
    };
    // Every node of the row, the neighbours' gradients (about 1/h) among them.
    for (int i = 1; i <= 5; ++i) {
        const int node = g.index({i, 3});
        EXPECT_NEAR(grad_x_of(a, node), grad_x_of(b, node), 1e-6) << "node " << i;
    }
    EXPECT_GT(std::abs(grad_x_of(a, g.index({2, 3}))), 0.5);
}

TEST(MpmShapeFunctions, AxisymmetricApicCentreIsTheWeightsCentroid) {
    // APIC carries v + C (x_node - s.x) to the nodes: the momentum it adds, m C sum_k N_k
    // (x_k - s.x), must be nil. The r-weighted axisymmetric weights have their centroid
    // outside the point (by l^2 / (3 r) along r for uGIMP), so s.x is that centroid.
    const Grid<2> g = grid<2>();
    const double half[4] = {0.125, 0.0, 0.0, 0.1};
    const double sheared[4] = {0.12, 0.03, -0.02, 0.09};
    for (const double r : {0.125, 0.2, 0.6, 2.3}) {
        const double x[2] = {r, 1.23};
        for (ShapeKind kind : {ShapeKind::Linear, ShapeKind::GIMP, ShapeKind::CPDI}) {
            Stencil<2> s;
            evaluate_shape<2>(g, kind, true, x, kind == ShapeKind::CPDI ? sheared : half, s);
            double moment[2] = {0.0, 0.0};
            for (int k = 0; k < s.count; ++k) {
                const auto c = g.stored_ijk(s.e[k].node);
                for (int d = 0; d < 2; ++d) moment[d] += s.e[k].N * (g.coordinate(d, c[d]) - s.x[d]);
            }
            EXPECT_NEAR(moment[0], 0.0, 1e-12);
            EXPECT_NEAR(moment[1], 0.0, 1e-12);
            if (kind == ShapeKind::GIMP) {
                EXPECT_NEAR(s.x[0], r + 0.125 * 0.125 / (3.0 * r), 1e-12);  // uGIMP: int s^2 ds / int s ds
                EXPECT_NEAR(s.x[1], x[1], 1e-12);
            }
            if (kind == ShapeKind::Linear) {
                EXPECT_NEAR(s.x[0], r, 1e-12);  // unweighted: the point
            }
        }
    }
}
