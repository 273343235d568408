#pragma once
// What the case-input tests share: a shipped case's text, an edit of it, the edited case
// written to a temporary file, and the error reading (and building) it gives.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/cases/mpm_case.hpp"
#include "io/cases/mpm_run_builder.hpp"
#include "io/yaml/case_error.hpp"

namespace case_text {

// A file's whole text ("" when it cannot be read).
inline std::string file_text(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

inline std::string shipped(const std::string& relative_path) {
    return file_text(std::string(PILEMPM_SOURCE_DIR) + "/" + relative_path);
}

// `text` with its first `from` replaced by `to` (a test failure when `from` is missing).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

inline std::filesystem::path write(const std::string& text, const std::string& name) {
    const auto file = std::filesystem::temp_directory_path() /
                      ("pilempm-case-" + name + "-" + std::to_string(::getpid()) + ".yaml");
    std::ofstream(file) << text;
    return file;
}

// The message of the CaseError reading `text` as an MPM case (and, with build, building
// its 2D run) throws; "" if none.
inline std::string mpm_error_of(const std::string& text, const std::string& name, bool build = false) {
    const auto file = write(text, name);
    std::string message;
    try {
        const auto c = pilempm::io::read_mpm_case(file.string());
        if (build) (void)pilempm::io::build_mpm_run<2>(c);
    } catch (const pilempm::io::CaseError& e) {
        message = e.what();
    }
    std::filesystem::remove(file);
    return message;
}

}  // namespace case_text
