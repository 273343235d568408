#pragma once
// analysis: drivability_study: a drivability case at every location of a field records
// file, against the measured blows (app/jobs/drivability_study_job.cpp).
#include <filesystem>
#include <string>

namespace pilempm::app {

int check_drivability_study_case(const std::string& file);
int run_drivability_study_case(const std::string& file, const std::filesystem::path& out_dir, bool quiet);

}  // namespace pilempm::app
