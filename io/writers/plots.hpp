#pragma once
#include <filesystem>
#include <string>

namespace pilempm::io {

// Runs scripts/<script> on a results folder with a python3 that has matplotlib. Returns
// false (and says why in `note`) when no such python is found or the script fails; a
// run never fails for want of plots.
bool make_plots(const std::string& script, const std::filesystem::path& dir, std::string& note);

}  // namespace pilempm::io
