// Graded grids: the zones' node coordinates, the cell lookup along a graded axis, and the
// shape functions on unequal cells (partition of unity, exact linear fields) for every
// kind, where the cells change size and at the grid's edges.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "mpm/grid/graded_axis.hpp"
#include "mpm/grid/shape_functions.hpp"

using namespace pilempm::mpm;

TEST(GradedAxis, UniformZoneHasEqualCells) {
    const auto x = graded_axis(1.0, {{3.0, 0.25}});
    ASSERT_EQ(x.size(), 9u);
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(x[i], 1.0 + 0.25 * i, 1e-12);
}

TEST(GradedAxis, GradedZoneGrowsGeometricallyFromThePreviousCell) {
    // 0.1 m cells to 1 m, then growing to 1 m cells at 10 m.
    const auto x = graded_axis(0.0, {{1.0, 0.1}, {10.0, 1.0}});
    EXPECT_DOUBLE_EQ(x.back(), 10.0);
    EXPECT_NEAR(x[10], 1.0, 1e-12);
    const double first = x[11] - x[10], last = x[x.size() - 1] - x[x.size() - 2];
    const double q = first / 0.1;
    EXPECT_GT(q, 1.0);
    EXPECT_LE(q, kMaxGradingRatio);
    for (std::size_t i = 11; i + 1 < x.size(); ++i)  // one ratio throughout
        EXPECT_NEAR((x[i + 1] - x[i]) / (x[i] - x[i - 1]), q, 1e-9);
    EXPECT_NEAR(last, 1.0, 0.1);  // the zone's end cell, to the rounding of the count
}

TEST(GradedAxis, RefiningHalvesTheCells) {
    const auto coarse = graded_axis(0.0, {{1.0, 0.1}, {10.0, 1.0}});
    const auto fine = graded_axis(0.0, {{1.0, 0.1}, {10.0, 1.0}}, 2.0);
    EXPECT_NEAR(static_cast<double>(fine.size() - 1 - 20), 2.0 * (coarse.size() - 1 - 10), 1.0);
    EXPECT_NEAR(fine[20], 1.0, 1e-12);
}

TEST(GradedAxis, BadZonesAreRejectedWithTheZoneNamed) {
    try {
        graded_axis(0.0, {{1.0, 0.1}, {0.5, 0.1}});
        FAIL() << "a zone running backwards was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("zone 2"), std::string::npos) << e.what();
    }
    EXPECT_THROW(graded_axis(0.0, {{1.0, 0.01}, {1.2, 1.0}}), std::invalid_argument);  // too steep
    EXPECT_THROW(graded_axis(0.0, {{1.0, 2.0}}), std::invalid_argument);               // cell longer than zone
    EXPECT_THROW(graded_axis(0.0, {}), std::invalid_argument);
}

namespace {

// 2D grid: x graded from 0.05 m cells over 0.5 m to 0.4 m cells at 4 m; y uniform 0.2 m.
Grid<2> graded_grid() {
    Grid<2> g;
    g.origin = {0.0, 0.0};
    g.spacing = {0.0, 0.2};
    g.cells = {0, 16};
    g.set_lines(0, graded_axis(0.0, {{0.5, 0.05}, {4.0, 0.4}}));
    g.allocate();
    g.activate_all();
    return g;
}

}  // namespace

TEST(GradedGrid, CellLookupFindsTheCellHoldingEachPoint) {
    const Grid<2> g = graded_grid();
    EXPECT_TRUE(g.graded(0));
    EXPECT_FALSE(g.graded(1));
    EXPECT_NEAR(g.spacing[0], 0.05, 1e-12);  // the smallest cell
    EXPECT_NEAR(g.top(0), 4.0, 1e-12);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 4.0);
    for (int k = 0; k < 2000; ++k) {
        const double x = u(rng);
        const int c = g.cell_of(0, x);
        ASSERT_LE(g.coordinate(0, c), x);
        ASSERT_LT(x, g.coordinate(0, c + 1));
    }
    for (int i = 0; i <= g.cells[0]; ++i) EXPECT_EQ(g.cell_of(0, g.coordinate(0, i)), std::min(i, g.cells[0] - 1));
    double sum = 0.0;
    for (int i = 0; i <= g.cells[0]; ++i) sum += g.tributary(0, i);
    EXPECT_NEAR(sum, 4.0, 1e-12);
}

namespace {

// sum N = 1, sum dN = 0, sum dN_d x_ie = delta_de; plane: sum N x_i = x (a symmetric domain's
// centroid); axisymmetric: sum hoop r_i = 1.
void check_on_graded(ShapeKind kind, bool axisymmetric, const double* x, const double* half) {
    const Grid<2> g = graded_grid();
    Stencil<2> s;
    evaluate_shape<2>(g, kind, axisymmetric, x, half, s);
    double sumN = 0.0, hoop_r = 0.0, Nx[2] = {}, dN[2] = {}, grad[2][2] = {};
    for (int k = 0; k < s.count; ++k) {
        const auto c = g.stored_ijk(s.e[k].node);
        sumN += s.e[k].N;
        for (int d = 0; d < 2; ++d) {
            Nx[d] += s.e[k].N * g.coordinate(d, c[d]);
            dN[d] += s.e[k].dN[d];
            for (int e = 0; e < 2; ++e) grad[d][e] += s.e[k].dN[d] * g.coordinate(e, c[e]);
        }
        if (axisymmetric) hoop_r += s.hoop[k] * g.coordinate(0, c[0]);
    }
    EXPECT_NEAR(sumN, 1.0, 1e-12);
    for (int d = 0; d < 2; ++d) {
        EXPECT_NEAR(dN[d], 0.0, 1e-9);
        if (!axisymmetric) {
            EXPECT_NEAR(Nx[d], x[d], 1e-12) << "axis " << d;
        }
        for (int e = 0; e < 2; ++e) {
            EXPECT_NEAR(grad[d][e], d == e ? 1.0 : 0.0, 1e-9) << d << e;
        }
    }
    if (axisymmetric) {
        EXPECT_NEAR(hoop_r, 1.0, 1e-12);
    }
}

}  // namespace

TEST(GradedGrid, ShapeFunctionsAreConsistentWhereCellsChangeSize) {
    const Grid<2> g = graded_grid();
    // Points straddling the end of the fine zone, inside the graded one, and at the r = 0
    // axis and the far edge.
    const double xs[][2] = {{0.49, 1.01}, {0.52, 1.5}, {1.7, 0.33}, {0.01, 0.1}, {3.97, 3.15}};
    for (const auto& x : xs) {
        const int c = g.cell_of(0, x[0]);
        const double w = g.width(0, c);
        const double half[4] = {0.25 * w, 0.0, 0.0, 0.05};
        const double sheared[4] = {0.24 * w, 0.01, -0.2 * w, 0.045};
        SCOPED_TRACE("x = " + std::to_string(x[0]));
        check_on_graded(ShapeKind::Linear, false, x, half);
        check_on_graded(ShapeKind::GIMP, false, x, half);
        check_on_graded(ShapeKind::CPDI, false, x, sheared);
        check_on_graded(ShapeKind::GIMP, true, x, half);
        check_on_graded(ShapeKind::CPDI, true, x, sheared);
    }
}
