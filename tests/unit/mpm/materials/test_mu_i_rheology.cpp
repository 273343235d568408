// The mu(I) granular rheology against its closed forms: steady simple shear at a given
// rate carries tau = mu(I) p with I = gdot d / sqrt(p / rho_s); the quasi-static limit is
// mu_s; below yield it is linear elasticity; in tension the grains separate.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/cases/material_input.hpp"
#include "mpm/materials/constitutive_model.hpp"
#include "mpm/materials/mu_i_rheology.hpp"

using namespace pilempm::mpm;

namespace {

const MuIParameters kBeads{};  // Jop et al. (2006) glass beads, E = 5 MPa

// Shears a point at pressure p by dgamma (engineering) in each of `steps` steps of dt
// (isochoric, so p stays); returns tau = sigma_xy; state out.
double steady_shear(MuIRheology& model, double p, double dgamma, double dt, int steps, double* state) {
    double s[6] = {-p, -p, -p, 0.0, 0.0, 0.0};
    state[0] = state[1] = 0.0;
    model.set_time(0.0, dt);
    const double de[6] = {0.0, 0.0, 0.0, dgamma, 0.0, 0.0};
    const int point = 0;
    for (int n = 0; n < steps; ++n) model.update(1, &point, de, s, state, 2);
    EXPECT_NEAR(-(s[0] + s[1] + s[2]) / 3.0, p, 1e-9 * p);  // plastic flow is isochoric
    return s[3];
}

}  // namespace

TEST(MuIRheology, FrictionLaw) {
    const MuIRheology m(kBeads);
    EXPECT_DOUBLE_EQ(m.friction(0.0), kBeads.mu_s);
    EXPECT_NEAR(m.friction(kBeads.I_0), 0.5 * (kBeads.mu_s + kBeads.mu_2), 1e-15);
    EXPECT_NEAR(m.friction(1e12), kBeads.mu_2, 1e-12);
    // I = gdot d / sqrt(p / rho_s): 100 1/s, 0.5 mm, 2450 Pa of 2450 kg/m^3 grains -> 0.05.
    EXPECT_NEAR(m.inertial_number(100.0, 2450.0), 0.05, 1e-15);
}

// Four decades of inertial number, 0.0055 to 5.5: steady tau / p equals mu(I) to 1e-9.
TEST(MuIRheology, SteadySimpleShearCarriesMuOfI) {
    const double p = 2e3;
    for (double gdot : {10.0, 100.0, 1e3, 1e4}) {
        MuIRheology m(kBeads);
        const double dt = 2e-6 / gdot;  // 2e-6 of shear per step
        double state[2];
        const double tau = steady_shear(m, p, gdot * dt, dt, 20000, state);
        const double I = m.inertial_number(gdot, p);
        EXPECT_NEAR(tau / p, m.friction(I), 1e-9) << "gdot " << gdot;
        EXPECT_NEAR(state[1], I, 1e-9 * I) << "gdot " << gdot;
        EXPECT_GT(m.friction(I), kBeads.mu_s + 0.004);  // the rate term is really there
    }
}

// Without a time step, or with grains so fine that I -> 0, the flow is quasi-static at mu_s.
TEST(MuIRheology, QuasiStaticLimitIsMuS) {
    const double p = 5e3;
    MuIRheology m(kBeads);
    double state[2];
    EXPECT_NEAR(steady_shear(m, p, 2e-6, 0.0, 3000, state) / p, kBeads.mu_s, 1e-12);
    MuIParameters fine = kBeads;
    fine.grain_diameter = 1e-9;
    MuIRheology f(fine);
    EXPECT_NEAR(steady_shear(f, p, 1e-4, 1e-6, 3000, state) / p, kBeads.mu_s, 1e-6);
}

TEST(MuIRheology, ElasticBelowYieldAndSeparatedInTension) {
    const MuIRheology m(kBeads);
    const LinearElastic le(kBeads.youngs_modulus, kBeads.poisson_ratio);
    const int point = 0;
    double a[6] = {-10e3, -8e3, -9e3, 500.0, -300.0, 200.0}, b[6];
    for (int i = 0; i < 6; ++i) b[i] = a[i];
    const double de[6] = {-1e-5, 2e-5, 0.5e-5, 3e-5, -1e-5, 2e-5};
    double state[2] = {0.0, 0.0};
    m.update(1, &point, de, a, state, 2);
    le.update(1, &point, de, b, nullptr, 0);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(a[i], b[i], 1e-9) << i;
    EXPECT_EQ(state[0], 0.0);
    double s[6] = {-100.0, -100.0, -100.0, 10.0, 0.0, 0.0};
    const double pull[6] = {1e-3, 1e-3, 1e-3, 0.0, 0.0, 0.0};
    m.update(1, &point, pull, s, state, 2);
    for (double x : s) EXPECT_EQ(x, 0.0);
}

// Case-file keys: defaults are the glass beads; a mu_2 below mu_s names its key.
TEST(MuIRheology, MaterialKeysAreValidated) {
    auto read = [](const std::string& text) {
        return pilempm::io::read_material(pilempm::io::MapReader(YAML::Load(text), "material", "case.yaml"), false);
    };
    const std::string base = "{model: mu_i_rheology, youngs_modulus: 5.0e6, poisson_ratio: 0.3";
    const auto m = read(base + "}");
    EXPECT_EQ(m.mu_i.mu_s, kBeads.mu_s);
    EXPECT_NEAR(m.friction_angle, 20.9, 0.05);  // atan(mu_s), for K0
    EXPECT_EQ(pilempm::mpm::make_constitutive_model(m)->name(), "mu_i_rheology");
    EXPECT_EQ(read(base + ", grain_diameter: 1.0e-3}").mu_i.grain_diameter, 1e-3);
    try {
        read(base + ", mu_s: 0.5, mu_2: 0.4}");
        ADD_FAILURE() << "mu_2 < mu_s accepted";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("mu_2"), std::string::npos) << e.what();
    }
}
