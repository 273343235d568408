// Mohr-Coulomb with non-associated flow and tension cut-off: closed-form checks of the
// principal-space return mapping. Tension positive throughout (voigt.hpp).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "mpm/materials/constitutive_model.hpp"
#include "mpm/materials/mohr_coulomb.hpp"

using namespace pilempm::mpm;

namespace {

using V6 = std::array<double, 6>;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDeg = std::numbers::pi / 180.0;

struct Point {
    V6 s{};
    double eps_p = 0.0;
};

void step(const ConstitutiveModel& m, Point& pt, const V6& de) {
    const int idx = 0;
    m.update(1, &idx, de.data(), pt.s.data(), &pt.eps_p, 1);
}

// Principal stresses, most tensile first.
std::array<double, 3> principal(const V6& s) {
    Eigen::Matrix3d m;
    m << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
    const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m).eigenvalues();
    return {ev(2), ev(1), ev(0)};
}

double max_abs(const V6& v) {
    double r = 0.0;
    for (double x : v) r = std::max(r, std::abs(x));
    return r;
}

// Lame constants of (E, nu).
double lame_lambda(double E, double nu) { return E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)); }
double lame_mu(double E, double nu) { return E / (2.0 * (1.0 + nu)); }

// Rotates a Voigt tensor, T' = R T R^T; `shear_factor` 0.5 for engineering strains.
V6 rotate(const V6& v, const Eigen::Matrix3d& R, double shear_factor) {
    Eigen::Matrix3d t;
    const double f = shear_factor;
    t << v[0], f * v[3], f * v[5], f * v[3], v[1], f * v[4], f * v[5], f * v[4], v[2];
    const Eigen::Matrix3d r = R * t * R.transpose();
    return {r(0, 0), r(1, 1), r(2, 2), r(0, 1) / f, r(1, 2) / f, r(0, 2) / f};
}

Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
    std::normal_distribution<double> n(0.0, 1.0);
    Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
    q.normalize();
    return q.toRotationMatrix();
}

}  // namespace

TEST(MohrCoulomb, ElasticRangeEqualsLinearElastic) {
    const MohrCoulomb mc(40e6, 0.3, 30.0, 5.0, 10e3, 5e3);
    const LinearElastic le(40e6, 0.3);
    Point a, b;
    a.s = b.s = {-150e3, -100e3, -120e3, 8e3, -3e3, 2e3};
    ASSERT_LT(mc.yield_function(a.s.data()), 0.0);
    const V6 de{1e-5, -2e-5, 0.5e-5, 3e-5, -1e-5, 2e-5};
    step(mc, a, de);
    step(le, b, de);
    for (int i = 0; i < 6; ++i) EXPECT_EQ(a.s[i], b.s[i]) << i;  // bitwise: same predictor
    EXPECT_EQ(a.eps_p, 0.0);
    EXPECT_EQ(mc.p_wave_modulus(), lame_lambda(40e6, 0.3) + 2.0 * lame_mu(40e6, 0.3));
    EXPECT_EQ(mc.shear_modulus(), lame_mu(40e6, 0.3));
    EXPECT_EQ(mc.num_state(), 1);
    EXPECT_STREQ(mc.state_name(0), "plastic_strain");
}

TEST(MohrCoulomb, RejectsBadParameters) {
    EXPECT_THROW(MohrCoulomb(-1.0, 0.3, 30, 0, 0, 0), std::invalid_argument);
    EXPECT_THROW(MohrCoulomb(1e7, 0.5, 30, 0, 0, 0), std::invalid_argument);
    EXPECT_THROW(MohrCoulomb(1e7, 0.3, 30, 35, 0, 0), std::invalid_argument);  // psi > phi
    EXPECT_THROW(MohrCoulomb(1e7, 0.3, 0, 0, 0, kInf), std::invalid_argument);  // no strength
    EXPECT_NO_THROW(MohrCoulomb(1e7, 0.3, 0, 0, 100e3, kInf));                 // Tresca
}

// Drained triaxial test on the axis y with the radial stress held at the confining value by
// Newton iteration on the lateral strain, to failure. Compression (axial loading) ends on
// the triaxial-compression edge, extension (axial unloading) on the triaxial-extension
// edge. Compression positive, sigma1' is the major principal stress and at failure
// (sigma1' + a) / (sigma3' + a) = (1 + sin phi) / (1 - sin phi), a = c cot phi.
namespace {
void drained_triaxial(const MohrCoulomb& mc, double confining, double de_axial, int steps,
                      Point& pt) {
    pt = Point{};
    pt.s = {-confining, -confining, -confining, 0, 0, 0};
    auto radial_error = [&](double e, Point& out) {
        out = pt;
        step(mc, out, {e, de_axial, e, 0, 0, 0});
        return out.s[0] + confining;
    };
    for (int n = 0; n < steps; ++n) {
        Point trial, probe;
        double e = 0.0, g = radial_error(e, trial);
        for (int it = 0; it < 50 && std::abs(g) >= 1e-9 * confining; ++it) {
            const double h = 1e-9;
            e -= g * h / (radial_error(e + h, probe) - g);
            g = radial_error(e, trial);
        }
        ASSERT_LT(std::abs(g), 1e-9 * confining) << "step " << n;
        pt = trial;
        ASSERT_NEAR(pt.s[2], pt.s[0], 1e-9 * confining);
    }
}
}  // namespace

TEST(MohrCoulomb, DrainedTriaxialReachesMohrCoulombFailure) {
    const double E = 20e6, nu = 0.3, phi = 30.0, c = 10e3, confining = 100e3;
    const MohrCoulomb mc(E, nu, phi, 5.0, c, kInf);
    const double s = std::sin(phi * kDeg), a = c / std::tan(phi * kDeg);
    for (const bool compression : {true, false}) {
        Point pt;
        drained_triaxial(mc, confining, compression ? -1e-4 : 1e-4, 300, pt);
        const double axial = -pt.s[1], radial = -pt.s[0];
        const double sigma1 = compression ? axial : radial, sigma3 = compression ? radial : axial;
        EXPECT_NEAR((sigma1 + a) / (sigma3 + a) / ((1.0 + s) / (1.0 - s)), 1.0, 1e-6) << compression;
        EXPECT_GT(pt.eps_p, 0.0);
        if (compression) {  // q_f = 6 (c cos phi + p' sin phi) / (3 - sin phi)
            const double p = (sigma1 + 2.0 * sigma3) / 3.0, q = sigma1 - sigma3;
            EXPECT_NEAR(q / (6.0 * (c * std::cos(phi * kDeg) + p * s) / (3.0 - s)), 1.0, 1e-6);
        }
    }
}

// Shearing in the x-z plane with y fixed keeps s_yy strictly between the other two, so the
// point yields on the main MC plane (no edge). There the plastic strain increment is
// along the potential's gradient: d_eps_x / d_eps_z = -(1 + sin psi) / (1 - sin psi)
// (compression positive: d_eps3 / d_eps1 with 1 the major principal) and d_eps_y = 0.
TEST(MohrCoulomb, NonAssociatedFlowFollowsDilationAngle) {
    const double E = 30e6, nu = 0.25;
    for (double psi : {0.0, 10.0, 30.0}) {
        const MohrCoulomb mc(E, nu, 30.0, psi, 5e3, kInf);
        Point pt;
        pt.s = {-80e3, -120e3, -200e3, 0, 0, 0};
        const V6 de{2e-5, 0.0, -2e-5, 0, 0, 0};
        int plastic_steps = 0;
        for (int n = 0; n < 400 && plastic_steps < 5; ++n) {
            const Point before = pt;
            step(mc, pt, de);
            if (pt.eps_p == before.eps_p) continue;
            if (before.eps_p == 0.0) continue;  // first plastic step starts inside
            ++plastic_steps;
            ASSERT_GT(pt.s[0], pt.s[1] + 1e3);
            ASSERT_GT(pt.s[1], pt.s[2] + 1e3);
            double dep[3];
            double ds[3], tr = 0.0;
            for (int i = 0; i < 3; ++i) tr += ds[i] = pt.s[i] - before.s[i];
            for (int i = 0; i < 3; ++i) dep[i] = de[i] - ((1.0 + nu) * ds[i] - nu * tr) / E;
            const double sp = std::sin(psi * kDeg);
            EXPECT_NEAR(dep[0] / dep[2], -(1.0 + sp) / (1.0 - sp), 1e-6) << "psi " << psi;
            EXPECT_NEAR(dep[1] / dep[0], 0.0, 1e-6) << "psi " << psi;
            // Plastic dilatancy (expansion positive) over plastic shear d_eps1 - d_eps3.
            EXPECT_NEAR((dep[0] + dep[1] + dep[2]) / (dep[0] - dep[2]), sp, 1e-6);
        }
        EXPECT_EQ(plastic_steps, 5) << "psi " << psi;
    }
}

// Undrained clay as Tresca (phi = 0, c = 100 kPa): plane strain simple shear caps the
// shear stress at c and, without volume change, leaves the mean stress alone.
TEST(MohrCoulomb, TrescaSimpleShearCapsAtCohesion) {
    const double c = 100e3;
    const MohrCoulomb mc(30e6, 0.45, 0.0, 0.0, c, kInf);
    Point pt;
    pt.s = {-200e3, -200e3, -200e3, 0, 0, 0};
    for (int n = 0; n < 100; ++n) step(mc, pt, {0, 0, 0, 1e-3, 0, 0});
    EXPECT_NEAR(pt.s[3], c, 1e-8 * c);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(pt.s[i], -200e3, 1e-8 * c);
    EXPECT_NEAR(pt.s[4], 0.0, 1e-8 * c);
    EXPECT_NEAR(pt.s[5], 0.0, 1e-8 * c);
    // Plastic engineering shear 0.1 - c/G; eps_p = sqrt(2/3 de:de) = gamma_p / sqrt(3).
    const double gamma_p = 0.1 - c / mc.shear_modulus();
    EXPECT_NEAR(pt.eps_p, gamma_p / std::sqrt(3.0), 1e-9 * gamma_p);
    // Reversed shear unloads elastically, then caps at -c.
    Point back = pt;
    step(mc, back, {0, 0, 0, -1e-3, 0, 0});
    EXPECT_NEAR(back.s[3], c - mc.shear_modulus() * 1e-3, 1e-8 * c);
    EXPECT_EQ(back.eps_p, pt.eps_p);
    for (int n = 0; n < 100; ++n) step(mc, back, {0, 0, 0, -1e-3, 0, 0});
    EXPECT_NEAR(back.s[3], -c, 1e-8 * c);
}

TEST(MohrCoulomb, TensionCutOffAndApex) {
    const double c = 10e3, phi = 30.0, apex = c / std::tan(phi * kDeg);
    const V6 pull{1e-2, 1e-2, 1e-2, 0, 0, 0};
    const V6 pull_uneven{1e-2, 3e-2, 2e-2, 1e-2, -2e-2, 0.5e-2};
    {  // cut-off below the apex: isotropic pull lands on s1 = s2 = s3 = t
        const double t = 2e3;
        const MohrCoulomb mc(50e6, 0.3, phi, 5.0, c, t);
        EXPECT_EQ(mc.tension_cutoff(), t);
        Point pt;
        step(mc, pt, pull);
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(pt.s[i], t, 1e-9 * t);
        for (int i = 3; i < 6; ++i) EXPECT_NEAR(pt.s[i], 0.0, 1e-9 * t);
        Point un;
        un.s = {-50e3, -60e3, -40e3, 0, 0, 0};
        step(mc, un, {5e-2, 0, 0, 0, 0, 0});  // uniaxial tensile strain
        EXPECT_LE(principal(un.s)[0], t * (1.0 + 1e-12));
        EXPECT_LE(mc.yield_function(un.s.data()), 1e-9 * max_abs(un.s));
    }
    for (double psi : {0.0, 10.0, 30.0}) {  // cut-off above the apex: clamped, apex return
        const MohrCoulomb mc(50e6, 0.3, phi, psi, c, 1e9);
        EXPECT_NEAR(mc.tension_cutoff(), apex, 1e-12 * apex);
        for (const V6& de : {pull, pull_uneven}) {
            Point pt;
            pt.s = {-100e3, -30e3, -60e3, 10e3, 0, -5e3};
            step(mc, pt, de);
            for (int i = 0; i < 3; ++i) EXPECT_NEAR(pt.s[i], apex, 1e-9 * apex) << psi;
            for (int i = 3; i < 6; ++i) EXPECT_NEAR(pt.s[i], 0.0, 1e-9 * apex) << psi;
            EXPECT_GT(pt.eps_p, 0.0);
        }
    }
    {  // cohesionless sand: the apex is the origin
        const MohrCoulomb sand(50e6, 0.3, 35.0, 0.0, 0.0, 0.0);
        Point pt;
        pt.s = {-10e3, -20e3, -15e3, 1e3, 2e3, 3e3};
        step(sand, pt, pull_uneven);
        for (int i = 0; i < 6; ++i) EXPECT_NEAR(pt.s[i], 0.0, 1e-9) << i;
        Point zero;  // zero stress and zero increment stays put
        step(sand, zero, {0, 0, 0, 0, 0, 0});
        for (int i = 0; i < 6; ++i) EXPECT_EQ(zero.s[i], 0.0);
    }
}

// Rotating stress and strain increment by the same rigid rotation rotates the result.
TEST(MohrCoulomb, InvariantUnderRigidRotation) {
    const std::vector<MohrCoulomb> models{{50e6, 0.3, 30.0, 5.0, 10e3, 3e3},
                                          {50e6, 0.3, 35.0, 0.0, 0.0, 0.0},
                                          {30e6, 0.45, 0.0, 0.0, 100e3, kInf}};
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int plastic = 0;
    for (int n = 0; n < 300; ++n) {
        const MohrCoulomb& mc = models[n % models.size()];
        Point a;
        for (int i = 0; i < 3; ++i) a.s[i] = -100e3 + 80e3 * u(rng);
        for (int i = 3; i < 6; ++i) a.s[i] = 40e3 * u(rng);
        V6 de;
        for (int i = 0; i < 6; ++i) de[i] = 5e-3 * u(rng);
        const Eigen::Matrix3d R = random_rotation(rng);
        Point b;
        b.s = rotate(a.s, R, 1.0);
        step(mc, a, de);
        step(mc, b, rotate(de, R, 0.5));
        const V6 back = rotate(b.s, R.transpose(), 1.0);
        const double scale = max_abs(a.s) + 10e3;
        for (int i = 0; i < 6; ++i) EXPECT_NEAR(back[i], a.s[i], 1e-9 * scale) << n << " " << i;
        EXPECT_NEAR(b.eps_p, a.eps_p, 1e-9 * a.eps_p);
        plastic += a.eps_p > 0.0;
    }
    EXPECT_GT(plastic, 100);  // the check covered returns, not just elastic steps
}

// Random states (general, hydrostatic, two equal principal stresses, zero, far outside the
// surface) and increments from zero to huge: never NaN, always admissible.
TEST(MohrCoulomb, RandomStatesStayAdmissible) {
    const std::vector<MohrCoulomb> models{
        {50e6, 0.3, 30.0, 5.0, 10e3, 3e3},     {50e6, 0.3, 35.0, 5.0, 0.0, 0.0},
        {30e6, 0.49, 0.0, 0.0, 100e3, kInf},   {30e6, 0.3, 0.0, 0.0, 50e3, 20e3},
        {20e6, 0.2, 25.0, 25.0, 20e3, 1e9},    {80e6, 0.35, 40.0, 0.0, 5e3, kInf},
        {80e6, -0.2, 20.0, 10.0, 5e3, -1e3}};
    std::mt19937_64 rng(20240611);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_int_distribution<int> pick(0, 4);
    int plastic = 0;
    for (int n = 0; n < 10000; ++n) {
        const MohrCoulomb& mc = models[n % models.size()];
        // Principal values by kind, then a random orientation.
        const double level = std::pow(10.0, 3.0 + 3.0 * std::abs(u(rng)));  // 1 kPa .. 1 MPa
        std::array<double, 3> sp{level * u(rng), level * u(rng), level * u(rng)};
        switch (pick(rng)) {
            case 0: sp = {sp[0], sp[0], sp[0]}; break;  // hydrostatic, either sign
            case 1: sp[1] = sp[0]; break;               // two equal
            case 2: sp = {0.0, 0.0, 0.0}; break;
            default: break;
        }
        V6 s{sp[0], sp[1], sp[2], 0, 0, 0};
        if (n % 3 != 0) s = rotate(s, random_rotation(rng), 1.0);
        const double size = n % 11 == 0 ? 0.0 : std::pow(10.0, -7.0 + 7.0 * std::abs(u(rng)));
        V6 de;
        for (int i = 0; i < 6; ++i) de[i] = size * u(rng);
        if (pick(rng) == 0) de = {size * u(rng), de[0], de[0], 0, 0, 0};  // volumetric
        if (pick(rng) == 0) std::fill(de.begin() + 1, de.begin() + 3, de[0]);
        Point pt;
        pt.s = s;
        pt.eps_p = 0.25;
        step(mc, pt, de);
        ASSERT_TRUE(std::isfinite(pt.eps_p)) << n;
        ASSERT_GE(pt.eps_p, 0.25) << n;
        for (int i = 0; i < 6; ++i) ASSERT_TRUE(std::isfinite(pt.s[i])) << n;
        const double tol = 1e-13 * (max_abs(pt.s) + 1e3);
        const double f = mc.yield_function(pt.s.data());
        ASSERT_LE(f, tol) << n;
        ASSERT_LE(principal(pt.s)[0], mc.tension_cutoff() + tol) << n;
        if (pt.eps_p > 0.25) {
            ++plastic;
            ASSERT_GE(f, -tol) << n;  // a return lands on the surface, not inside it
        }
    }
    EXPECT_GT(plastic, 3000);
}

// Increments of strain 10 (trial stresses ~1e4 times the strength) still land on the
// surface to rounding of the returned stress, not of the trial.
TEST(MohrCoulomb, HugeIncrementsLandOnTheSurface) {
    const std::vector<MohrCoulomb> models{{50e6, 0.3, 30.0, 5.0, 10e3, 3e3},
                                          {30e6, 0.3, 0.0, 0.0, 50e3, 20e3},
                                          {80e6, 0.35, 40.0, 0.0, 5e3, kInf}};
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int plastic = 0;
    for (int n = 0; n < 3000; ++n) {
        const MohrCoulomb& mc = models[n % models.size()];
        Point pt;
        pt.s = {-100e3, -100e3, -100e3, 0, 0, 0};
        V6 de;
        for (double& x : de) x = 10.0 * u(rng);
        step(mc, pt, de);
        if (pt.eps_p == 0.0) continue;  // strong compression can stay inside the cone
        ++plastic;
        EXPECT_NEAR(mc.yield_function(pt.s.data()), 0.0, 1e-13 * (max_abs(pt.s) + 1e3)) << n;
    }
    EXPECT_GT(plastic, 2500);
}

// With psi = phi (and the associated cut-off) the return is the closest point of the
// elastic domain in the complementary-energy norm, which every region must honour:
// (s_trial - s) : C : (tau - s) <= 0 for every admissible tau.
TEST(MohrCoulomb, AssociatedReturnIsClosestPointProjection) {
    const double E = 20e6, nu = 0.2;
    const std::vector<MohrCoulomb> models{{E, nu, 30.0, 30.0, 10e3, 3e3},
                                          {E, nu, 25.0, 25.0, 20e3, kInf},
                                          {E, nu, 0.0, 0.0, 50e3, 20e3}};
    auto compliance = [&](const V6& s) {  // strain, engineering shear
        const double tr = s[0] + s[1] + s[2];
        V6 e;
        for (int i = 0; i < 3; ++i) e[i] = ((1.0 + nu) * s[i] - nu * tr) / E;
        for (int i = 3; i < 6; ++i) e[i] = 2.0 * (1.0 + nu) * s[i] / E;
        return e;
    };
    auto energy_dot = [&](const V6& a, const V6& b) {
        const V6 ca = compliance(a);
        double r = 0.0;
        for (int i = 0; i < 6; ++i) r += ca[i] * b[i];
        return r;
    };
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-6.0, 4.0);
    // Principal values spread over all regions (scale ~ the strength), random orientation.
    auto random_stress = [&](double scale) {
        return rotate({scale * u(rng), scale * u(rng), scale * u(rng), 0, 0, 0}, random_rotation(rng), 1.0);
    };
    const double scales[] = {10e3, 15e3, 30e3};
    for (std::size_t m = 0; m < models.size(); ++m) {
        const MohrCoulomb& mc = models[m];
        std::vector<V6> admissible;  // returns of random states: admissible, all regions
        for (int n = 0; n < 600; ++n) {
            Point pt;
            pt.s = random_stress(scales[m]);
            step(mc, pt, {});
            admissible.push_back(pt.s);
        }
        int plastic = 0;
        for (int n = 0; n < 600; ++n) {
            Point pt;
            pt.s = random_stress(scales[m]);
            const V6 trial = pt.s;
            step(mc, pt, {});
            if (pt.eps_p == 0.0) continue;
            ++plastic;
            V6 r;
            for (int i = 0; i < 6; ++i) r[i] = trial[i] - pt.s[i];
            for (const V6& tau : admissible) {
                V6 d;
                for (int i = 0; i < 6; ++i) d[i] = tau[i] - pt.s[i];
                // Floor on |d|: tau may be the returned point itself (a shared corner).
                const double dd = energy_dot(d, d) + scales[m] * scales[m] / E;
                const double norm = std::sqrt(energy_dot(r, r) * dd);
                ASSERT_LE(energy_dot(r, d), 1e-9 * norm) << m << " " << n;
            }
        }
        EXPECT_GT(plastic, 200);
    }
}
