// The Abaqus-UMAT interface, with a small Fortran UMAT written for the test
// (tests/umat/orthotropic_shear_umat.f90): the component order and engineering shears
// reach it as Abaqus sends them, its state variables and STRAN persist, a PNEWDT < 1 gets
// the increment again in pieces, load errors name what is missing, and an MPM case with the
// UMAT gives the same result as the built-in linear elastic model.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include "mpm/materials/user_material.hpp"

using namespace pilempm::mpm;

namespace {

#ifdef PILEMPM_TEST_UMAT
constexpr double kE = 50e6, kNu = 0.3, kG12 = 10e6, kG13 = 20e6, kG23 = 30e6, kLimit = 1e-3;

UserMaterialParameters test_umat() {
    UserMaterialParameters p;
    p.library = PILEMPM_TEST_UMAT;
    p.properties = {kE, kNu, kG12, kG13, kG23, kLimit};
    p.state_variables = 2;
    p.p_wave_modulus = kE * (1 - kNu) / ((1 + kNu) * (1 - 2 * kNu));
    p.shear_modulus = kG23;
    return p;
}
#endif

}  // namespace

TEST(UserMaterial, AbaqusOrderShearsStateAndStrainReachTheUmat) {
#ifndef PILEMPM_TEST_UMAT
    GTEST_SKIP() << "no Fortran compiler: the test UMAT was not built";
#else
    const UserMaterial m(test_umat());
    ASSERT_EQ(m.num_state(), 8);
    EXPECT_STREQ(m.state_name(0), "statev_1");
    EXPECT_STREQ(m.state_name(6), "umat_strain_13");
    double s[6] = {-100e3, -100e3, -200e3, 0, 0, 0}, st[8];
    m.initialise_state(s, st);
    // pilempm order: xx yy zz xy yz zx, engineering shear.
    const double de[6] = {1e-4, -2e-4, 3e-4, 1e-4, 2e-4, 3e-4};
    const int idx = 0;
    m.update(1, &idx, de, s, st, 8);
    const double lam = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), mu = kE / (2 * (1 + kNu));
    const double tr = de[0] + de[1] + de[2];
    EXPECT_NEAR(s[0], -100e3 + lam * tr + 2 * mu * de[0], 1e-6);
    EXPECT_NEAR(s[1], -100e3 + lam * tr + 2 * mu * de[1], 1e-6);
    EXPECT_NEAR(s[2], -200e3 + lam * tr + 2 * mu * de[2], 1e-6);
    EXPECT_NEAR(s[3], kG12 * de[3], 1e-6);  // xy = 12
    EXPECT_NEAR(s[4], kG23 * de[4], 1e-6);  // yz = 23
    EXPECT_NEAR(s[5], kG13 * de[5], 1e-6);  // zx = 13
    double norm = 0.0;
    for (double x : de) norm += x * x;
    EXPECT_NEAR(st[0], std::sqrt(norm), 1e-15);
    EXPECT_EQ(st[1], 1.0);
    m.update(1, &idx, de, s, st, 8);
    EXPECT_EQ(st[1], 2.0);
    EXPECT_NEAR(st[2 + 4], 2 * de[5], 1e-18);  // STRAN, Abaqus 13 = zx
    EXPECT_NEAR(st[2 + 5], 2 * de[4], 1e-18);  // STRAN, Abaqus 23 = yz
#endif
}

TEST(UserMaterial, PnewdtBelowOneSplitsTheIncrement) {
#ifndef PILEMPM_TEST_UMAT
    GTEST_SKIP() << "no Fortran compiler: the test UMAT was not built";
#else
    const UserMaterial m(test_umat());
    double s[6] = {0, 0, 0, 0, 0, 0}, st[8];
    m.initialise_state(s, st);
    const double de[6] = {0, 0, -3e-3, 0, 0, 0};  // 3x the UMAT's limit: needs 4 pieces
    const int idx = 0;
    m.update(1, &idx, de, s, st, 8);
    const double lam = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), mu = kE / (2 * (1 + kNu));
    EXPECT_NEAR(s[2], (lam + 2 * mu) * de[2], 1e-6);
    EXPECT_EQ(st[1], 4.0);  // only the accepted attempt's calls count
    EXPECT_NEAR(st[0], 3e-3, 1e-15);
    const double huge[6] = {0, 0, -3.0, 0, 0, 0};  // would need 3000 pieces
    EXPECT_THROW(m.update(1, &idx, huge, s, st, 8), std::runtime_error);
#endif
}

TEST(UserMaterial, LoadErrorsNameTheLibraryOrSymbol) {
    UserMaterialParameters p;
    p.library = "/nonexistent/libnothing.so";
    p.p_wave_modulus = p.shear_modulus = 1e6;
    try {
        UserMaterial m(p);
        FAIL() << "loaded a missing library";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/libnothing.so"), std::string::npos);
    }
#ifdef PILEMPM_TEST_UMAT
    p.library = PILEMPM_TEST_UMAT;
    p.symbol = "vumat_";
    try {
        UserMaterial m(p);
        FAIL() << "found a missing symbol";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("vumat_"), std::string::npos);
    }
#endif
}

// The elastic column of MPM verification 1 with the UMAT (isotropic shear moduli) in place
// of linear_elastic: the same stresses, and the case's own check passes.
TEST(UserMaterial, MpmColumnWithTheUmatMatchesTheBuiltInElasticModel) {
#ifndef PILEMPM_TEST_UMAT
    GTEST_SKIP() << "no Fortran compiler: the test UMAT was not built";
#else
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "pilempm-umat-column";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ifstream in(std::string(PILEMPM_SOURCE_DIR) + "/cases/verification/mpm-column-plane-strain.yaml");
    std::stringstream text;
    text << in.rdbuf();
    std::string yaml = text.str();
    const std::string elastic = "model: linear_elastic, density: 2000.0, youngs_modulus: 10.0e6, poisson_ratio: 0.3";
    const auto at = yaml.find(elastic);
    ASSERT_NE(at, std::string::npos);
    const double E = 10e6, nu = 0.3, G = E / (2 * (1 + nu)), M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
    std::ostringstream umat;
    umat.precision(17);
    umat << "model: umat, density: 2000.0, library: " << PILEMPM_TEST_UMAT << ", properties: [" << E << ", " << nu
         << ", " << G << ", " << G << ", " << G << ", 1.0], state_variables: 2, p_wave_modulus: " << M
         << ", shear_modulus: " << G << ", k0: " << nu / (1 - nu);
    yaml.replace(at, elastic.size(), umat.str());
    // The self-weight check on the case's own grid (the lateral-ratio closed form is for
    // linear_elastic materials).
    yaml = yaml.substr(0, yaml.find("verification:")) + "verification:\n  checks: [self_weight_stress]\n  surface: 10.0\n";
    std::ofstream(dir / "column-umat.yaml") << yaml;
    const std::string run = std::string(PILEMPM_EXECUTABLE) + " run " + (dir / "column-umat.yaml").string() +
                            " --out " + (dir / "out").string() + " --quiet";
    ASSERT_EQ(std::system(run.c_str()), 0);
    const std::string reference = std::string(PILEMPM_EXECUTABLE) + " run " + PILEMPM_SOURCE_DIR +
                                  "/cases/verification/mpm-column-plane-strain.yaml --out " + (dir / "ref").string() +
                                  " --quiet";
    ASSERT_EQ(std::system(reference.c_str()), 0);
    auto computed = [](const fs::path& f) {
        std::ifstream j(f);
        std::stringstream t;
        t << j.rdbuf();
        const std::string s = t.str();
        const auto k = s.find("\"computed\"");
        return k == std::string::npos ? NAN : std::stod(s.substr(s.find(':', k) + 1));
    };
    const double a = computed(dir / "out" / "verification.json"), b = computed(dir / "ref" / "verification.json");
    EXPECT_TRUE(std::isfinite(a));
    // Same physics, different round-off (the UMAT forms lambda and mu its own way); the
    // stage stops at an unbalanced ratio of 1e-6, so the results agree to about that.
    EXPECT_NEAR(a, b, 1e-6);
    fs::remove_all(dir);
#endif
}

// A case naming a library that is not there is bad input: exit status 2, file and key named.
TEST(UserMaterial, MissingLibraryInACaseIsBadInput) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "pilempm-umat-bad";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "bad.yaml") << "analysis: element_test\n"
                                       "material: {model: umat, library: libmissing.so, properties: [1.0],\n"
                                       "           p_wave_modulus: 1.0e6, shear_modulus: 1.0e5}\n"
                                       "initial_stress: {axial: 100.0e3}\n"
                                       "tests: [{type: isotropic, path: [200.0e3]}]\n";
    const std::string cmd = std::string(PILEMPM_EXECUTABLE) + " element-test " + (dir / "bad.yaml").string() +
                            " --out " + (dir / "out").string() + " 2>" + (dir / "err.txt").string() + " >/dev/null";
    const int raw = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(raw));
    EXPECT_EQ(WEXITSTATUS(raw), 2);
    std::ifstream e(dir / "err.txt");
    std::stringstream t;
    t << e.rdbuf();
    EXPECT_NE(t.str().find("material.library"), std::string::npos) << t.str();
    EXPECT_NE(t.str().find("libmissing.so"), std::string::npos) << t.str();
    EXPECT_FALSE(fs::exists(dir / "out"));
    fs::remove_all(dir);
}
