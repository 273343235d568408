#pragma once
// Strict reading of one YAML mapping: every value is checked for type and range as it is
// read, and finish() rejects the keys nobody asked for. Errors carry file, line and key.
#include <yaml-cpp/yaml.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "io/yaml/case_error.hpp"

namespace pilempm::io {

// A range check with the words that describe it, e.g. {"a positive length in m", x > 0}.
struct Expect {
    std::string words;
    std::function<bool(double)> accepts;
};
Expect positive(const std::string& what);
Expect non_negative(const std::string& what);
Expect in_open_range(double lo, double hi, const std::string& what);
Expect in_half_open_range(double lo, double hi, const std::string& what);  // (lo, hi]

class MapReader {
public:
    // key_line: the line of the key that introduced this mapping (0 for the document).
    MapReader(YAML::Node node, std::string path, std::string file, int key_line = 0);

    int line() const;  // 1-based line of this mapping
    int line_of(const std::string& key) const;
    const std::string& path() const { return path_; }
    const std::string& file() const { return file_; }
    bool has(const std::string& key);  // also marks the key as known

    double number(const std::string& key, const Expect& e);
    double number_or(const std::string& key, double fallback, const Expect& e);
    int integer_or(const std::string& key, int fallback, int min_value);
    bool boolean_or(const std::string& key, bool fallback);
    std::string text_or(const std::string& key, const std::string& fallback);
    std::string choice(const std::string& key, const std::vector<std::string>& options);
    std::string choice_or(const std::string& key, const std::string& fallback,
                          const std::vector<std::string>& options);
    std::vector<double> numbers(const std::string& key, const Expect& e);
    std::vector<std::string> words(const std::string& key, const std::vector<std::string>& options);
    MapReader map(const std::string& key);
    std::optional<MapReader> optional_map(const std::string& key);
    std::vector<MapReader> maps(const std::string& key);
    YAML::Node raw(const std::string& key);  // marks the key as read

    [[noreturn]] void fail(const std::string& key, const std::string& expected,
                           const std::string& found = "") const;
    void finish() const;  // unknown keys are errors

private:
    YAML::Node get(const std::string& key, const std::string& expected);
    std::string key_path(const std::string& key) const;
    double to_number(const YAML::Node& n, const std::string& path, int line, const Expect& e) const;
    // Line to report for a value: its own, or its key's when the value is empty (yaml-cpp
    // places an empty value at whatever follows it in the file).
    int value_line(const YAML::Node& n, const std::string& key) const;

    YAML::Node node_;
    std::string path_, file_;
    std::vector<std::string> read_;
    int key_line_ = 0;
};

// Loads a YAML file whose top level is a mapping; syntax errors become CaseError.
MapReader load_yaml_file(const std::string& file);
std::string describe(const YAML::Node& n);  // "'abc'" / "a list" / "a mapping"

}  // namespace pilempm::io
