// Stress updates per second of each soil model on yielding points (the costly branch):
// a batch of points at a normally consolidated / failure state loaded in shear and
// compression every iteration. items_per_second is the figure to report.
#include <benchmark/benchmark.h>

#include <memory>
#include <numeric>
#include <vector>

#include "mpm/materials/hypoplastic.hpp"
#include "mpm/materials/hardening_soil_small.hpp"
#include "mpm/materials/modified_cam_clay.hpp"
#include "mpm/materials/mohr_coulomb.hpp"
#include "mpm/materials/subloading_cam_clay.hpp"

using namespace pilempm::mpm;

namespace {

constexpr int kPoints = 10000;

void run(benchmark::State& s, const ConstitutiveModel& model, double p0, double increment = 1.0) {
    std::vector<int> idx(kPoints);
    std::iota(idx.begin(), idx.end(), 0);
    const int stride = model.num_state();
    std::vector<double> stress(6 * kPoints), state(static_cast<std::size_t>(stride) * kPoints), de(6 * kPoints);
    for (int i = 0; i < kPoints; ++i) {
        double* sg = &stress[6 * i];
        sg[0] = sg[1] = -0.5 * p0;
        sg[2] = -p0;
        sg[3] = 0.05 * p0 * (i % 7) / 7.0;
        sg[4] = sg[5] = 0.0;
        model.initialise_state(sg, &state[static_cast<std::size_t>(stride) * i]);
        const double d[6] = {2e-5, 2e-5, -6e-5, 1e-5, 0.0, 0.0};  // compression and shear
        for (int k = 0; k < 6; ++k) de[6 * i + k] = increment * d[k];
    }
    // Warm-up: models with a strain memory (intergranular strain) start from a loaded state,
    // and every iteration updates that same state, so the figure does not drift with time.
    for (int k = 0; k < 20; ++k) model.update(kPoints, idx.data(), de.data(), stress.data(), state.data(), stride);
    const std::vector<double> stress0 = stress, state0 = state;
    for (auto _ : s) {
        s.PauseTiming();
        stress = stress0;
        state = state0;
        s.ResumeTiming();
        model.update(kPoints, idx.data(), de.data(), stress.data(), state.data(), stride);
        benchmark::DoNotOptimize(stress.data());
    }
    s.SetItemsProcessed(s.iterations() * kPoints);
}

void BM_StressUpdateMohrCoulomb(benchmark::State& s) {
    const MohrCoulomb model(30e6, 0.3, 30.0, 0.0, 0.0, 0.0);
    run(s, model, 100e3);
}

void BM_StressUpdateModifiedCamClay(benchmark::State& s) {
    CamClayParameters p;
    p.M = 1.2;
    const ModifiedCamClay model(p);
    run(s, model, 100e3);
}

// Schlabendorfer sand with intergranular strain: every point is loading in the hypoplastic
// branch (the rate is evaluated twice per substep).
void BM_StressUpdateHypoplastic(benchmark::State& s) {
    const Hypoplastic model(HypoplasticParameters{});
    run(s, model, 100e3);
}

// The same at a typical explicit-MPM strain increment (1e-6 instead of 7e-5): one substep.
void BM_StressUpdateHypoplasticSmallIncrement(benchmark::State& s) {
    const Hypoplastic model(HypoplasticParameters{});
    run(s, model, 100e3, 0.015);
}

// Matsuoka-Nakai surface (the Lode-angle solve is part of the cost), a = 2000, OCR 2.
void BM_StressUpdateSubloadingCamClay(benchmark::State& s) {
    SubloadingCamClayParameters p;
    p.ocr = 2.0;
    const SubloadingCamClay model(p);
    run(s, model, 100e3);
}

// The same, its stress bounded by the Matsuoka-Nakai cone of its phi' (the test of the cone,
// a Lode-angle solve, on every point; the return where it is outside).
void BM_StressUpdateSubloadingCamClayBounded(benchmark::State& s) {
    SubloadingCamClayParameters p;
    p.ocr = 2.0;
    p.peak_friction_angle = p.friction_angle;
    const SubloadingCamClay model(p);
    run(s, model, 100e3);
}

// Seed 001, Table 2, D_R = 99 %: the shear surface and the cap both load in this path.
void BM_StressUpdateHardeningSoilSmall(benchmark::State& s) {
    HardeningSoilSmallParameters p;
    p.c = 1e3;
    p.psi = 1.0;
    const HardeningSoilSmall model(p);
    run(s, model, 100e3);
}

// The same at an explicit-MPM step's strain increment (1e-6): one substep on the surfaces.
void BM_StressUpdateHardeningSoilSmallSmallIncrement(benchmark::State& s) {
    HardeningSoilSmallParameters p;
    p.c = 1e3;
    p.psi = 1.0;
    const HardeningSoilSmall model(p);
    run(s, model, 100e3, 0.015);
}

// Unloading at that increment: the elastic branch most points of a blow take.
void BM_StressUpdateHardeningSoilSmallUnloading(benchmark::State& s) {
    HardeningSoilSmallParameters p;
    p.c = 1e3;
    p.psi = 1.0;
    const HardeningSoilSmall model(p);
    run(s, model, 100e3, -0.015);
}

}  // namespace

BENCHMARK(BM_StressUpdateHypoplastic)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StressUpdateHypoplasticSmallIncrement)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StressUpdateMohrCoulomb)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StressUpdateModifiedCamClay)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StressUpdateSubloadingCamClay)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StressUpdateSubloadingCamClayBounded)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StressUpdateHardeningSoilSmall)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StressUpdateHardeningSoilSmallSmallIncrement)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StressUpdateHardeningSoilSmallUnloading)->Unit(benchmark::kMillisecond);
