// The blocked grid: only the blocks the points reach are stored, a body in a box a hundred
// times its size steps exactly as in a box that fits it, blocks follow a moving body, and
// bodies on separate velocity fields pass through each other while bodies on one collide.
#include <gtest/gtest.h>

#include <omp.h>

#include <cmath>

#include "mpm/setup/model_setup.hpp"
#include "mpm/solver/mpm_solver.hpp"

using namespace pilempm::mpm;

namespace {

// An elastic square of 10 x 10 cells at `corner` in a grid of `cells` x `cells` 0.1 m cells.
MpmModel<2> square(int cells, double corner, ShapeKind shape = ShapeKind::GIMP) {
    MpmModel<2> m;
    m.grid.origin = {0.0, 0.0};
    m.grid.spacing = {0.1, 0.1};
    m.grid.cells = {cells, cells};
    m.grid.allocate();
    m.shape = shape;
    m.flip = 1.0;
    m.materials.push_back(std::make_unique<LinearElastic>(1e6, 0.3));
    fill_region<2>(m.grid, m.particles, [corner](const double* x) {
        return x[0] > corner && x[0] < corner + 1.0 && x[1] > corner && x[1] < corner + 1.0;
    }, 2, 1000.0, 0, false);
    // A spin and a squeeze: every point moves differently.
    for (std::size_t i = 0; i < m.particles.size(); ++i) {
        const double* x = &m.particles.x[2 * i];
        m.particles.v[2 * i] = 0.2 - 0.5 * (x[1] - corner - 0.5) + 0.3 * (x[0] - corner - 0.5);
        m.particles.v[2 * i + 1] = 0.1 + 0.5 * (x[0] - corner - 0.5);
    }
    return m;
}

}  // namespace

TEST(SparseGrid, ABodyInAHugeBoxStoresOnlyItsBlocksAndStepsAsInASmallOne) {
    for (ShapeKind shape : {ShapeKind::Linear, ShapeKind::GIMP, ShapeKind::CPDI}) {
        MpmModel<2> small = square(20, 0.5, shape), huge = square(2000, 0.5, shape);
        MpmSolver<2> a(small), b(huge);
        for (int n = 0; n < 100; ++n) {
            const double dt = a.stable_time_step();
            a.step(dt);
            b.step(dt);
        }
        // 2001^2 nodes in the grid; the body and its neighbourhood fit in a few blocks.
        EXPECT_EQ(huge.grid.num_nodes(), 2001 * 2001);
        EXPECT_LE(huge.grid.stored_nodes(), 4 * Grid<2>::kBlockNodes);
        for (std::size_t i = 0; i < small.particles.x.size(); ++i) {
            ASSERT_EQ(small.particles.x[i], huge.particles.x[i]) << i;
            ASSERT_EQ(small.particles.v[i], huge.particles.v[i]) << i;
        }
        for (std::size_t i = 0; i < small.particles.stress.size(); ++i)
            ASSERT_EQ(small.particles.stress[i], huge.particles.stress[i]) << i;
    }
}

TEST(SparseGrid, BlocksFollowABodyAcrossTheGrid) {
    MpmModel<2> m = square(200, 0.5);
    for (std::size_t i = 0; i < m.particles.size(); ++i) {
        m.particles.v[2 * i] = 20.0;  // a rigid translation across many blocks
        m.particles.v[2 * i + 1] = 10.0;
    }
    const std::vector<double> x0 = m.particles.x;
    MpmSolver<2> s(m);
    double t = 0.0;
    while (t < 0.5) {
        const double dt = std::min(s.stable_time_step(), 0.5 - t);
        s.step(dt);
        t += dt;
    }
    // 10 m along x and 5 m along y: through 6 and 3 blocks of 16 nodes.
    for (std::size_t i = 0; i < m.particles.size(); ++i) {
        ASSERT_NEAR(m.particles.x[2 * i], x0[2 * i] + 10.0, 1e-9);
        ASSERT_NEAR(m.particles.x[2 * i + 1], x0[2 * i + 1] + 5.0, 1e-9);
    }
    EXPECT_LE(m.grid.stored_nodes(), 4 * Grid<2>::kBlockNodes);
    double grid_mass = 0.0;
    for (double x : m.grid.mass) grid_mass += x;
    EXPECT_NEAR(grid_mass, s.total_mass(), 1e-12 * s.total_mass());
}

namespace {

// Two elastic blocks 1 m apart closing at 2 m/s each, on one velocity field or on two.
MpmModel<2> two_blocks(bool separate_fields) {
    MpmModel<2> m;
    m.grid.origin = {0.0, 0.0};
    m.grid.spacing = {0.1, 0.1};
    m.grid.cells = {50, 20};
    m.grid.fields = separate_fields ? 2 : 1;
    m.grid.allocate();
    m.flip = 1.0;
    m.materials.push_back(std::make_unique<LinearElastic>(1e6, 0.3));
    fill_region<2>(m.grid, m.particles, [](const double* x) { return x[0] > 1.0 && x[0] < 2.0 && x[1] > 0.5 && x[1] < 1.5; },
                   2, 1000.0, 0, false);
    const std::size_t first = m.particles.size();
    fill_region<2>(m.grid, m.particles, [](const double* x) { return x[0] > 3.0 && x[0] < 4.0 && x[1] > 0.5 && x[1] < 1.5; },
                   2, 1000.0, 0, false);
    for (std::size_t i = 0; i < m.particles.size(); ++i) {
        const bool right = i >= first;
        m.particles.v[2 * i] = right ? -2.0 : 2.0;
        m.particles.field[i] = separate_fields && right ? 1 : 0;
    }
    return m;
}

}  // namespace

TEST(SparseGrid, BodiesOnSeparateFieldsPassThroughEachOtherAndOnOneFieldCollide) {
    for (bool separate : {true, false}) {
        MpmModel<2> m = two_blocks(separate);
        MpmSolver<2> s(m);
        double t = 0.0;
        while (t < 0.6) {  // they meet after 0.25 s; on separate fields they overlap fully at 0.5 s
            const double dt = std::min(s.stable_time_step(), 0.6 - t);
            s.step(dt);
            t += dt;
        }
        // Total momentum is zero either way (to round-off).
        EXPECT_NEAR(s.momentum()[0], 0.0, 1e-9 * s.total_mass());
        double left_momentum = 0.0;
        for (std::size_t i = 0; i < m.particles.size() / 2; ++i) left_momentum += m.particles.mass[i] * m.particles.v[2 * i];
        const double left_mass = 0.5 * s.total_mass();
        if (separate) {
            // Nothing passed between them: each block still moves at its own 2 m/s.
            EXPECT_NEAR(left_momentum / left_mass, 2.0, 1e-9);
            for (std::size_t i = 0; i < m.particles.size() / 2; ++i) ASSERT_NEAR(m.particles.v[2 * i], 2.0, 1e-9);
        } else {
            // They struck: the left block has been stopped or sent back.
            EXPECT_LT(left_momentum / left_mass, 1.0);
        }
    }
}

TEST(SparseGrid, APointOnAFieldTheGridDoesNotHaveIsRefused) {
    MpmModel<2> m = square(20, 0.5);
    m.particles.field[0] = 1;
    EXPECT_THROW(MpmSolver<2>{m}, std::invalid_argument);
}

// With several threads the points are cut into chunks, each scattering into a buffer over
// the blocks it reaches: the same motion as one thread (to round-off: the sums run in
// another order) and the same momentum.
TEST(SparseGrid, ChunkedScatterOnTwoThreadsMatchesOneThread) {
    auto big_square = [] {
        MpmModel<2> m;
        m.grid.origin = {0.0, 0.0};
        m.grid.spacing = {0.1, 0.1};
        m.grid.cells = {200, 200};
        m.grid.allocate();
        m.flip = 1.0;
        m.materials.push_back(std::make_unique<LinearElastic>(1e6, 0.3));
        fill_region<2>(m.grid, m.particles, [](const double* x) { return x[0] > 2.0 && x[0] < 10.0 && x[1] > 2.0 && x[1] < 10.0; },
                       2, 1000.0, 0, false);
        for (std::size_t i = 0; i < m.particles.size(); ++i) {
            const double* x = &m.particles.x[2 * i];
            m.particles.v[2 * i] = 0.5 - 0.2 * (x[1] - 6.0);
            m.particles.v[2 * i + 1] = 0.2 * (x[0] - 6.0);
        }
        return m;
    };
    const int threads = omp_get_max_threads();
    MpmModel<2> one = big_square(), two = big_square();
    ASSERT_GT(one.particles.size(), 20000u);
    omp_set_num_threads(1);
    MpmSolver<2> a(one);
    for (int n = 0; n < 20; ++n) a.step(1e-3);
    omp_set_num_threads(2);
    MpmSolver<2> b(two);
    for (int n = 0; n < 20; ++n) b.step(1e-3);
    omp_set_num_threads(threads);
    for (std::size_t i = 0; i < one.particles.x.size(); ++i) ASSERT_NEAR(one.particles.x[i], two.particles.x[i], 1e-12);
    for (int d = 0; d < 2; ++d) EXPECT_NEAR(a.momentum()[d], b.momentum()[d], 1e-10 * a.total_mass());
}
