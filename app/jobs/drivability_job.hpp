#pragma once
#include <filesystem>
#include <string>

namespace pilempm::app {

int check_drivability_case(const std::string& file);
int run_drivability_case(const std::string& file, const std::filesystem::path& out_dir, bool quiet);

}  // namespace pilempm::app
