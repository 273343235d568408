#include "io/writers/plots.hpp"

#include <cstdlib>
#include <filesystem>

namespace pilempm::io {

namespace {
std::string quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}
}  // namespace

bool make_plots(const std::string& script, const std::filesystem::path& dir, std::string& note) {
    const std::filesystem::path path = std::filesystem::path(PILEMPM_SOURCE_DIR) / "scripts" / script;
    if (!std::filesystem::exists(path)) {
        note = "plot script " + path.string() + " not found";
        return false;
    }
    // The python3 on PATH first (it may be a virtual environment), then the system one.
    for (const char* python : {"python3", "/usr/bin/python3"}) {
        const std::string probe = std::string(python) + " -c 'import matplotlib' >/dev/null 2>&1";
        if (std::system(probe.c_str()) != 0) continue;
        const std::string cmd = std::string(python) + " " + quoted(path.string()) + " " +
                                quoted(dir.string()) + " >/dev/null 2>&1";
        if (std::system(cmd.c_str()) == 0) return true;
        note = "plot script failed: " + cmd;
        return false;
    }
    note = "no python3 with matplotlib found; plots skipped (apt-get install python3-matplotlib)";
    return false;
}

}  // namespace pilempm::io
