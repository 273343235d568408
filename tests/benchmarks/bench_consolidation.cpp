// One implicit consolidation step (Biot u-p on the MPM grid, Trilinos GMRES + ILU(1)) on the
// seed 001-sized axisymmetric domain of cases/examples/north-sea-pause-consolidation.yaml:
// 20 m x 20 m of saturated sand in 0.25 m cells, 25 600 points, about 20 000 unknowns.
// Counters: the linear solve's share (setup + iterations), its setup, and its GMRES iterations.
// Run: build/tests/pilempm_benchmarks --benchmark_filter=Consolidation
#include <benchmark/benchmark.h>

#include "mpm/implicit/consolidation.hpp"
#include "mpm/setup/model_setup.hpp"

using namespace pilempm::mpm;

namespace {

MpmModel<2> seabed(int cells) {
    MpmModel<2> m;
    m.grid.origin = {0.0, 0.0};
    m.grid.spacing = {20.0 / cells, 20.0 / cells};
    m.grid.cells = {cells, cells + cells / 20};
    m.grid.water = true;
    m.grid.fields = 2;
    m.grid.allocate();
    m.axisymmetric = true;
    m.gravity[1] = -9.81;
    m.water.free_surface = true;
    m.water.level = 60.0;
    m.materials.push_back(std::make_unique<LinearElastic>(50e6, 0.3));
    m.drainage.push_back({Drainage::Coupled, 0.4, 1000.0 * 9.80665 / 1e-4});
    fill_region<2>(m.grid, m.particles, [](const double* x) { return x[1] < 20.0; }, 2, 1600.0, 0, true);
    for (auto& n : m.particles.porosity) n = 0.4;
    apply_k0_stress<2>(m.particles, 20.0, 9.81, [](double) { return 1000.0; }, [](double) { return 0.3 / 0.7; });
    apply_boundary<2>(m.grid, 0, 0, BoundaryKind::Roller);
    apply_boundary<2>(m.grid, 0, 1, BoundaryKind::Roller);
    apply_boundary<2>(m.grid, 1, 0, BoundaryKind::Fixed);
    // Excess pressure under the pile's footprint, as a blow leaves it.
    for (std::size_t i = 0; i < m.particles.size(); ++i) {
        const double r = m.particles.x[2 * i], z = m.particles.x[2 * i + 1];
        if (r < 3.9 && z > 14.0) m.particles.pore_pressure[i] = 300e3 * (z - 14.0) / 6.0;
    }
    return m;
}

// range(0): cells across; range(1): 0 GMRES + ILU(1) (the stage's default), 1 GMRES + ILU(2),
// 2 KLU2 (direct); range(2): the step in 0.1 ms (67: a pause's first step, 500: a later one).
void BM_ConsolidationStep(benchmark::State& state) {
    MpmModel<2> m = seabed(static_cast<int>(state.range(0)));
    pilempm::core::SolverOptions options;
    options.relative_tolerance = 1e-10;
    options.ilu_level = state.range(1) == 1 ? 2 : 1;
    if (state.range(1) == 2) options.method = pilempm::core::KrylovMethod::direct;
    ConsolidationSolver<2> solver(m, options);
    double solve = 0.0, setup = 0.0, iterations = 0.0, kept = 0.0;
    for (auto _ : state) {
        const auto r = solver.step(state.range(2) * 1e-4);
        solve += r.solve.setup_seconds + r.solve.solve_seconds;
        setup += r.solve.setup_seconds;
        kept += r.solve.setup_kept ? 1.0 : 0.0;
        iterations += r.solve.iterations;
        state.counters["unknowns"] = r.unknowns;
    }
    const double n = static_cast<double>(state.iterations());
    state.counters["points"] = static_cast<double>(m.particles.size());
    state.counters["linear_solve_s"] = solve / n;
    state.counters["setup_s"] = setup / n;
    // The share of steps whose matrix kept the last one's pattern (and its ILU's fill graph):
    // none here: the soil settles under the footprint's excess pressure and its points' stencils
    // change from step to step (a drive's pause keeps 8 of its 10).
    state.counters["setup_kept"] = kept / n;
    state.counters["gmres_iterations"] = iterations / n;
}
BENCHMARK(BM_ConsolidationStep)->Args({40, 0, 67})->Args({80, 0, 67})->Args({80, 0, 500})->Args({80, 1, 500})
    ->Args({80, 2, 500})->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
