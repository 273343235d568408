// Wave-equation drivability: one depth point (blows to a steady set) and the whole North
// Sea study on one thread. Run: build/tests/pilempm_benchmarks --benchmark_filter=Driv
#include <benchmark/benchmark.h>

#include "coupling/wave_equation/drivability.hpp"
#include "io/cases/drivability_case.hpp"

using namespace pilempm;

namespace {

coupling::DrivabilitySetup north_sea_setup(int threads) {
    const auto c = io::read_drivability_case(std::string(PILEMPM_SOURCE_DIR) +
                                             "/cases/drivability/north-sea-monopile.yaml");
    auto s = io::build_drivability_setup(c);
    s.threads = threads;
    return s;
}

void BM_DrivabilityDepthPoint(benchmark::State& state) {
    const auto s = north_sea_setup(1);
    const auto srd = coupling::srd_for_driving(s, s.cases[1], static_cast<double>(state.range(0)));
    long blows = 0;
    for (auto _ : state) {
        const auto r = coupling::drive_at_penetration(s.mesh, s.steel, srd, s.smith, s.hammer,
                                                      s.ram_element_size, s.driving);
        blows += r.blows;
        benchmark::DoNotOptimize(r.set);
    }
    state.counters["blows_per_s"] = benchmark::Counter(static_cast<double>(blows), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_DrivabilityDepthPoint)->Arg(12)->Arg(30)->Unit(benchmark::kMillisecond);

// The README's default case, all three soil cases, on `threads` threads.
void BM_NorthSeaDrivability(benchmark::State& state) {
    const auto s = north_sea_setup(static_cast<int>(state.range(0)));
    long points = 0;
    for (auto _ : state) {
        const auto r = coupling::run_drivability(s);
        points = r.depth_points;
        benchmark::DoNotOptimize(r.blows_simulated);
    }
    state.counters["depth_points"] = static_cast<double>(points);
}
BENCHMARK(BM_NorthSeaDrivability)->Arg(1)->Arg(2)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
