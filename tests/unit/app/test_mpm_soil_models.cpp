// Every soil model is usable in an MPM case: a small sand column released on a rough base
// (plane strain, APIC, dynamic) collapses with each model, through points at zero stress at
// the free surface and large strains at the toe, without NaN or a failed stress update,
// and spreads.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {

const char* kColumn = R"(title: "column collapse with %MODEL%"
analysis: mpm
dimension: 2
geometry: plane_strain
grid: {origin: [0.0, 0.0], size: [0.5, 0.24], cells: [25, 12]}
shape_function: gimp
particles_per_cell: 2
velocity_transfer: apic
materials:
  - {name: sand, density: 1700.0, %MATERIAL%}
regions:
  - {material: sand, box: {min: [0.0, 0.0], max: [0.1, 0.2]}}
boundaries:
  - {plane: x_min, type: roller}
  - {plane: y_min, type: frictional, friction: 0.577}
initial_stress: {type: k0, surface: 0.2}
stages:
  - {name: collapse, type: dynamic, duration: 0.25}
output: {plots: false, snapshot_interval: 1.0}
verification: {checks: [granular_runout], initial_width: 0.1, height: 0.2}
)";

struct Material {
    const char* model;
    const char* keys;
};

const Material kMaterials[] = {
    {"mohr_coulomb", "model: mohr_coulomb, youngs_modulus: 5.0e6, poisson_ratio: 0.3, friction_angle: 30.0"},
    {"modified_cam_clay", "model: modified_cam_clay, lambda: 0.15, kappa: 0.013, friction_angle: 30.0, "
                          "poisson_ratio: 0.3, void_ratio: 0.62, min_pressure: 100.0"},
    {"subloading_cam_clay", "model: subloading_cam_clay, lambda: 0.15, kappa: 0.013, friction_angle: 30.0, "
                            "poisson_ratio: 0.3, void_ratio: 0.62, ocr: 2.0, subloading_a: 2000.0, min_pressure: 100.0"},
    {"hypoplastic", "model: hypoplastic, friction_angle: 33.0, h_s: 1600.0e6, n: 0.19, e_d0: 0.44, e_c0: 0.85, "
                    "e_i0: 1.00, alpha: 0.25, beta: 1.00, p_t: 10.0, void_ratio: 0.82"},
    {"hardening_soil_small", "model: hardening_soil_small, e50_ref: 48.0e6, eoed_ref: 48.0e6, eur_ref: 144.0e6, "
                             "poisson_ratio: 0.2, g0_ref: 114.4e6, gamma_07: 1.2e-4, stiffness_exponent: 0.45, "
                             "friction_angle: 30.0, cohesion: 10.0, min_pressure: 100.0"},
    {"mu_i_rheology", "model: mu_i_rheology, youngs_modulus: 5.0e6, poisson_ratio: 0.3"},
};

std::string replace_all(std::string s, const std::string& key, const std::string& value) {
    for (auto at = s.find(key); at != std::string::npos; at = s.find(key, at + value.size())) s.replace(at, key.size(), value);
    return s;
}

double computed_runout(const fs::path& json) {
    std::ifstream in(json);
    std::stringstream t;
    t << in.rdbuf();
    const std::string s = t.str();
    const auto k = s.find("\"computed\"");
    return k == std::string::npos ? NAN : std::stod(s.substr(s.find(':', k) + 1));
}

}  // namespace

TEST(MpmSoilModels, EveryModelCollapsesAColumnWithoutFailing) {
    const fs::path dir = fs::temp_directory_path() / "pilempm-mpm-soil-models";
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const auto& m : kMaterials) {
        const fs::path file = dir / (std::string(m.model) + ".yaml"), out = dir / m.model;
        std::ofstream(file) << replace_all(replace_all(kColumn, "%MODEL%", m.model), "%MATERIAL%", m.keys);
        const std::string cmd = std::string(PILEMPM_EXECUTABLE) + " run " + file.string() + " --out " + out.string() +
                                " --quiet 2>" + (dir / "err.txt").string();
        const int raw = std::system(cmd.c_str());
        ASSERT_TRUE(WIFEXITED(raw));
        // 0: the run-out is within Lube's 15 %; 1: it is not (not this test's business).
        EXPECT_LE(WEXITSTATUS(raw), 1) << m.model;
        const double runout = computed_runout(out / "verification.json");
        EXPECT_TRUE(std::isfinite(runout)) << m.model;
        EXPECT_GT(runout, 0.2) << m.model;  // the column did spread
        std::printf("  %-22s normalised run-out %.3f after 0.25 s\n", m.model, runout);
    }
    fs::remove_all(dir);
}
