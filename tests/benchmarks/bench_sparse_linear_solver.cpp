// One sparse solve of 2D Poisson (5-point, 316 x 316 = 99 856 unknowns) to 1e-8: CG with
// each preconditioner, GMRES + ILU(0), and KLU2; wall time of the setup (matrix copy,
// preconditioner) and of the iterations, reported as counters, the iterations too.
// Run: build/tests/pilempm_benchmarks --benchmark_filter=SparseSolve
#include <benchmark/benchmark.h>

#include <vector>

#include "core/linear_algebra/sparse_linear_solver.hpp"

using namespace pilempm::core;

namespace {

constexpr int kSide = 316;

SparseMatrix laplacian(int n) {
    std::vector<Triplet> t;
    t.reserve(5 * static_cast<std::size_t>(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int p = j * n + i;
            t.push_back({p, p, 4.0});
            if (i > 0) t.push_back({p, p - 1, -1.0});
            if (i + 1 < n) t.push_back({p, p + 1, -1.0});
            if (j > 0) t.push_back({p, p - n, -1.0});
            if (j + 1 < n) t.push_back({p, p + n, -1.0});
        }
    return SparseMatrix(n * n, t);
}

void run(benchmark::State& state, KrylovMethod method, Preconditioner preconditioner) {
    const SparseMatrix a = laplacian(kSide);
    const std::vector<double> b(static_cast<std::size_t>(a.size()), 1.0);
    SolverOptions o;
    o.method = method;
    o.preconditioner = preconditioner;
    o.max_iterations = 5000;
    SolveReport r;
    double setup = 0.0, iterations = 0.0;
    for (auto _ : state) {
        std::vector<double> x;
        r = solve(a, b, x, o);
        setup += r.setup_seconds;
        iterations += r.solve_seconds;
    }
    if (!r.converged) state.SkipWithError("not converged");
    const double runs = static_cast<double>(state.iterations());
    state.counters["unknowns"] = a.size();
    state.counters["iterations"] = r.iterations;
    state.counters["setup_s"] = setup / runs;
    state.counters["solve_s"] = iterations / runs;
}

using K = KrylovMethod;
using P = Preconditioner;
void BM_SparseSolveCgJacobi(benchmark::State& s) { run(s, K::cg, P::jacobi); }
void BM_SparseSolveCgIlu0(benchmark::State& s) { run(s, K::cg, P::ilu); }
void BM_SparseSolveCgMueLu(benchmark::State& s) { run(s, K::cg, P::multigrid); }
void BM_SparseSolveGmresIlu0(benchmark::State& s) { run(s, K::gmres, P::ilu); }
void BM_SparseSolveKlu2(benchmark::State& s) { run(s, K::direct, P::none); }
BENCHMARK(BM_SparseSolveCgJacobi)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SparseSolveCgIlu0)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SparseSolveCgMueLu)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SparseSolveGmresIlu0)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SparseSolveKlu2)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
