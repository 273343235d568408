#pragma once
#include <filesystem>
#include <string>

namespace pilempm::app {

int check_mpm_case(const std::string& file);
// resume: continue from the checkpoint an interrupted run left in DIR.incomplete.
int run_mpm_case(const std::string& file, const std::filesystem::path& out_dir, bool quiet, bool resume);

}  // namespace pilempm::app
