#pragma once
// `pilempm element-test CASE.yaml` (or `run` on an analysis: element_test case): drives
// one material point along laboratory paths; CSV per test, summary, plots, verification.
#include <filesystem>
#include <string>

namespace pilempm::app {

int check_element_test_case(const std::string& file);
int run_element_test_case(const std::string& file, const std::filesystem::path& out_dir, bool quiet);

}  // namespace pilempm::app
