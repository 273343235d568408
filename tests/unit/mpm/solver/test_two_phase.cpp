// The explicit v-w solver: momentum of skeleton and water together is conserved while the
// Darcy drag exchanges it (to round-off, against the free-body law), and while an
// impermeable wall holds the water against it; the drag relaxes the
// relative velocity at the rate of its closed form; a point driven to zero effective stress
// by cyclic undrained shear never produces a NaN, and recovers its effective stress when
// the pore water drains (the implicit consolidation); the handover between explicit and
// implicit stages conserves the grains' volume and the masses.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mpm/implicit/consolidation.hpp"
#include "mpm/materials/hypoplastic.hpp"
#include "mpm/setup/model_setup.hpp"
#include "mpm/solver/mpm_solver.hpp"

using namespace pilempm::mpm;

namespace {

constexpr double kPorosity = 0.4;

// A block of coupled elastic soil in a grid with water fields.
MpmModel<2> saturated_block(double hydraulic_conductivity, double lo = 0.8, double hi = 1.6, int cells = 12) {
    MpmModel<2> m;
    for (int d = 0; d < 2; ++d) {
        m.grid.origin[d] = 0.0;
        m.grid.spacing[d] = 0.2;
        m.grid.cells[d] = cells;
    }
    m.grid.water = true;
    m.grid.fields = 2;
    m.grid.allocate();
    m.materials.push_back(std::make_unique<LinearElastic>(1e6, 0.3));
    MaterialDrainage dr;
    dr.drainage = Drainage::Coupled;
    dr.porosity = kPorosity;
    dr.darcy_resistance = m.water.density * 9.80665 / hydraulic_conductivity;
    m.drainage.push_back(dr);
    fill_region<2>(m.grid, m.particles, [lo, hi](const double* x) {
        return x[0] > lo && x[0] < hi && x[1] > lo && x[1] < hi;
    }, 2, 2000.0 - kPorosity * 1000.0, 0, false);
    for (std::size_t i = 0; i < m.particles.size(); ++i) m.particles.porosity[i] = kPorosity;
    return m;
}

TEST(TwoPhase, FreeBodyKeepsTheMomentumOfSkeletonAndWater) {
    MpmModel<2> m = saturated_block(1e-3);
    // The skeleton and the water move apart (no strain: the water's mass in each point's
    // volume stays what it is); the drag trades momentum between them.
    for (std::size_t i = 0; i < m.particles.size(); ++i) {
        m.particles.v[2 * i + 0] = 0.3;
        m.particles.v[2 * i + 1] = -0.1;
        m.particles.w[2 * i + 0] = -0.2;
        m.particles.w[2 * i + 1] = 0.4;
    }
    MpmSolver<2> s(m);
    const auto q0 = s.momentum();
    const double dt = s.stable_time_step();
    for (int n = 0; n < 300; ++n) s.step(dt);
    const auto q = s.momentum();
    double scale = 0.0;
    for (std::size_t i = 0; i < m.particles.size(); ++i) scale += m.particles.mass[i] * 0.5;
    for (int d = 0; d < 2; ++d) EXPECT_NEAR(q[d], q0[d], 1e-12 * scale) << "axis " << d;
    // The water has been dragged toward the skeleton: their relative velocity fell.
    double rel = 0.0;
    for (std::size_t i = 0; i < m.particles.size(); ++i) rel = std::max(rel, std::abs(m.particles.w[2 * i] - m.particles.v[2 * i]));
    EXPECT_LT(rel, 0.5 * 0.5);
    for (double x : m.particles.pore_pressure) EXPECT_TRUE(std::isfinite(x));
}

// An impermeable wall along the block's top (the FE pile's steel, as coupling sets it):
// at the nodes on it the water moves with the skeleton across it, and the momentum of
// skeleton and water together is still conserved to round-off (the wall's force is
// between the phases).
TEST(TwoPhase, AnImpermeableWallStopsTheFlowAcrossItAndKeepsTheMomentum) {
    const double hi = 1.6;
    MpmModel<2> m = saturated_block(1e-3, 0.8, hi);
    auto& p = m.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
        p.v[2 * i + 1] = -0.1;
        p.w[2 * i + 0] = -0.2;
        p.w[2 * i + 1] = 0.4;  // the water flows up, into the wall
        if (p.x[2 * i + 1] > hi - 0.1) m.water_walls.push_back({static_cast<long>(i), {0.0, -1.0, 0.0}, {0.0, hi, 0.0}});
    }
    ASSERT_FALSE(m.water_walls.empty());
    // The step's momentum, its water weighed as the step weighs it (n rho_w V at its start:
    // the point's water content follows its volume afterwards).
    std::vector<double> water(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) water[i] = p.porosity[i] * m.water.density * p.volume[i];
    auto momentum = [&](int d) {
        double q = 0.0;
        for (std::size_t i = 0; i < p.size(); ++i) q += p.mass[i] * p.v[2 * i + d] + water[i] * p.w[2 * i + d];
        return q;
    };
    const double q0[2] = {momentum(0), momentum(1)};
    MpmSolver<2> s(m);
    s.step(s.stable_time_step());
    double scale = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) scale += p.mass[i] * 0.5;
    for (int d = 0; d < 2; ++d) EXPECT_NEAR(momentum(d), q0[d], 1e-12 * scale) << "axis " << d;
    // The remapped velocities at the nodes on the wall (those the strain is taken from):
    // the water's vertical velocity is the skeleton's.
    const auto& g = m.grid;
    int held = 0;
    for (int n = 0; n < g.stored_nodes(); ++n) {
        const int es = 2 * n, ew = es + 1;
        if (!g.stored_node_exists(n) || g.mass[es] <= 0.0 || g.mass[ew] <= 0.0) continue;
        if (g.position[2 * es + 1] < hi - 1e-9) continue;
        EXPECT_NEAR(g.velocity[2 * ew + 1], g.velocity[2 * es + 1], 1e-12) << "node " << n;
        ++held;
    }
    EXPECT_GT(held, 0);
}

// Uniform relative motion: the stresses stay zero, and the mixture's momentum fixes the
// common velocity, so w - v decays as exp(-t / tau) with 1/tau = n R (1/rho_w + n/rho_s'),
// rho_s' = (1 - n) rho_s. The semi-implicit drag is backward Euler on this ODE:
// (w - v)_N = (w - v)_0 / (1 + dt / tau)^N, here with a step 20 times tau (an explicit drag
// would blow up).
TEST(TwoPhase, DragRelaxesRelativeVelocityAsBackwardEuler) {
    const double k = 1e-9;  // clay: tau ~ 1e-10 s
    MpmModel<2> m = saturated_block(k, 0.0, 2.4, 12);  // the whole grid: no free surface
    for (std::size_t i = 0; i < m.particles.size(); ++i) {
        m.particles.w[2 * i] = 1e-3;
        m.particles.v[2 * i] = 0.0;
    }
    m.flip = 1.0;
    MpmSolver<2> s(m);
    const double R = m.drainage[0].darcy_resistance, rho_s = 2000.0 - kPorosity * 1000.0;
    const double tau = 1.0 / (kPorosity * R * (1.0 / 1000.0 + kPorosity / rho_s));
    const double dt = 20.0 * tau;
    const int steps = 3;
    for (int n = 0; n < steps; ++n) s.step(dt);
    const double expected = 1e-3 / std::pow(1.0 + dt / tau, steps);
    double worst = 0.0;
    for (std::size_t i = 0; i < m.particles.size(); ++i)
        worst = std::max(worst, std::abs((m.particles.w[2 * i] - m.particles.v[2 * i]) - expected));
    EXPECT_LT(worst, 1e-6 * 1e-3) << "expected w - v = " << expected;
}

// A drained stage (a drained nil step) on coupled soil: the block squeezed inward steps at
// the drained P-wave speed sqrt(M / (rho_s + n rho_w)) with no excess pressure and the water
// moving with the skeleton (momentum of both conserved); set back to coupled, the same
// squeeze raises the excess pressure and the step is the v-w one again.
TEST(TwoPhase, ADrainedStageHoldsTheWaterHydrostaticAndStepsAtTheDrainedWaveSpeed) {
    MpmModel<2> m = saturated_block(1e-6);
    auto squeeze = [&m] {
        for (std::size_t i = 0; i < m.particles.size(); ++i)
            for (int d = 0; d < 2; ++d) m.particles.v[2 * i + d] = -0.01 * (m.particles.x[2 * i + d] - 1.2);
    };
    squeeze();
    MpmSolver<2> s(m);
    const double coupled_dt = s.stable_time_step();
    s.set_drained(true);
    const double E = 1e6, nu = 0.3, M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
    const double c_drained = std::sqrt(M / (2000.0 - kPorosity * 1000.0 + kPorosity * 1000.0));
    double v_max = 0.0;
    for (double v : m.particles.v) v_max = std::max(v_max, std::abs(v));
    const double dt = s.stable_time_step();
    EXPECT_NEAR(dt, m.cfl * 0.2 / (c_drained + std::sqrt(2.0) * v_max), 1e-6 * dt);
    EXPECT_GT(dt, 3.0 * coupled_dt);  // no water wave to resolve
    const auto q0 = s.momentum();
    for (int n = 0; n < 20; ++n) s.step(dt);
    for (std::size_t i = 0; i < m.particles.size(); ++i) {
        EXPECT_EQ(m.particles.pore_pressure[i], 0.0);
        EXPECT_EQ(m.particles.w[2 * i] + m.particles.w[2 * i + 1], 0.0);
    }
    const auto q = s.momentum();
    for (int d = 0; d < 2; ++d) EXPECT_NEAR(q[d], q0[d], 1e-12);
    s.set_drained(false);
    EXPECT_NEAR(s.stable_time_step() / coupled_dt, 1.0, 0.05);
    squeeze();
    for (int n = 0; n < 20; ++n) s.step(s.stable_time_step());
    double p_max = 0.0;
    for (double p : m.particles.pore_pressure) p_max = std::max(p_max, p);
    EXPECT_GT(p_max, 100.0) << "the coupled water takes the squeeze again";
}

// Loose sand (hypoplastic, e = e_c0: contractive) under a 100 kPa surcharge, sheared back and
// forth at constant volume of the water (coupled, k = 1e-8 m/s: undrained within a cycle):
// the pore pressure rises toward the total stress, the effective stress toward zero
// (liquefaction). Nothing may turn NaN; after the shaking an implicit pause with a drained
// top lets the water out and the effective stress comes back.
TEST(TwoPhase, LiquefactionAndBackWithoutNaN) {
    MpmModel<2> m;
    m.grid.origin = {0.0, 0.0};
    m.grid.spacing = {0.25, 0.25};
    m.grid.cells = {4, 6};
    m.grid.water = true;
    m.grid.fields = 2;
    m.grid.allocate();
    HypoplasticParameters hp;
    hp.void_ratio = 0.84;
    m.materials.push_back(std::make_unique<Hypoplastic>(hp));
    const double n0 = hp.void_ratio / (1.0 + hp.void_ratio);
    MaterialDrainage dr;
    dr.drainage = Drainage::Coupled;
    dr.porosity = n0;
    dr.darcy_resistance = 1000.0 * 9.80665 / 1e-8;
    m.drainage.push_back(dr);
    m.particles.state_stride = m.materials[0]->num_state();
    fill_region<2>(m.grid, m.particles, [](const double* x) { return x[1] < 1.0; }, 2, 1500.0, 0, false);
    auto& p = m.particles;
    const double sv0 = -100e3, sh0 = -50e3;
    for (std::size_t i = 0; i < p.size(); ++i) {
        p.porosity[i] = n0;
        double* s = &p.stress[6 * i];
        s[0] = s[2] = sh0;
        s[1] = sv0;
        m.materials[0]->initialise_state(s, p.state.data() + p.state_stride * i);
    }
    // The surcharge on the top row (held), the base fixed, every other node moving with
    // simple shear x-velocity gamma_dot y (vertical free).
    for (std::size_t i = 0; i < p.size(); ++i)
        if (p.x[2 * i + 1] > 0.875) {
            SurfaceLoad load;
            load.point = static_cast<int>(i);
            load.offset[1] = 0.5 * p.domain0[4 * i + 3];
            load.force[1] = sv0 * p.domain0[4 * i];  // compression: down
            m.surface_loads.push_back(load);
        }
    apply_boundary<2>(m.grid, 1, 0, BoundaryKind::Fixed);
    std::vector<int> sheared;
    for (int node = 0; node < m.grid.num_nodes(); ++node)
        if (m.grid.ijk(node)[1] > 0) sheared.push_back(node);
    MpmSolver<2> s(m);
    const double period = 0.05, amplitude = 0.01;  // shear strain amplitude 1 %
    const double dt = s.stable_time_step();
    double least_mean = 1e300;
    const double mean0 = -(2.0 * sh0 + sv0) / 3.0;
    for (long step = 0; step * dt < 10 * period; ++step) {
        const double t = step * dt;
        const double rate = amplitude * 2.0 * M_PI / period * std::cos(2.0 * M_PI * t / period);
        for (int node : sheared) {
            auto& c = m.grid.condition(node);
            c.fixed[0] = 1;
            c.prescribed[0] = rate * m.grid.coordinate(1, m.grid.ijk(node)[1]);
        }
        s.step(dt);
        double mean = 0.0;
        for (std::size_t i = 0; i < p.size(); ++i) {
            for (int k = 0; k < 6; ++k) ASSERT_TRUE(std::isfinite(p.stress[6 * i + k])) << "step " << step;
            ASSERT_TRUE(std::isfinite(p.pore_pressure[i]));
            mean += -(p.stress[6 * i] + p.stress[6 * i + 1] + p.stress[6 * i + 2]) / 3.0 / static_cast<double>(p.size());
        }
        least_mean = std::min(least_mean, mean);
    }
    EXPECT_LT(least_mean, 0.1 * mean0) << "the loose sand did not liquefy";
    // The pause: shaking stopped (the sides held), the top drains (its free surface).
    for (int node : sheared) m.grid.condition(node).prescribed[0] = 0.0;
    m.drainage[0].darcy_resistance = 1000.0 * 9.80665 / 1e-2;  // a gravel-fast drainage: the test need not wait
    ConsolidationSolver<2> pause(m);
    for (int k = 0; k < 20; ++k) pause.step(0.05 * std::pow(1.3, k));
    double mean = 0.0, excess = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        for (int k = 0; k < 6; ++k) ASSERT_TRUE(std::isfinite(p.stress[6 * i + k]));
        mean += -(p.stress[6 * i] + p.stress[6 * i + 1] + p.stress[6 * i + 2]) / 3.0 / static_cast<double>(p.size());
        excess = std::max(excess, std::abs(p.pore_pressure[i]));
    }
    EXPECT_GT(mean, 0.5 * mean0) << "the effective stress did not come back";
    EXPECT_LT(excess, 0.05 * -sv0);
}

// Explicit, implicit and explicit again: the grains' volume (1 - n) V of every point and the
// masses do not change across the handovers (to round-off).
TEST(TwoPhase, HandoverBetweenExplicitAndImplicitStagesLosesNothing) {
    MpmModel<2> m = saturated_block(1e-4, 0.0, 1.6);  // on a fixed base beside a roller
    apply_boundary<2>(m.grid, 1, 0, BoundaryKind::Fixed);
    apply_boundary<2>(m.grid, 0, 0, BoundaryKind::Roller);
    auto& p = m.particles;
    for (std::size_t i = 0; i < p.size(); ++i) p.v[2 * i + 1] = -0.01 * p.x[2 * i + 1];  // a squeeze
    std::vector<double> grains0(p.size()), mass0 = p.mass;
    for (std::size_t i = 0; i < p.size(); ++i) grains0[i] = (1.0 - p.porosity[i]) * p.volume[i];
    auto explicit_steps = [&m] {
        MpmSolver<2> s(m);
        const double dt = s.stable_time_step();
        for (int n = 0; n < 50; ++n) s.step(dt);
    };
    explicit_steps();
    double excess = 0.0;
    for (double x : p.pore_pressure) excess = std::max(excess, std::abs(x));
    EXPECT_GT(excess, 0.0);  // the squeeze left pressure for the pause to drain
    ConsolidationSolver<2> pause(m);
    for (int k = 0; k < 5; ++k) pause.step(0.01);
    explicit_steps();
    for (std::size_t i = 0; i < p.size(); ++i) {
        EXPECT_NEAR((1.0 - p.porosity[i]) * p.volume[i], grains0[i], 1e-13 * grains0[i]) << i;
        EXPECT_EQ(p.mass[i], mass0[i]);
    }
}

}  // namespace

// Cavitation: a saturated block under a free water surface torn open (its points moving
// apart, the water too slow to follow) draws its pore pressure down to the water's
// absolute zero, -(p_atm + rho_w g depth), and no further; without the limit it falls far
// below.
TEST(TwoPhase, CavitationHoldsTheWatersAbsolutePressureAtZero) {
    auto pulled = [](bool cavitation) {
        MpmModel<2> m = saturated_block(1e-9);  // all but undrained
        m.water.free_surface = true;
        m.water.level = 3.0;
        m.water.cavitation = cavitation;
        for (std::size_t i = 0; i < m.particles.size(); ++i)
            for (int d = 0; d < 2; ++d) {
                m.particles.v[2 * i + d] = 0.5 * (m.particles.x[2 * i + d] - 1.2);
                m.particles.w[2 * i + d] = m.particles.v[2 * i + d];
            }
        MpmSolver<2> s(m);
        const double dt = s.stable_time_step();
        double below = 0.0, at = 1e300;  // the most below the limit; the nearest to it, over the run
        for (int n = 0; n < 20; ++n) {
            s.step(dt);
            for (std::size_t i = 0; i < m.particles.size(); ++i) {
                const double limit = m.water.least_excess_pressure(m.particles.x[2 * i + 1]);
                below = std::max(below, limit - m.particles.pore_pressure[i]);
                at = std::min(at, std::abs(m.particles.pore_pressure[i] - limit));
            }
        }
        return std::make_pair(below, at);
    };
    const auto [below_free, at_free] = pulled(false);
    EXPECT_GT(below_free, 1.0e5);  // without the limit: far past it
    const auto [below, at] = pulled(true);
    EXPECT_EQ(below, 0.0);
    EXPECT_LT(at, 1e-6);  // some points sit on it
}
