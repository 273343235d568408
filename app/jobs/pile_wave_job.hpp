#pragma once
#include <filesystem>
#include <string>

namespace pilempm::app {

// `pilempm check`: validates the case, builds the model and prints what would be run.
int check_pile_wave_case(const std::string& file);
// `pilempm run`: runs the case and writes every output into out_dir (atomically).
int run_pile_wave_case(const std::string& file, const std::filesystem::path& out_dir, bool quiet);

}  // namespace pilempm::app
