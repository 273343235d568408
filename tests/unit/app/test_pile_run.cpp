// A pile jacked into the soil and held, run as a user runs it: once held, the jack's force
// plus the pile's weight is the soil's resistance (outer shaft + inner shaft + base) within
// 0.5 % (the pile at rest, Newton); the penetration stays below 1 % of a cell at every
// step; the traction profiles, the pile's VTK series and the plots' inputs are written.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// history.csv as columns by name.
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

}  // namespace

TEST(PileRun, AHeldPileCarriesItsJackAndWeightOnTheSoil) {
    const fs::path out = fs::temp_directory_path() / ("pilempm-pile-run-" + std::to_string(::getpid()));
    fs::remove_all(out);
    const std::string command = std::string(PILEMPM_EXECUTABLE) + " run " + PILEMPM_SOURCE_DIR +
                                "/cases/jacking/jacked-open-pile-tiny.yaml --out " + out.string() + " --quiet";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << command;
    auto h = read_history(out / "history.csv");
    ASSERT_FALSE(h["time_s"].empty());
    // The pile's weight: steel 7850 kg/m^3, the 0.4 m tube with a 20 mm wall, 0.6 m long.
    const double weight = 7850.0 * 9.81 * std::numbers::pi * (0.2 * 0.2 - 0.18 * 0.18) * 0.6;
    const double jack = h["pile_head_force_N"].back();
    const double soil = h["outer_shaft_resistance_N"].back() + h["inner_shaft_resistance_N"].back() + h["base_resistance_N"].back();
    EXPECT_GT(soil, 10.0 * weight);  // the soil carries the jack's push
    EXPECT_NEAR((jack + weight) / soil, 1.0, 5e-3);
    EXPECT_NEAR(h["pile_head_settlement_m"].back(), 0.025, 1e-3);  // 0.5 m/s for 0.05 s
    double deepest = 0.0;
    for (double g : h["max_penetration_over_cell"]) deepest = std::max(deepest, g);
    EXPECT_LT(deepest, 0.01);
    for (const char* f : {"pile_tractions_outer.csv", "pile_tractions_inner.csv", "pile_tractions_toe.csv", "vtk/pile.pvd"})
        EXPECT_TRUE(fs::exists(out / f)) << f;
    fs::remove_all(out);
}
