#include "io/cases/coupled_run_records.hpp"

#include <cmath>
#include <filesystem>

#include "io/cases/field_records.hpp"
#include "io/yaml/case_error.hpp"

namespace pilempm::io {

namespace fs = std::filesystem;

coupling::CalibrationTarget read_coupled_run(const std::string& folder, int skip_blows, const std::string& case_file,
                                             int line, const std::string& where) {
    const std::string expected = "the output folder of a coupled driving run (blows.csv and history.csv)";
    for (const char* name : {"blows.csv", "history.csv"})
        if (!fs::is_regular_file(fs::path(folder) / name))
            throw CaseError(case_file, line, where, expected, folder + " without " + name);
    const HeaderedCsv blows = read_headered_csv((fs::path(folder) / "blows.csv").string());
    const auto stage = blows.numbers("stage"), start = blows.numbers("start_time_s");
    const auto depth = blows.numbers("toe_depth_before_m"), set = blows.numbers("set_m");
    const auto enthru = blows.numbers("enthru_J");
    const int n = static_cast<int>(set.size());
    if (n <= skip_blows)
        throw CaseError(case_file, line, where, "more blows than skip_blows (" + std::to_string(skip_blows) + ")",
                        folder + ": " + std::to_string(n) + " blows");
    coupling::CalibrationTarget t;
    t.source = folder;
    for (int b = skip_blows; b < n; ++b) {
        t.depth += depth[b];
        t.set += set[b];
        t.enthru += enthru[b];
        ++t.blows;
    }
    t.depth /= t.blows, t.set /= t.blows, t.enthru /= t.blows;
    if (!(t.set > 0.0))
        throw CaseError(case_file, line, where, "blows that drive the pile (a positive mean set)",
                        folder + ": " + std::to_string(t.set) + " m");

    const HeaderedCsv history = read_headered_csv((fs::path(folder) / "history.csv").string());
    const auto time = history.numbers("time_s"), rows_stage = history.numbers("stage");
    const auto force = history.numbers("pile_head_force_N"), velocity = history.numbers("pile_head_velocity_m_s");
    const double last_stage = stage[n - 1], t0 = start[n - 1];
    for (std::size_t i = 0; i < time.size(); ++i) {
        if (rows_stage[i] != last_stage) continue;
        t.record.time.push_back(time[i] - t0);
        t.record.force.push_back(force[i]);
        t.record.velocity.push_back(velocity[i]);
    }
    if (t.record.time.size() < 2)
        throw CaseError(case_file, line, where, "the head's record of the last blow in history.csv",
                        folder + ": stage " + std::to_string(static_cast<int>(last_stage)) + " has no rows");
    return t;
}

}  // namespace pilempm::io
