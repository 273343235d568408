// The reference solution of waves in a saturated half-space (Laplace domain, inverted
// numerically) against what is known in closed form: the undrained wave at low permeability
// (one undistorted pulse at c_u carrying B = (K_w/n) / (M + K_w/n) of the load in the water),
// Terzaghi's half-space consolidation p = u0 erf(z / 2 sqrt(c_v t)) long after a step load,
// the drag-free fast wave's arrival at the speed of pore_water.hpp's closed form; and the
// series converged in its number of terms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mpm/materials/pore_water.hpp"
#include "mpm/verification/dynamic_poroelastic_column.hpp"

using namespace pilempm::mpm;

namespace {

constexpr double kGravity = 9.81;

PoroelasticColumn sand(double hydraulic_conductivity) {
    PoroelasticColumn c;
    c.p_wave_modulus = 100.0e6;
    c.porosity = 0.4;
    c.solid_density_partial = 0.6 * 2650.0;
    c.water_density = 1000.0;
    c.water_bulk_modulus = 2.2e9;
    c.darcy_resistance = hydraulic_conductivity > 0.0 ? c.water_density * kGravity / hydraulic_conductivity : 0.0;
    return c;
}

double sine_squared(double t, double duration) {
    if (t <= 0.0 || t >= duration) return 0.0;
    const double s = std::sin(std::numbers::pi * t / duration);
    return s * s;
}

std::vector<double> sample_times(double end, int count) {
    std::vector<double> t(count);
    for (int j = 0; j < count; ++j) t[j] = end * (j + 1) / count;
    return t;
}

}  // namespace

TEST(PoroelasticColumn, LowPermeabilityIsTheUndrainedWave) {
    const auto c = sand(1e-10);
    const ColumnLoad load{10.0e3, 0.01, ColumnPulse::SineSquared};
    const double Q = c.water_bulk_modulus / c.porosity, M = c.p_wave_modulus;
    const double rho = c.solid_density_partial + c.porosity * c.water_density;
    const double cu = std::sqrt((M + Q) / rho), B = Q / (M + Q);
    const double depth = 5.0;
    const auto t = sample_times(0.02, 400);
    const auto r = poroelastic_column_history(c, load, depth, t);
    double worst = 0.0;
    for (std::size_t j = 0; j < t.size(); ++j) {
        const double f = load.pressure * sine_squared(t[j] - depth / cu, load.duration);
        worst = std::max(worst, std::abs(r[j].excess_pore_pressure - B * f));
        worst = std::max(worst, std::abs(r[j].effective_stress + (1.0 - B) * f));
    }
    EXPECT_LT(worst / load.pressure, 1e-3);
}

TEST(PoroelasticColumn, LongAfterAStepItConsolidatesAsTerzaghisHalfSpace) {
    const auto c = sand(1e-3);
    const ColumnLoad load{10.0e3, 0.0, ColumnPulse::Rectangular};  // held from t = 0
    const double Q = c.water_bulk_modulus / c.porosity, M = c.p_wave_modulus;
    const double u0 = load.pressure * Q / (M + Q);
    const double cv = 1.0 / (c.darcy_resistance * (1.0 / M + c.porosity / c.water_bulk_modulus));
    const std::vector<double> t = {0.1, 0.2, 0.4};
    for (const double depth : {0.5, 1.5, 3.0}) {
        const auto r = poroelastic_column_history(c, load, depth, t);
        for (std::size_t j = 0; j < t.size(); ++j) {
            const double p = u0 * std::erf(depth / (2.0 * std::sqrt(cv * t[j])));
            EXPECT_NEAR(r[j].excess_pore_pressure / u0, p / u0, 5e-3) << "z = " << depth << ", t = " << t[j];
            // The waves have gone: the total stress carries the load at every depth.
            EXPECT_NEAR((r[j].effective_stress - r[j].excess_pore_pressure) / load.pressure, -1.0, 5e-3);
        }
    }
}

TEST(PoroelasticColumn, WithoutDragTheFastWaveArrivesAtTheClosedFormSpeed) {
    const auto c = sand(0.0);
    const ColumnLoad load{10.0e3, 0.004, ColumnPulse::SineSquared};
    PoreWater water;
    const double fast = saturated_wave_speeds(c.p_wave_modulus, c.porosity, c.solid_density_partial, water).fastest;
    const double depth = 10.0, arrival = depth / fast;
    const auto t = sample_times(0.012, 1200);  // the slow wave (~250 m/s) is still far away
    const auto r = poroelastic_column_history(c, load, depth, t);
    double before = 0.0, peak = 0.0, peak_at = 0.0;
    for (std::size_t j = 0; j < t.size(); ++j) {
        const double p = std::abs(r[j].excess_pore_pressure);
        if (t[j] < arrival - 1e-4) before = std::max(before, p);
        if (p > peak) peak = p, peak_at = t[j];
    }
    EXPECT_LT(before / load.pressure, 1e-4);
    EXPECT_NEAR(peak_at, arrival + 0.5 * load.duration, 2e-5);  // the pulse's centre, undistorted
}

TEST(PoroelasticColumn, TheSeriesHasConvergedInItsTerms) {
    const auto c = sand(1e-2);
    const ColumnLoad load{10.0e3, 0.01, ColumnPulse::SineSquared};
    const auto t = sample_times(0.04, 200);
    LaplaceInversion fewer;
    fewer.terms /= 2;
    const auto a = poroelastic_column_history(c, load, 2.0, t, fewer);
    const auto b = poroelastic_column_history(c, load, 2.0, t);
    double worst = 0.0;
    for (std::size_t j = 0; j < t.size(); ++j)
        worst = std::max({worst, std::abs(a[j].excess_pore_pressure - b[j].excess_pore_pressure),
                          std::abs(a[j].effective_stress - b[j].effective_stress)});
    EXPECT_LT(worst / load.pressure, 1e-5);
}
