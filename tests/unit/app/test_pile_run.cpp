// Piles in the soil run as a user runs them. A pile jacked in and held: the jack's force
// plus the pile's weight is the soil's resistance (outer shaft + inner shaft + base) within
// 0.5 % (the pile at rest, Newton); the penetration stays below 1 % of a cell at every
// step; the traction profiles, the pile's VTK series and the plots' inputs are written.
// A pile wished in place in soil at K0, after the nil step: the normal traction on its
// outer shaft is the soil's horizontal stress K0 rho g z, converging on two grids. A
// maintained load after jacking (force control, quasi-static): the soil carries the load
// plus the weight within 0.5 %; so it does for a closed-ended (solid) pile, all on its base.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "tests/unit/io/cases/case_text.hpp"

namespace fs = std::filesystem;

namespace {

// A CSV file as columns by name.
std::map<std::string, std::vector<double>> read_history(const fs::path& file) {
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    std::vector<std::string> names;
    std::stringstream header(line);
    for (std::string name; std::getline(header, name, ',');) names.push_back(name);
    std::map<std::string, std::vector<double>> columns;
    while (std::getline(in, line)) {
        std::stringstream row(line);
        std::string value;
        for (std::size_t k = 0; k < names.size() && std::getline(row, value, ','); ++k) columns[names[k]].push_back(std::stod(value));
    }
    return columns;
}

int run_case(const std::string& case_file, const fs::path& out) {
    fs::remove_all(out);
    const std::string command = std::string(PILEMPM_EXECUTABLE) + " run " + case_file + " --out " + out.string() + " --quiet";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The mean of sigma_n / (K0 rho g z) - 1 on the outer shaft between 0.3 and 1.7 m deep
// (clear of the ground surface and of the toe 2 m down).
double k0_shaft_error(const fs::path& out) {
    auto t = read_history(out / "pile_tractions_outer.csv");
    const double k0 = 0.3 / 0.7, surface = 3.0;
    double sum = 0.0;
    int n = 0;
    for (std::size_t k = 0; k < t["elevation_m"].size(); ++k) {
        const double depth = surface - t["elevation_m"][k];
        if (depth < 0.3 || depth > 1.7) continue;
        sum += t["normal_traction_compression_Pa"][k] / (k0 * 1900.0 * 9.81 * depth) - 1.0;
        ++n;
    }
    EXPECT_GT(n, 10);
    return n ? sum / n : 1e9;
}

fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("pilempm-pile-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// Runs `yaml` (written into dir) into dir/out and returns its history.
std::map<std::string, std::vector<double>> run_text(const fs::path& dir, const std::string& yaml) {
    const fs::path file = dir / "case.yaml";
    std::ofstream(file) << yaml;
    EXPECT_EQ(run_case(file.string(), dir / "out"), 0);
    return read_history(dir / "out" / "history.csv");
}

// The soil's axial resistance on the pile at the end of a run, N.
double soil_resistance(std::map<std::string, std::vector<double>>& h) {
    return h["outer_shaft_resistance_N"].back() + h["inner_shaft_resistance_N"].back() + h["base_resistance_N"].back();
}

// The tiny case's 0.6 m steel pile (D = 0.4 m): its weight with a 20 mm wall and solid, N.
const double kTubeWeight = 7850.0 * 9.81 * std::numbers::pi * (0.2 * 0.2 - 0.18 * 0.18) * 0.6;
const double kSolidWeight = 7850.0 * 9.81 * std::numbers::pi * 0.2 * 0.2 * 0.6;

const char* kTinyCase = "cases/jacking/jacked-open-pile-tiny.yaml";

// The tiny case with a solid steel cylinder (D = 0.4 m) for its pile and `stages` for its own.
std::string solid_pile_case(const std::string& stages) {
    std::string yaml = case_text::replaced(case_text::shipped(kTinyCase), "wall_thickness: 0.02", "wall_thickness: 0.2");
    const auto at = yaml.find("stages:");
    return yaml.replace(at, yaml.find("output:") - at, "stages:\n" + stages);
}

}  // namespace

TEST(PileRun, AWishedInPlacePileAtRestFeelsK0OnItsShaft) {
    const std::string fine = std::string(PILEMPM_SOURCE_DIR) + "/cases/jacking/wished-in-place-k0.yaml";
    const fs::path dir = fresh_dir("k0");
    // The same case on cells of 0.1 m (the shipped one has 0.05 m).
    const std::string coarse = case_text::replaced(case_text::shipped("cases/jacking/wished-in-place-k0.yaml"),
                                                   "cells: [40, 90]", "cells: [20, 45]");
    const fs::path coarse_file = dir / "coarse.yaml";
    std::ofstream(coarse_file) << coarse;
    ASSERT_EQ(run_case(coarse_file.string(), dir / "coarse"), 0);
    ASSERT_EQ(run_case(fine, dir / "fine"), 0);
    const double e_coarse = k0_shaft_error(dir / "coarse"), e_fine = k0_shaft_error(dir / "fine");
    std::printf("  outer shaft sigma_n against K0 rho g z: %+.2f %% (0.1 m cells), %+.2f %% (0.05 m)\n", 100.0 * e_coarse,
                100.0 * e_fine);
    EXPECT_LT(std::abs(e_fine), 0.05);
    EXPECT_LT(std::abs(e_coarse), 0.09);
    EXPECT_LT(std::abs(e_fine), 0.7 * std::abs(e_coarse));  // converging
    fs::remove_all(dir);
}

TEST(PileRun, AMaintainedLoadIsCarriedByTheSoil) {
    const fs::path dir = fresh_dir("load");
    const std::string last = "pile: {velocity: 0.0}}\n";
    auto h = run_text(dir, case_text::replaced(case_text::shipped(kTinyCase), last,
                                               last + "  - {name: load, type: quasi_static, max_steps: 4000, "
                                                      "tolerance: 1.0e-5, pile: {force: 40.0e3}}\n"));
    EXPECT_DOUBLE_EQ(h["pile_head_force_N"].back(), 40.0e3);
    EXPECT_NEAR(soil_resistance(h) / (40.0e3 + kTubeWeight), 1.0, 5e-3);
    fs::remove_all(dir);
}

TEST(PileRun, AClosedEndedPileUnderALoadIsCarriedByTheSoil) {
    const fs::path dir = fresh_dir("solid");
    // A solid steel cylinder (D = 0.4 m) on the surface, pushed by 20 kN: a rigid punch.
    auto h = run_text(dir, solid_pile_case("  - {name: load, type: quasi_static, max_steps: 4000, tolerance: 1.0e-5, "
                                           "pile: {force: 20.0e3}}\n"));
    EXPECT_NEAR(h["base_resistance_N"].back() / (20.0e3 + kSolidWeight), 1.0, 5e-3);  // all of it on the base
    EXPECT_LT(std::abs(h["inner_shaft_resistance_N"].back()), 1e-9);
    double deepest = 0.0;
    for (double g : h["max_penetration_over_cell"]) deepest = std::max(deepest, g);
    EXPECT_LT(deepest, 0.01);
    fs::remove_all(dir);
}

// The same solid pile in a stage at 3 g (gravity_factor, as in a centrifuge): the base
// carries the load and three times the pile's weight, the soil having settled under 3 g.
TEST(PileRun, AStagesGravityFactorScalesThePilesWeight) {
    const fs::path dir = fresh_dir("ng");
    auto h = run_text(dir, solid_pile_case("  - {name: load, type: quasi_static, max_steps: 6000, tolerance: 1.0e-5, "
                                           "gravity_factor: 3.0, pile: {force: 20.0e3}}\n"));
    EXPECT_NEAR(h["base_resistance_N"].back() / (20.0e3 + 3.0 * kSolidWeight), 1.0, 5e-3);
    fs::remove_all(dir);
}

TEST(PileRun, AHeldPileCarriesItsJackAndWeightOnTheSoil) {
    const fs::path dir = fresh_dir("held"), out = dir / "out";
    auto h = run_text(dir, case_text::shipped(kTinyCase));
    ASSERT_FALSE(h["time_s"].empty());
    const double jack = h["pile_head_force_N"].back(), soil = soil_resistance(h);
    EXPECT_GT(soil, 10.0 * kTubeWeight);  // the soil carries the jack's push
    EXPECT_NEAR((jack + kTubeWeight) / soil, 1.0, 5e-3);
    EXPECT_NEAR(h["pile_head_settlement_m"].back(), 0.025, 1e-3);  // 0.5 m/s for 0.05 s
    double deepest = 0.0;
    for (double g : h["max_penetration_over_cell"]) deepest = std::max(deepest, g);
    EXPECT_LT(deepest, 0.01);
    for (const char* f : {"pile_tractions_outer.csv", "pile_tractions_inner.csv", "pile_tractions_toe.csv", "vtk/pile.pvd"})
        EXPECT_TRUE(fs::exists(out / f)) << f;
    fs::remove_all(dir);
}

// While it is jacked at a steady 0.5 m/s through a damped stage (local damping 0.7 on the
// soil), the jack's force plus the pile's weight is the soil's resistance on average over
// the second half of the stride (0.5 %; measured 3e-6): the damping of a damped stage
// must not push on the moving pile (Cundall's damping on its DOFs once did, raising the
// jacking force 70 % while the held pile at rest still balanced).
TEST(PileRun, AJackedPileIsResistedByTheSoilAloneWhileItMoves) {
    const fs::path dir = fresh_dir("moving");
    auto h = run_text(dir, case_text::shipped(kTinyCase));
    double jack = 0.0, soil = 0.0;
    int rows = 0;
    for (std::size_t k = 0; k < h["time_s"].size(); ++k) {
        if (h["stage"][k] != 1.0 || h["time_s"][k] < 0.025) continue;
        jack += h["pile_head_force_N"][k] + kTubeWeight;
        soil += h["outer_shaft_resistance_N"][k] + h["inner_shaft_resistance_N"][k] + h["base_resistance_N"][k];
        ++rows;
    }
    ASSERT_GT(rows, 50);
    EXPECT_GT(soil / rows, 20.0 * kTubeWeight);  // the soil carries the jack's push
    EXPECT_NEAR(jack / soil, 1.0, 5e-3);
    fs::remove_all(dir);
}

// A solid pile set on the soil and left free in a nil step (quasi-static, local damping 0.7)
// comes to rest on it: the stage ends in equilibrium, soil and pile both (tolerance 1e-5),
// the base carrying the weight within 1e-4. Cundall's damping on each of the pile's DOFs
// held it 0.3-0.4 % out of balance through its vibration's noise (the soil's balance alone
// ended the stage there).
TEST(PileRun, AFreePileComesToRestOnTheSoilInANilStep) {
    const fs::path dir = fresh_dir("free");
    auto h = run_text(dir, solid_pile_case("  - {name: nil, type: quasi_static, max_steps: 20000, tolerance: 1.0e-5, "
                                           "local_damping: 0.7}\n"));
    EXPECT_LT(h["step"].back(), 20000.0);  // in equilibrium before max_steps
    EXPECT_NEAR(h["base_resistance_N"].back() / kSolidWeight, 1.0, 1e-4);
    fs::remove_all(dir);
}

// The North Sea monopile's nil step (the shipped case, its drive left out, 12 000 of its
// 20 000 steps): the 77 m pile, released 4.7 m deep in two-phase soil on 0.5 m cells,
// comes to rest on the soil. Its vibration on the contact kept the soil's unbalanced force
// at 0.07 to 0.3 of its load (0.18 after 20 000 steps) until the pile's vibration took the
// stage's local damping too (0.005 at 12 000 steps, 0.003 at 20 000); the soil carries the
// pile's weight within 0.5 % (measured 0.07 %).
TEST(PileRun, TheNorthSeaMonopileComesToRestInItsNilStep) {
    const fs::path dir = fresh_dir("north-sea-nil");
    std::string yaml = case_text::shipped("cases/driving/north-sea-monopile.yaml");
    const auto drive = yaml.find("  - name: drive");
    yaml.replace(drive, yaml.find("output:") - drive, "");
    auto h = run_text(dir, case_text::replaced(yaml, "max_steps: 20000", "max_steps: 12000"));
    const double weight = 7850.0 * 9.81 * std::numbers::pi * (3.9 * 3.9 - 3.83 * 3.83) * 77.4;
    EXPECT_LT(h["unbalanced_force_ratio"].back(), 0.02);
    EXPECT_NEAR(soil_resistance(h) / weight, 1.0, 5e-3);
    fs::remove_all(dir);
}
