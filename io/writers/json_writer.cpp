#include "io/writers/json_writer.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace pilempm::io {
namespace {

std::string quote(const std::string& s) {
    std::string out = "\"";
    for (char ch : s) {
        switch (ch) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\t': out += "\\t"; break;
            default:
                if (static_cast<unsigned char>(ch) < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", ch);
                    out += buf;
                } else {
                    out += ch;
                }
        }
    }
    return out + "\"";
}

std::string number(double x) {
    if (!std::isfinite(x)) return "null";  // JSON has no inf/nan
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", x);
    return buf;
}

}  // namespace

std::string to_json(const JsonObject& o, int indent) {
    const std::string pad(indent + 2, ' '), end_pad(indent, ' ');
    std::string s = "{\n";
    for (std::size_t i = 0; i < o.members.size(); ++i) {
        const auto& [key, value] = o.members[i];
        s += pad + quote(key) + ": ";
        if (auto d = std::get_if<double>(&value)) s += number(*d);
        else if (auto t = std::get_if<std::string>(&value)) s += quote(*t);
        else if (auto b = std::get_if<bool>(&value)) s += *b ? "true" : "false";
        else if (auto obj = std::get_if<std::shared_ptr<JsonObject>>(&value)) s += to_json(**obj, indent + 2);
        else if (auto nums = std::get_if<std::vector<double>>(&value)) {
            s += "[";
            for (std::size_t k = 0; k < nums->size(); ++k) s += (k ? ", " : "") + number((*nums)[k]);
            s += "]";
        } else {
            const auto& list = std::get<std::vector<JsonObject>>(value);
            s += "[";
            for (std::size_t k = 0; k < list.size(); ++k)
                s += (k ? ", " : "") + to_json(list[k], indent + 2);
            s += "]";
        }
        s += i + 1 < o.members.size() ? ",\n" : "\n";
    }
    return s + end_pad + "}";
}

void write_json(const std::filesystem::path& file, const JsonObject& o) {
    std::ofstream out(file);
    if (!out) throw std::runtime_error("cannot write " + file.string());
    out << to_json(o) << "\n";
    if (!out) throw std::runtime_error("error writing " + file.string());
}

std::vector<JsonObject> json_lines(const std::string& key, const std::vector<std::string>& lines) {
    std::vector<JsonObject> out;
    for (const auto& line : lines) {
        JsonObject j;
        j.add(key, line);
        out.push_back(std::move(j));
    }
    return out;
}

}  // namespace pilempm::io
