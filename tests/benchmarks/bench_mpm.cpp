// MPM throughput in particle-steps per second: 2D linear-elastic uGIMP (FLIP and APIC), 2D Mohr-Coulomb
// CPDI and 3D linear-elastic uGIMP, on 1 and 2 threads (the argument); the 2D uGIMP block
// saturated (coupled v-w and undrained) beside its dry self, and the uGIMP blocks on their
// lines given as graded axes.
// Run: build/tests/pilempm_benchmarks --benchmark_filter=Mpm
#include <benchmark/benchmark.h>
#include <omp.h>

#include <vector>

#include "mpm/setup/model_setup.hpp"
#include "mpm/materials/mohr_coulomb.hpp"
#include "mpm/solver/mpm_solver.hpp"

using namespace pilempm::mpm;

namespace {

// A block of soil on a fixed base under gravity, 2 points per cell per direction. With
// `spread` > 1 the grid is that many times wider (each horizontal axis) and taller than the
// soil: a body in a mostly empty box, as a pile-driving domain's far field or a collapse.
template <int D>
MpmModel<D> block(int cells_across, ShapeKind shape, bool mohr_coulomb, int spread = 1,
                  Drainage drainage = Drainage::Dry, bool graded = false) {
    MpmModel<D> m;
    if (drainage == Drainage::Coupled) {
        m.grid.water = true;
        m.grid.fields = 2;
    }
    for (int d = 0; d < D; ++d) {
        m.grid.origin[d] = 0.0;
        m.grid.spacing[d] = 0.25;
        m.grid.cells[d] = spread * (d == D - 1 ? cells_across + 4 : cells_across);
        // The same lines given as a graded axis: what the graded path (cells found by bins,
        // hats over unequal cells) costs against the uniform one on identical work.
        if (graded) {
            std::vector<double> lines(m.grid.cells[d] + 1);
            for (std::size_t i = 0; i < lines.size(); ++i) lines[i] = 0.25 * static_cast<double>(i);
            m.grid.set_lines(d, lines);
        }
    }
    m.grid.allocate();
    m.shape = shape;
    m.gravity[D - 1] = -9.81;
    if (mohr_coulomb) m.materials.push_back(std::make_unique<MohrCoulomb>(20e6, 0.3, 30.0, 0.0, 5e3, 0.0));
    else m.materials.push_back(std::make_unique<LinearElastic>(20e6, 0.3));
    m.particles.state_stride = m.materials.front()->num_state();
    const double top = 0.25 * cells_across;
    const double width = 0.25 * cells_across;
    fill_region<D>(m.grid, m.particles, [top, width](const double* x) {
        for (int d = 0; d < D - 1; ++d)
            if (x[d] > width) return false;
        return x[D - 1] < top;
    }, 2, drainage == Drainage::Dry ? 2000.0 : 1600.0, 0, false);
    if (drainage != Drainage::Dry) {
        // Saturated (rho_sat 2000 kg/m^3, n = 0.4, k = 1e-4 m/s) under a water surface above it.
        m.drainage.push_back({drainage, 0.4, 1000.0 * 9.80665 / 1e-4});
        m.water.free_surface = true;
        m.water.level = top + 10.0;
        for (auto& n : m.particles.porosity) n = 0.4;
    }
    apply_boundary<D>(m.grid, D - 1, 0, BoundaryKind::Fixed);
    for (int d = 0; d < D - 1; ++d) {
        apply_boundary<D>(m.grid, d, 0, BoundaryKind::Roller);
        apply_boundary<D>(m.grid, d, 1, BoundaryKind::Roller);
    }
    return m;
}

template <int D>
void run(benchmark::State& state, ShapeKind shape, bool mohr_coulomb, int cells, bool apic = false, int spread = 1,
         Drainage drainage = Drainage::Dry, bool graded = false) {
    omp_set_num_threads(static_cast<int>(state.range(0)));
    MpmModel<D> m = block<D>(cells, shape, mohr_coulomb, spread, drainage, graded);
    m.apic = apic;
    MpmSolver<D> solver(m);
    const double dt = solver.stable_time_step();
    for (auto _ : state) solver.step(dt);
    const double n = static_cast<double>(m.particles.size());
    state.counters["points"] = n;
    state.counters["particle_steps_per_s"] =
        benchmark::Counter(n * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
    omp_set_num_threads(omp_get_num_procs());
}

void BM_Mpm2dElasticGimp(benchmark::State& s) { run<2>(s, ShapeKind::GIMP, false, 100); }
void BM_Mpm2dElasticGimpApic(benchmark::State& s) { run<2>(s, ShapeKind::GIMP, false, 100, true); }
void BM_Mpm2dMohrCoulombCpdi(benchmark::State& s) { run<2>(s, ShapeKind::CPDI, true, 100); }
void BM_Mpm3dElasticGimp(benchmark::State& s) { run<3>(s, ShapeKind::GIMP, false, 20); }
// The 2D and 3D uGIMP blocks on their own lines given as graded axes.
void BM_Mpm2dElasticGimpGraded(benchmark::State& s) { run<2>(s, ShapeKind::GIMP, false, 100, false, 1, Drainage::Dry, true); }
void BM_Mpm3dElasticGimpGraded(benchmark::State& s) { run<3>(s, ShapeKind::GIMP, false, 20, false, 1, Drainage::Dry, true); }
// The same bodies in boxes 4 x 4 (2D) and 3 x 3 x 3 (3D) times their size.
void BM_Mpm2dElasticGimpSparse(benchmark::State& s) { run<2>(s, ShapeKind::GIMP, false, 100, false, 4); }
void BM_Mpm3dElasticGimpSparse(benchmark::State& s) { run<3>(s, ShapeKind::GIMP, false, 20, false, 3); }
// Saturated: the v-w step (two velocity fields, the drag solved per node) and the undrained one.
void BM_Mpm2dElasticGimpCoupled(benchmark::State& s) { run<2>(s, ShapeKind::GIMP, false, 100, false, 1, Drainage::Coupled); }
void BM_Mpm2dElasticGimpUndrained(benchmark::State& s) { run<2>(s, ShapeKind::GIMP, false, 100, false, 1, Drainage::Undrained); }
BENCHMARK(BM_Mpm2dElasticGimpGraded)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Mpm3dElasticGimpGraded)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Mpm2dElasticGimpCoupled)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Mpm2dElasticGimpUndrained)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Mpm2dElasticGimp)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Mpm2dElasticGimpApic)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Mpm2dMohrCoulombCpdi)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Mpm3dElasticGimp)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Mpm2dElasticGimpSparse)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Mpm3dElasticGimpSparse)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
