// A verification's grid sequence with tolerance_on: finest_grid: the checks of the coarser
// grids are reported beside their references, only the finest grid's pass or fail (the 1D
// wave on 80 and 160 cells, its travel time's order of convergence still checked).
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/unit/io/cases/case_text.hpp"

namespace fs = std::filesystem;

namespace {

// The tolerance_kind written for the check called exactly `name`.
std::string kind_of(const std::string& json, const std::string& name) {
    const auto at = json.find("\"name\": \"" + name + "\"");
    if (at == std::string::npos) return "missing";
    const std::string key = "\"tolerance_kind\": \"";
    const auto k = json.find(key, at) + key.size();
    return json.substr(k, json.find('"', k) - k);
}

}  // namespace

TEST(GridSequence, TheToleranceOnTheFinestGridReportsTheCoarserOnes) {
    const fs::path dir = fs::temp_directory_path() / ("pilempm-grid-sequence-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::string yaml = case_text::shipped("cases/verification/mpm-wave-1d.yaml");
    yaml = case_text::replaced(yaml, "grid_sequence: [2, 4, 8]", "grid_sequence: [2]\n  tolerance_on: finest_grid");
    const fs::path file = dir / "wave.yaml";
    std::ofstream(file) << yaml;
    const int status = std::system((std::string(PILEMPM_EXECUTABLE) + " run " + file.string() + " --out " +
                                    (dir / "out").string() + " --quiet")
                                       .c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
    const std::string json = case_text::file_text(dir / "out" / "verification.json");
    EXPECT_EQ(kind_of(json, "wave_travel_time_between_probes_s"), "reported") << json;
    EXPECT_EQ(kind_of(json, "wave_travel_time_between_probes_s_grid_1x160"), "relative") << json;
    EXPECT_EQ(kind_of(json, "wave_travel_time_between_probes_s_observed_order"), "at_least") << json;
    // Without a sequence the key has nothing to hold: a clear error, exit 2.
    const std::string alone = case_text::replaced(
        case_text::replaced(yaml, "grid_sequence: [2]\n", ""), "  converging: [wave_travel_time_between_probes_s]", "");
    std::ofstream(dir / "alone.yaml") << alone;
    const int bad = std::system((std::string(PILEMPM_EXECUTABLE) + " check " + (dir / "alone.yaml").string() +
                                 " > /dev/null 2>&1").c_str());
    EXPECT_EQ(WEXITSTATUS(bad), 2);
    fs::remove_all(dir);
}
