#pragma once
// A small JSON emitter for summary.json and verification.json: objects of numbers,
// strings, booleans and lists of objects. Keys keep their insertion order.
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace pilempm::io {

struct JsonObject;
using JsonValue = std::variant<double, std::string, bool, std::vector<JsonObject>,
                               std::shared_ptr<JsonObject>, std::vector<double>>;

struct JsonObject {
    std::vector<std::pair<std::string, JsonValue>> members;
    JsonObject& add(std::string key, JsonValue value) {
        members.emplace_back(std::move(key), std::move(value));
        return *this;
    }
};

std::string to_json(const JsonObject& o, int indent = 0);
// A list of one-member objects {key: line}, e.g. the correlations a model used.
std::vector<JsonObject> json_lines(const std::string& key, const std::vector<std::string>& lines);
void write_json(const std::filesystem::path& file, const JsonObject& o);

}  // namespace pilempm::io
