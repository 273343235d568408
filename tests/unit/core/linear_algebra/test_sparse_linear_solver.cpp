// Sparse solves through Trilinos, each against an x_exact chosen first: b is formed from
// x_exact by loops of its own (a stencil, the blocks), never by the matrix being tested, and
// the solution must come back to 1e-8. Also: duplicate triplets summed, the pattern reused,
// and bad input answered by an exception or converged = false.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/linear_algebra/sparse_linear_solver.hpp"

using namespace pilempm::core;

namespace {

double relative_error(const std::vector<double>& x, const std::vector<double>& reference) {
    double d = 0.0, r = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        d += (x[i] - reference[i]) * (x[i] - reference[i]);
        r += reference[i] * reference[i];
    }
    return std::sqrt(d / r);
}

// -Laplace on the n x n interior nodes of the unit square (zero Dirichlet values outside),
// h = 1/(n+1), assembled edge by edge, so that every diagonal entry is the sum of four
// triplets: each edge (i, j) adds [1 -1; -1 1]/h^2, a boundary edge 1/h^2 on its node.
SparseMatrix poisson(int n) {
    const double c = (n + 1.0) * (n + 1.0);
    std::vector<Triplet> t;
    const auto node = [n](int i, int j) { return j * n + i; };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int p = node(i, j);
            for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{0, 1}}) {
                const int ii = i + di, jj = j + dj;
                if (ii < n && jj < n) {
                    const int q = node(ii, jj);
                    t.push_back({p, p, c});
                    t.push_back({q, q, c});
                    t.push_back({p, q, -c});
                    t.push_back({q, p, -c});
                } else {
                    t.push_back({p, p, c});  // the edge to the boundary node beyond
                }
            }
            if (i == 0) t.push_back({p, p, c});
            if (j == 0) t.push_back({p, p, c});
        }
    return SparseMatrix(n * n, t);
}

struct Problem {
    SparseMatrix a;
    std::vector<double> x_exact, b;
};

// The matrix, x_exact = sin(pi x) sin(pi y) + x y^2 at the nodes, and b = A x_exact by the
// 5-point stencil.
Problem poisson_problem(int n) {
    Problem p{poisson(n), {}, {}};
    std::vector<double>& x_exact = p.x_exact;
    std::vector<double>& b = p.b;
    const double h = 1.0 / (n + 1.0);
    x_exact.assign(static_cast<std::size_t>(n * n), 0.0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double x = (i + 1) * h, y = (j + 1) * h;
            x_exact[j * n + i] = std::sin(M_PI * x) * std::sin(M_PI * y) + x * y * y;
        }
    const auto u = [&](int i, int j) {
        return i < 0 || j < 0 || i >= n || j >= n ? 0.0 : x_exact[j * n + i];
    };
    b.assign(x_exact.size(), 0.0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            b[j * n + i] =
                (4.0 * u(i, j) - u(i - 1, j) - u(i + 1, j) - u(i, j - 1) - u(i, j + 1)) / (h * h);
    return p;
}

SolverOptions options(KrylovMethod method, Preconditioner preconditioner,
                      double tolerance = 1e-12) {
    SolverOptions o;
    o.method = method;
    o.preconditioner = preconditioner;
    o.relative_tolerance = tolerance;
    return o;
}

void expect_poisson_solved(const SolverOptions& options, int n = 40) {
    const auto [a, x_exact, b] = poisson_problem(n);
    std::vector<double> x;
    const SolveReport r = solve(a, b, x, options);
    EXPECT_TRUE(r.converged) << r.method << " + " << r.preconditioner;
    EXPECT_GT(r.iterations, 0);
    EXPECT_LE(r.iterations, options.max_iterations);
    EXPECT_LE(r.relative_residual, options.relative_tolerance);
    EXPECT_LT(relative_error(x, x_exact), 1e-8) << r.method << " + " << r.preconditioner;
}

// Biot-like u-p blocks on m displacement and m pressure unknowns: K the 1D stiffness
// (tridiagonal 2, -1, SPD), Q a coupling of p_j to u_j and u_{j+1} (+1, -1), S = s I plus a
// 1D permeability Laplacian times dt. symmetric: [K -Q; -Q^T -S]; else [K -Q; Q^T S].
struct SaddlePoint {
    int m = 0;
    bool symmetric = true;
    double s = 0.1, dt = 0.5;
    int uncoupled = -1;  // p_j of this j not coupled to u_{j+1}: one entry fewer in each off-diagonal block
    double k(int i, int j) const { return i == j ? 2.0 : std::abs(i - j) == 1 ? -1.0 : 0.0; }
    double q(int i, int j) const { return i == j ? 1.0 : i == j + 1 && j != uncoupled ? -1.0 : 0.0; }
    double sp(int i, int j) const { return (i == j ? s : 0.0) + dt * k(i, j); }

    SparseMatrix matrix() const {
        std::vector<Triplet> t;
        const double sign = symmetric ? -1.0 : 1.0;
        for (int i = 0; i < m; ++i)
            for (int j = std::max(0, i - 1); j <= std::min(m - 1, i + 1); ++j) {
                t.push_back({i, j, k(i, j)});
                if (q(i, j) != 0.0) {
                    t.push_back({i, m + j, -q(i, j)});        // -Q
                    t.push_back({m + j, i, sign * q(i, j)});  // -Q^T or Q^T
                }
                t.push_back({m + i, m + j, sign * sp(i, j)});  // -S or S
            }
        return SparseMatrix(2 * m, t);
    }
    // b from x_exact = (u, p) block by block, over all (i, j) (a dense loop).
    std::vector<double> rhs(const std::vector<double>& x) const {
        std::vector<double> b(2 * m, 0.0);
        const double sign = symmetric ? -1.0 : 1.0;
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j) {
                b[i] += k(i, j) * x[j] - q(i, j) * x[m + j];
                b[m + i] += sign * (q(j, i) * x[j] + sp(i, j) * x[m + j]);
            }
        return b;
    }
    std::vector<double> exact() const {
        std::vector<double> x(2 * m);
        for (int i = 0; i < 2 * m; ++i) x[i] = std::cos(0.37 * i) + (i >= m ? 10.0 : 0.0);
        return x;
    }
};

void expect_saddle_point_solved(const SaddlePoint& sp, const SolverOptions& options) {
    const std::vector<double> x_exact = sp.exact();
    const std::vector<double> b = sp.rhs(x_exact);
    std::vector<double> x;
    const SolveReport r = solve(sp.matrix(), b, x, options);
    EXPECT_TRUE(r.converged) << r.method << " + " << r.preconditioner << ": "
                             << r.relative_residual;
    EXPECT_LE(r.relative_residual, options.relative_tolerance);
    EXPECT_LT(relative_error(x, x_exact), 1e-8) << r.method << " + " << r.preconditioner;
}

}  // namespace

TEST(SparseLinearSolver, PoissonCgJacobi) {
    expect_poisson_solved(options(KrylovMethod::cg, Preconditioner::jacobi));
}

TEST(SparseLinearSolver, PoissonCgMultigrid) {
    expect_poisson_solved(options(KrylovMethod::cg, Preconditioner::multigrid), 60);
}

TEST(SparseLinearSolver, PoissonGmresIlu) {
    SolverOptions o = options(KrylovMethod::gmres, Preconditioner::ilu);
    o.gmres_restart = 30;  // restarts at least once
    expect_poisson_solved(o);
}

TEST(SparseLinearSolver, PoissonBiCgStabIlutAndDirect) {
    expect_poisson_solved(options(KrylovMethod::bicgstab, Preconditioner::ilut));
    expect_poisson_solved(options(KrylovMethod::direct, Preconditioner::none));
}

TEST(SparseLinearSolver, MultigridNeedsFewerIterationsThanJacobi) {
    const auto [a, x_exact, b] = poisson_problem(60);
    SolverOptions o = options(KrylovMethod::cg, Preconditioner::jacobi, 1e-8);
    std::vector<double> x;
    const SolveReport jacobi = solve(a, b, x, o);
    o.preconditioner = Preconditioner::multigrid;
    x.clear();
    const SolveReport multigrid = solve(a, b, x, o);
    EXPECT_TRUE(jacobi.converged && multigrid.converged);
    EXPECT_LT(3 * multigrid.iterations, jacobi.iterations);
    EXPECT_EQ(multigrid.method, "CG");
    EXPECT_EQ(multigrid.preconditioner, "MueLu SA");
    EXPECT_EQ(jacobi.preconditioner, "Jacobi x1");
    EXPECT_EQ(to_string(KrylovMethod::bicgstab), "BiCGStab");
    EXPECT_EQ(to_string(Preconditioner::multigrid), "multigrid");
}

TEST(SparseLinearSolver, SymmetricIndefiniteSaddlePointGmresIlu) {
    SaddlePoint sp;
    sp.m = 300;
    expect_saddle_point_solved(sp, options(KrylovMethod::gmres, Preconditioner::ilu));
}

TEST(SparseLinearSolver, NonsymmetricSaddlePointGmresIluBiCgStabAndDirect) {
    SaddlePoint sp;
    sp.m = 300;
    sp.symmetric = false;
    SolverOptions o = options(KrylovMethod::gmres, Preconditioner::ilu);
    o.ilu_level = 1;
    expect_saddle_point_solved(sp, o);
    o.method = KrylovMethod::bicgstab;
    expect_saddle_point_solved(sp, o);
    o.method = KrylovMethod::direct;
    expect_saddle_point_solved(sp, o);
}

TEST(SparseLinearSolver, DuplicateTripletsAreSummedAndThePatternReused) {
    const SparseMatrix a(3, {{0, 0, 1.0}, {2, 1, 4.0}, {0, 0, 2.0}, {1, 1, 5.0}, {0, 2, -1.0},
                             {2, 1, 0.5}, {2, 2, 3.0}, {0, 0, 0.25}, {1, 0, 0.0}});
    EXPECT_EQ(a.size(), 3);
    EXPECT_EQ(a.nonzeros(), 6u);  // (0,0) (0,2) (1,0) (1,1) (2,1) (2,2); the explicit zero stays
    EXPECT_DOUBLE_EQ(a(0, 0), 3.25);
    EXPECT_DOUBLE_EQ(a(2, 1), 4.5);
    EXPECT_DOUBLE_EQ(a(0, 1), 0.0);
    EXPECT_EQ(a.row_start(), (std::vector<std::size_t>{0, 2, 4, 6}));
    EXPECT_EQ(a.columns(), (std::vector<int>{0, 2, 0, 1, 1, 2}));
    std::vector<double> y;
    a.multiply({1.0, 2.0, 3.0}, y);
    EXPECT_EQ(y, (std::vector<double>{3.25 - 3.0, 10.0, 9.0 + 9.0}));

    SparseMatrix b = a;
    b.set_zero();
    EXPECT_EQ(b.nonzeros(), 6u);
    b.add(1, 0, 2.0);
    b.add(1, 0, 0.5);
    EXPECT_DOUBLE_EQ(b(1, 0), 2.5);
    EXPECT_DOUBLE_EQ(b(0, 0), 0.0);
    EXPECT_THROW(b.add(0, 1, 1.0), std::out_of_range);  // not in the pattern

    // The solve sees the summed values: a 3x3 system with a known solution.
    const SparseMatrix c(3, {{0, 0, 2.0}, {0, 0, 2.0}, {1, 1, 1.0}, {1, 1, 1.0}, {2, 2, 8.0},
                             {0, 1, 1.0}, {1, 2, 1.0}});  // [4 1 0; 0 2 1; 0 0 8]
    std::vector<double> x;
    const SolveReport r = solve(c, {4.0 + 2.0, 4.0 + 3.0, 24.0}, x, {});  // x = (1, 2, 3)
    EXPECT_TRUE(r.converged);
    EXPECT_NEAR(x[0], 1.0, 1e-10);
    EXPECT_NEAR(x[1], 2.0, 1e-10);
    EXPECT_NEAR(x[2], 3.0, 1e-10);
}

TEST(SparseLinearSolver, BadInputIsRefusedWithAClearError) {
    EXPECT_THROW(SparseMatrix(2, {{0, 2, 1.0}}), std::invalid_argument);
    EXPECT_THROW(SparseMatrix(2, {{-1, 0, 1.0}}), std::invalid_argument);
    EXPECT_THROW(SparseMatrix(2, {{0, 0, std::nan("")}}), std::invalid_argument);
    const SparseMatrix a(2, {{0, 0, 1.0}, {1, 1, 1.0}});
    std::vector<double> x;
    EXPECT_THROW(solve(a, {1.0, 2.0, 3.0}, x), std::invalid_argument);
    x = {0.0, INFINITY};
    EXPECT_THROW(solve(a, {1.0, 2.0}, x), std::invalid_argument);
}

TEST(SparseLinearSolver, SingularOrIndefiniteMatricesGiveAnErrorOrNotConverged) {
    // Row 1 is empty (a node nobody assembled): singular, and b asks for something there.
    const SparseMatrix singular(3, {{0, 0, 2.0}, {0, 2, 1.0}, {2, 0, 1.0}, {2, 2, 3.0}});
    const std::vector<double> b = {1.0, 1.0, 1.0};
    for (const auto& [method, preconditioner] :
         {std::pair{KrylovMethod::gmres, Preconditioner::none},
          std::pair{KrylovMethod::gmres, Preconditioner::ilu},
          std::pair{KrylovMethod::gmres, Preconditioner::jacobi},
          std::pair{KrylovMethod::bicgstab, Preconditioner::ilut},
          std::pair{KrylovMethod::direct, Preconditioner::none}}) {
        SolverOptions o = options(method, preconditioner, 1e-8);
        o.max_iterations = 50;
        std::vector<double> x;
        try {
            const SolveReport r = solve(singular, b, x, o);
            EXPECT_FALSE(r.converged) << r.method << " + " << r.preconditioner;
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find("pilempm::core::solve"), std::string::npos);
        }
    }
    // CG on a symmetric indefinite matrix: refused (Belos asserts p^T A p > 0) or not converged.
    SaddlePoint sp;
    sp.m = 50;
    const std::vector<double> x_exact = sp.exact();
    const SolverOptions o = options(KrylovMethod::cg, Preconditioner::none, 1e-8);
    std::vector<double> x;
    try {
        const SolveReport r = solve(sp.matrix(), sp.rhs(x_exact), x, o);
        EXPECT_FALSE(r.converged && relative_error(x, x_exact) < 1e-6);
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("CG"), std::string::npos) << e.what();
    }
}

TEST(SparseLinearSolver, IterationLimitAndInitialGuess) {
    const auto [a, x_exact, b] = poisson_problem(40);
    SolverOptions o = options(KrylovMethod::cg, Preconditioner::none, 1e-8);
    o.max_iterations = 5;
    std::vector<double> x;
    const SolveReport limited = solve(a, b, x, o);
    EXPECT_FALSE(limited.converged);
    EXPECT_EQ(limited.iterations, 5);
    EXPECT_GT(limited.relative_residual, o.relative_tolerance);
    EXPECT_LT(limited.relative_residual, 1.0);

    // Starting from the answer: nothing to do.
    x = x_exact;
    const SolveReport at_solution = solve(a, b, x, o);
    EXPECT_TRUE(at_solution.converged);
    EXPECT_EQ(at_solution.iterations, 0);
    // b = 0: x = 0 without a solve.
    x = x_exact;
    const SolveReport zero = solve(a, std::vector<double>(b.size(), 0.0), x, o);
    EXPECT_TRUE(zero.converged);
    EXPECT_EQ(zero.iterations, 0);
    EXPECT_EQ(x, std::vector<double>(b.size(), 0.0));
}

// One LinearSolver through a sequence of u-p systems of one pattern and new values (the
// steps of a consolidation pause: S and dt change): each is solved to x_exact, exactly as a
// fresh solve() solves it (the values reach the kept ILU, LU, relaxation); the symbolic set-up
// is kept while pattern and options stay, and built anew when either changes.
TEST(SparseLinearSolver, ASolverKeepsItsSetUpWhileThePatternStaysAndSolvesAsAFreshOne) {
    for (const auto& [method, preconditioner] :
         {std::pair{KrylovMethod::gmres, Preconditioner::ilu},
          std::pair{KrylovMethod::bicgstab, Preconditioner::ilut},
          std::pair{KrylovMethod::gmres, Preconditioner::jacobi},
          std::pair{KrylovMethod::direct, Preconditioner::none}}) {
        // Jacobi preconditions this saddle point poorly: a looser tolerance, and the error with it.
        const bool jacobi = preconditioner == Preconditioner::jacobi;
        SolverOptions o = options(method, preconditioner, jacobi ? 1e-9 : 1e-12);
        o.ilu_level = 1;
        o.max_iterations = 5000;
        LinearSolver kept;
        int solves = 0;
        for (const int m : {200, 200, 200, 201}) {  // the last: another pattern
            SaddlePoint sp;
            sp.m = m;
            sp.symmetric = false;
            sp.s = 0.1 + 0.05 * solves;
            sp.dt = 0.5 / (1.0 + solves);
            const std::vector<double> x_exact = sp.exact(), b = sp.rhs(x_exact);
            std::vector<double> x, fresh;
            const SolveReport r = kept.solve(sp.matrix(), b, x, o);
            solve(sp.matrix(), b, fresh, o);
            EXPECT_TRUE(r.converged) << r.method << " + " << r.preconditioner << ", solve " << solves;
            EXPECT_LT(relative_error(x, x_exact), jacobi ? 1e-5 : 1e-8) << r.method << " + " << r.preconditioner;
            EXPECT_EQ(x, fresh) << r.method << " + " << r.preconditioner << ", solve " << solves;
            ++solves;
        }
        EXPECT_EQ(kept.reused(), 2) << to_string(method) << " + " << to_string(preconditioner);
    }
    // Another pattern (an entry gone from each off-diagonal block, then back): built anew each
    // time it changes, kept when it returns to the last one, and solved to x_exact throughout.
    SolverOptions o = options(KrylovMethod::gmres, Preconditioner::ilu);
    o.ilu_level = 1;
    LinearSolver changing;
    for (const auto& [uncoupled, kept_expected] : {std::pair{-1, false}, std::pair{17, false}, std::pair{17, true},
                                                   std::pair{-1, false}}) {
        SaddlePoint sp;
        sp.m = 200;
        sp.symmetric = false;
        sp.uncoupled = uncoupled;
        const std::vector<double> x_exact = sp.exact(), b = sp.rhs(x_exact);
        std::vector<double> x;
        const SolveReport r = changing.solve(sp.matrix(), b, x, o);
        EXPECT_TRUE(r.converged) << "uncoupled " << uncoupled;
        EXPECT_LT(relative_error(x, x_exact), 1e-8) << "uncoupled " << uncoupled;
        EXPECT_EQ(r.setup_kept, kept_expected) << "uncoupled " << uncoupled;
    }
    // Other options on the same pattern: built anew.
    SaddlePoint sp;
    sp.m = 100;
    sp.symmetric = false;
    const std::vector<double> x_exact = sp.exact(), b = sp.rhs(x_exact);
    LinearSolver kept;
    std::vector<double> x;
    kept.solve(sp.matrix(), b, x, options(KrylovMethod::gmres, Preconditioner::ilu));
    x.clear();
    const SolveReport r = kept.solve(sp.matrix(), b, x, options(KrylovMethod::direct, Preconditioner::none));
    EXPECT_EQ(kept.reused(), 0);
    EXPECT_LT(relative_error(x, x_exact), 1e-8) << r.method;
}
