#include "io/yaml/yaml_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace pilempm::io {

Expect positive(const std::string& what) {
    return {"a positive " + what, [](double x) { return x > 0.0; }};
}
Expect non_negative(const std::string& what) {
    return {"a non-negative " + what, [](double x) { return x >= 0.0; }};
}
Expect in_open_range(double lo, double hi, const std::string& what) {
    std::ostringstream s;
    s << what << " strictly between " << lo << " and " << hi;
    return {s.str(), [lo, hi](double x) { return x > lo && x < hi; }};
}
Expect in_half_open_range(double lo, double hi, const std::string& what) {
    std::ostringstream s;
    s << what << " greater than " << lo << " and at most " << hi;
    return {s.str(), [lo, hi](double x) { return x > lo && x <= hi; }};
}

std::string describe(const YAML::Node& n) {
    if (!n.IsDefined() || n.IsNull()) return "nothing";
    if (n.IsSequence()) return "a list";
    if (n.IsMap()) return "a mapping";
    return "'" + n.Scalar() + "'";
}

MapReader::MapReader(YAML::Node node, std::string path, std::string file, int key_line)
    : node_(std::move(node)), path_(std::move(path)), file_(std::move(file)), key_line_(key_line) {
    if (!node_.IsMap())
        throw CaseError(file_, line(), path_, "a mapping of keys to values", describe(node_));
    // YAML allows a key twice and keeps one silently; a case file must not.
    std::vector<std::string> seen;
    for (const auto& kv : node_) {
        const std::string k = kv.first.Scalar();
        if (std::find(seen.begin(), seen.end(), k) != seen.end())
            throw CaseError(file_, kv.first.Mark().line + 1, key_path(k), "each key once",
                            "'" + k + "' a second time");
        seen.push_back(k);
    }
}

int MapReader::line() const {
    if (key_line_ > 0) return key_line_;
    return node_.Mark().line < 0 ? 0 : node_.Mark().line + 1;
}

int MapReader::value_line(const YAML::Node& n, const std::string& key) const {
    if (!n.IsDefined() || n.IsNull()) return line_of(key);
    return n.Mark().line + 1;
}

int MapReader::line_of(const std::string& key) const {
    for (const auto& kv : node_)
        if (kv.first.Scalar() == key) return kv.first.Mark().line + 1;
    return line();
}

bool MapReader::has(const std::string& key) {
    read_.push_back(key);  // a key asked about is a key this mapping knows
    for (const auto& kv : node_)
        if (kv.first.Scalar() == key) return true;
    return false;
}

std::string MapReader::key_path(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
}

void MapReader::fail(const std::string& key, const std::string& expected,
                     const std::string& found) const {
    throw CaseError(file_, key.empty() ? line() : line_of(key), key.empty() ? path_ : key_path(key),
                    expected, found);
}

YAML::Node MapReader::get(const std::string& key, const std::string& expected) {
    read_.push_back(key);
    for (const auto& kv : node_)
        if (kv.first.Scalar() == key) return kv.second;
    throw CaseError(file_, line(), key_path(key), expected, "the key missing");
}

YAML::Node MapReader::raw(const std::string& key) { return get(key, "a value"); }

double MapReader::to_number(const YAML::Node& n, const std::string& path, int line,
                            const Expect& e) const {
    double x = 0.0;
    bool ok = n.IsScalar();
    if (ok) {
        try {
            x = n.as<double>();
        } catch (const YAML::Exception&) {
            ok = false;
        }
    }
    if (!ok || !std::isfinite(x)) throw CaseError(file_, line, path, e.words, describe(n));
    if (!e.accepts(x)) throw CaseError(file_, line, path, e.words, n.Scalar());
    return x;
}

double MapReader::number(const std::string& key, const Expect& e) {
    const YAML::Node n = get(key, e.words);
    return to_number(n, key_path(key), value_line(n, key), e);
}

double MapReader::number_or(const std::string& key, double fallback, const Expect& e) {
    return has(key) ? number(key, e) : fallback;
}

int MapReader::integer_or(const std::string& key, int fallback, int min_value) {
    if (!has(key)) return fallback;
    const std::string words = "an integer of at least " + std::to_string(min_value);
    const YAML::Node n = get(key, words);
    int x = 0;
    try {
        x = n.as<int>();
    } catch (const YAML::Exception&) {
        throw CaseError(file_, value_line(n, key), key_path(key), words, describe(n));
    }
    if (x < min_value) throw CaseError(file_, value_line(n, key), key_path(key), words, n.Scalar());
    return x;
}

bool MapReader::boolean_or(const std::string& key, bool fallback) {
    if (!has(key)) return fallback;
    const YAML::Node n = get(key, "true or false");
    try {
        return n.as<bool>();
    } catch (const YAML::Exception&) {
        throw CaseError(file_, value_line(n, key), key_path(key), "true or false", describe(n));
    }
}

std::string MapReader::text_or(const std::string& key, const std::string& fallback) {
    if (!has(key)) return fallback;
    const YAML::Node n = get(key, "text");
    if (!n.IsScalar()) throw CaseError(file_, value_line(n, key), key_path(key), "text", describe(n));
    return n.Scalar();
}

static std::string one_of(const std::vector<std::string>& options) {
    std::string s = "one of ";
    for (std::size_t i = 0; i < options.size(); ++i) s += (i ? ", " : "") + options[i];
    return s;
}

std::string MapReader::choice(const std::string& key, const std::vector<std::string>& options) {
    const YAML::Node n = get(key, one_of(options));
    if (!n.IsScalar() || std::find(options.begin(), options.end(), n.Scalar()) == options.end())
        throw CaseError(file_, value_line(n, key), key_path(key), one_of(options), describe(n));
    return n.Scalar();
}

std::string MapReader::choice_or(const std::string& key, const std::string& fallback,
                                 const std::vector<std::string>& options) {
    return has(key) ? choice(key, options) : fallback;
}

std::vector<double> MapReader::numbers(const std::string& key, const Expect& e) {
    const YAML::Node n = get(key, "a list of numbers");
    if (!n.IsSequence())
        throw CaseError(file_, value_line(n, key), key_path(key), "a list of " + e.words, describe(n));
    std::vector<double> out;
    for (std::size_t i = 0; i < n.size(); ++i)
        out.push_back(to_number(n[i], key_path(key) + "[" + std::to_string(i) + "]",
                                value_line(n[i], key), e));
    return out;
}

std::vector<std::string> MapReader::words(const std::string& key,
                                          const std::vector<std::string>& options) {
    const YAML::Node n = get(key, "a list of names");
    if (!n.IsSequence())
        throw CaseError(file_, value_line(n, key), key_path(key), "a list of " + one_of(options),
                        describe(n));
    std::vector<std::string> out;
    for (std::size_t i = 0; i < n.size(); ++i) {
        if (!n[i].IsScalar() ||
            std::find(options.begin(), options.end(), n[i].Scalar()) == options.end())
            throw CaseError(file_, value_line(n[i], key), key_path(key) + "[" + std::to_string(i) + "]",
                            one_of(options), describe(n[i]));
        out.push_back(n[i].Scalar());
    }
    return out;
}

MapReader MapReader::map(const std::string& key) {
    const YAML::Node n = get(key, "a mapping");
    if (!n.IsMap()) throw CaseError(file_, line_of(key), key_path(key), "a mapping", describe(n));
    return MapReader(n, key_path(key), file_, line_of(key));
}

std::optional<MapReader> MapReader::optional_map(const std::string& key) {
    if (!has(key)) return std::nullopt;
    return map(key);
}

std::vector<MapReader> MapReader::maps(const std::string& key) {
    const YAML::Node n = get(key, "a list of mappings");
    if (!n.IsSequence() || n.size() == 0)
        throw CaseError(file_, line_of(key), key_path(key), "a non-empty list of mappings", describe(n));
    std::vector<MapReader> out;
    for (std::size_t i = 0; i < n.size(); ++i)
        out.emplace_back(n[i], key_path(key) + "[" + std::to_string(i) + "]", file_, value_line(n[i], key));
    return out;
}

void MapReader::finish() const {
    for (const auto& kv : node_) {
        const std::string k = kv.first.Scalar();
        if (std::find(read_.begin(), read_.end(), k) == read_.end()) {
            std::string known;
            for (const auto& r : read_)
                if (known.find(r) == std::string::npos) known += (known.empty() ? "" : ", ") + r;
            throw CaseError(file_, kv.first.Mark().line + 1, key_path(k),
                            known.empty() ? "no further keys here" : "one of the keys " + known,
                            "the unknown key '" + k + "'");
        }
    }
}

MapReader load_yaml_file(const std::string& file) {
    if (!std::filesystem::is_regular_file(file))
        throw CaseError(file, 0, "", "a readable case file", "no such file");
    YAML::Node root;
    try {
        root = YAML::LoadFile(file);
    } catch (const YAML::ParserException& e) {
        throw CaseError(file, e.mark.line + 1, "", "valid YAML", e.msg);
    } catch (const YAML::BadFile&) {
        throw CaseError(file, 0, "", "a readable case file", "it cannot be opened");
    }
    if (!root.IsMap()) throw CaseError(file, 1, "", "a mapping at the top level", describe(root));
    return MapReader(root, "", file);
}

}  // namespace pilempm::io
