// One coupled step of the FE pile in the MPM soil: the jacked open pile of
// cases/jacking/jacked-open-pile-small.yaml (7 200 points, cells of 0.1 m, a 2.4 m steel pile
// of 98 nodes), pushed 0.05 m into the sand first. Counters: the share of the step in the
// contact and the pile (search, forces, field cut, the pile's subcycles) against the soil's
// MPM step, the pile's substeps, and particle-steps per second of the whole step.
// Run: build/tests/pilempm_benchmarks --benchmark_filter=CoupledPile
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <string>

#include "coupling/contact/coupled_pile.hpp"
#include "io/cases/mpm_case.hpp"
#include "io/cases/mpm_run_builder.hpp"

using namespace pilempm;

static void BM_CoupledPileJackingStep(benchmark::State& state) {
    const auto c = io::read_mpm_case(std::string(PILEMPM_SOURCE_DIR) + "/cases/jacking/jacked-open-pile-small.yaml");
    auto run = io::build_mpm_run<2>(c);
    auto& m = run.model;
    fem::ExplicitPile pile(run.pile.mesh, run.pile.steel, fem::ToeSupport{});
    coupling::CoupledPile coupled(pile, run.pile.contact, run.pile.frame, run.pile.gravity, run.pile.cut_fields,
                                  run.pile.toe_slip_line);
    coupled.set_head_control(run.pile.heads);
    m.local_damping = 0.7;  // the jacking stage's
    mpm::MpmSolver<2> soil(m);
    double t = 0.0;
    auto step = [&](double& in_contact, double& whole) {
        const double dt = std::min(soil.stable_time_step(), coupled.stable_time_step(m, soil.stable_time_step()));
        const auto t0 = std::chrono::steady_clock::now();
        coupled.advance(m, dt, 0, t);
        const auto t1 = std::chrono::steady_clock::now();
        soil.step(dt);
        const auto t2 = std::chrono::steady_clock::now();
        in_contact += std::chrono::duration<double>(t1 - t0).count();
        whole += std::chrono::duration<double>(t2 - t0).count();
        t += dt;
    };
    double a = 0.0, b = 0.0;
    while (coupled.head_settlement() < 0.05) step(a, b);  // into the soil first
    double in_contact = 0.0, whole = 0.0;
    long steps = 0;
    for (auto _ : state) {
        step(in_contact, whole);
        ++steps;
    }
    state.counters["contact_and_pile_share"] = whole > 0.0 ? in_contact / whole : 0.0;
    state.counters["pile_substeps"] = coupled.substeps();
    state.counters["points"] = static_cast<double>(m.particles.size());
    state.counters["particle_steps_per_s"] =
        benchmark::Counter(static_cast<double>(steps) * static_cast<double>(m.particles.size()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_CoupledPileJackingStep)->UseRealTime()->Unit(benchmark::kMillisecond)->MinTime(5.0);
