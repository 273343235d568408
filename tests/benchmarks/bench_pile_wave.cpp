// Throughput of the FE pile (element-steps per second) and wall time of one North Sea
// blow. Run: build/tests/pilempm_benchmarks  (not part of the test suite).
#include <benchmark/benchmark.h>

#include "fem/pile_wave/pile_wave.hpp"
#include "fem/mesh/axisymmetric_mesher.hpp"
#include "fem/dynamics/explicit_pile.hpp"
#include "fem/mesh/rod_mesh.hpp"
#include "io/cases/pile_wave_case.hpp"

using namespace pilempm;

namespace {

const fem::LinearElasticSteel kSteel{210e9, 0.3, 7850.0};

fem::PileGeometry north_sea() { return fem::make_pile_geometry({{77.4, 7.8, 0.07}}); }

// The explicit step alone: internal force, velocity and displacement updates.
void step_loop(benchmark::State& state, fem::ExplicitPile& pile) {
    const double dt = 0.9 * pile.stable_time_step();
    for (auto _ : state) {
        pile.compute_internal_force();
        pile.clear_external_force();
        pile.add_head_force(-1e6);
        pile.advance_velocity(dt);
        pile.advance_displacement(dt);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * pile.mesh().num_elements());
    state.counters["elements"] = pile.mesh().num_elements();
    state.counters["element_steps_per_s"] =
        benchmark::Counter(static_cast<double>(state.iterations()) * pile.mesh().num_elements(),
                           benchmark::Counter::kIsRate);
}

void BM_RodStep(benchmark::State& state) {
    fem::ExplicitPile pile(fem::mesh_rod(north_sea(), 77.4 / state.range(0)), kSteel,
                           {fem::ToeCondition::Dashpot, 6.9e7});
    step_loop(state, pile);
}
BENCHMARK(BM_RodStep)->Arg(310)->Arg(3096);

void BM_AxisymmetricStep(benchmark::State& state) {
    const double size = 0.07 / state.range(0);
    fem::ExplicitPile pile(fem::mesh_axisymmetric_wall(north_sea(), size, static_cast<int>(state.range(0)),
                                                       fem::default_pile_wall_geo()),
                           kSteel, {fem::ToeCondition::Dashpot, 6.9e7});
    step_loop(state, pile);
}
BENCHMARK(BM_AxisymmetricStep)->Arg(2)->Arg(4);

// One whole blow of the README's default case (and its axisymmetric variant), as run
// by `pilempm run` but without writing files: wall time per blow.
void BM_NorthSeaBlow(benchmark::State& state, const char* case_file) {
    const auto c = io::read_pile_wave_case(std::string(PILEMPM_SOURCE_DIR) + "/" + case_file);
    auto setup = io::build_pile_wave_setup(c);
    setup.snapshot_interval = 0.0;
    long steps = 0;
    for (auto _ : state) {
        const auto r = fem::run_pile_wave(setup);
        steps = r.summary.steps + 1;
        benchmark::DoNotOptimize(r.summary.peak_head_force);
    }
    state.counters["steps"] = static_cast<double>(steps);
    state.counters["elements"] = setup.mesh.num_elements();
}
BENCHMARK_CAPTURE(BM_NorthSeaBlow, rod, "cases/pile-wave/north-sea-monopile.yaml")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_NorthSeaBlow, axisymmetric, "cases/pile-wave/north-sea-monopile-axisymmetric.yaml")
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
