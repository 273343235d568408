// Element-test cases: bad input is refused with file, line and key, exit status 2, and
// the output folder untouched; `element-test` refuses other analyses.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "mpm/materials/constitutive_model.hpp"
#include "mpm/materials/element_test.hpp"

namespace fs = std::filesystem;

namespace {

const std::string kCase = R"(analysis: element_test
material: {model: modified_cam_clay, lambda: 0.15, kappa: 0.013, friction_angle: 35.0,
           poisson_ratio: 0.3, void_ratio: 0.62}
initial_stress: {axial: 100.0e3}
tests:
  - {type: triaxial_undrained, path: [0.01], steps_per_leg: 50}
output: {plots: false}
)";

struct Result {
    int status;
    std::string err;
};

Result run_pilempm(const std::string& args) {
    const std::string cmd = std::string(PILEMPM_EXECUTABLE) + " " + args + " 2>&1 >/dev/null";
    std::string out;
    FILE* pipe = popen(cmd.c_str(), "r");
    std::array<char, 512> buf{};
    while (fgets(buf.data(), buf.size(), pipe)) out += buf.data();
    const int st = pclose(pipe);
    return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, out};
}

fs::path write_case(const fs::path& dir, const std::string& name, const std::string& text) {
    const fs::path f = dir / name;
    std::ofstream(f) << text;
    return f;
}

class ElementTestCase : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("pilempm-element-test-" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

}  // namespace

TEST_F(ElementTestCase, RunsAndWritesThePath) {
    const fs::path f = write_case(dir_, "ok.yaml", kCase);
    EXPECT_EQ(run_pilempm("element-test " + f.string() + " --out " + (dir_ / "out").string() + " --quiet").status, 0);
    EXPECT_TRUE(fs::exists(dir_ / "out" / "triaxial_undrained_1.csv"));
    EXPECT_TRUE(fs::exists(dir_ / "out" / "summary.json"));
}

TEST_F(ElementTestCase, BadParameterNamesFileLineAndKey) {
    std::string text = kCase;
    text.replace(text.find("kappa: 0.013"), 12, "kappa: 0.200");  // above lambda
    const fs::path f = write_case(dir_, "bad.yaml", text);
    fs::create_directories(dir_ / "out");
    std::ofstream(dir_ / "out" / "keep.txt") << "old";
    const Result r = run_pilempm("element-test " + f.string() + " --out " + (dir_ / "out").string());
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("bad.yaml:2"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("material.kappa"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(dir_ / "out" / "keep.txt"));
}

TEST_F(ElementTestCase, UnknownTestTypeAndOtherAnalysesAreRefused) {
    std::string text = kCase;
    text.replace(text.find("triaxial_undrained"), 18, "triaxial_sideways");
    const Result r = run_pilempm("element-test " + write_case(dir_, "type.yaml", text).string());
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("tests[0].type"), std::string::npos) << r.err;
    const Result other = run_pilempm("element-test " + std::string(PILEMPM_SOURCE_DIR) +
                                 "/cases/verification/mpm-k0-cam-clay.yaml");
    EXPECT_EQ(other.status, 2);
    EXPECT_NE(other.err.find("analysis: mpm"), std::string::npos) << other.err;
}

// Stress-controlled triaxial legs (control: stress, deviator targets) on linear elasticity:
// drained, eps_a = q / E; undrained (constant volume), eps_a = q / (3 G). Cyclic legs come
// back to their start.
TEST(ElementTestDriver, DeviatorControlledTriaxialMatchesElasticity) {
    using namespace pilempm::mpm;
    const double E = 30e6, nu = 0.25, G = E / (2 * (1 + nu));
    const LinearElastic model(E, nu);
    const double s0[6] = {-100e3, -100e3, -100e3, 0, 0, 0};
    for (auto lateral : {ElementLeg::LateralStress, ElementLeg::Undrained}) {
        ElementTest test(model, s0, {});
        std::vector<ElementRecord> path;
        for (double q : {60e3, -40e3, 60e3}) {
            ElementLeg leg;
            leg.axial = ElementLeg::Deviator;
            leg.lateral = lateral;
            leg.axial_target = q;
            leg.steps = 10;
            test.run(leg, path);
        }
        const double stiffness = lateral == ElementLeg::LateralStress ? E : 3.0 * G;
        EXPECT_NEAR(path.back().q, 60e3, 1e-3);
        EXPECT_NEAR(path.back().axial_strain, 60e3 / stiffness, 1e-12);
        EXPECT_NEAR(path[9].axial_strain, 60e3 / stiffness, 1e-12);
        EXPECT_NEAR(path[19].axial_strain, -40e3 / stiffness, 1e-12);
        if (lateral == ElementLeg::Undrained) EXPECT_NEAR(path.back().volumetric_strain, 0.0, 1e-14);
    }
}
