#include "io/cases/field_records.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "io/yaml/case_error.hpp"

namespace pilempm::io {

namespace {

std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t\r\"");
    if (a == std::string::npos) return "";
    const auto b = s.find_last_not_of(" \t\r\"");
    return s.substr(a, b - a + 1);
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> out;
    std::string cell;
    std::istringstream s(line);
    while (std::getline(s, cell, ',')) out.push_back(trim(cell));
    if (!line.empty() && line.back() == ',') out.emplace_back();
    return out;
}

constexpr double kMpa = 1e6;

}  // namespace

int HeaderedCsv::column(const std::string& name) const {
    for (std::size_t c = 0; c < header.size(); ++c)
        if (header[c] == name) return static_cast<int>(c);
    return -1;
}

std::vector<double> HeaderedCsv::numbers(const std::string& name) const {
    const int c = column(name);
    if (c < 0) throw CaseError(path, 1, name, "a column named " + name + " in the header", "no such column");
    std::vector<double> out(rows.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const std::string& cell = rows[r][static_cast<std::size_t>(c)];
        if (cell.empty()) continue;
        std::size_t used = 0;
        double x = 0.0;
        try {
            x = std::stod(cell, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != cell.size() || !std::isfinite(x))
            throw CaseError(path, lines[r], name, "a number or an empty cell", "'" + cell + "'");
        out[r] = x;
    }
    return out;
}

HeaderedCsv read_headered_csv(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw CaseError(path, 0, "", "a readable CSV file with a header row", "cannot open it");
    HeaderedCsv t;
    t.path = path;
    std::string line;
    int lineno = 0;
    while (std::getline(in, line)) {
        ++lineno;
        if (trim(line).empty() || line[0] == '#') continue;
        std::vector<std::string> cells = split(line);
        if (t.header.empty()) {
            t.header = std::move(cells);
            continue;
        }
        if (cells.size() != t.header.size())
            throw CaseError(path, lineno, "", std::to_string(t.header.size()) + " cells as in the header",
                            std::to_string(cells.size()));
        t.rows.push_back(std::move(cells));
        t.lines.push_back(lineno);
    }
    if (t.header.empty()) throw CaseError(path, lineno, "", "a header row", "an empty file");
    return t;
}

std::vector<FieldRecord> read_field_records(const std::string& path, const std::vector<std::string>& only) {
    const HeaderedCsv t = read_headered_csv(path);
    const int loc = t.column("location");
    if (loc < 0) throw CaseError(path, 1, "location", "a column named location", "no such column");
    const auto depth = t.numbers("depth_m"), qc = t.numbers("qc_MPa"), fs = t.numbers("fs_MPa"),
               u2 = t.numbers("u2_MPa"), blows = t.numbers("blows_per_m"),
               energy = t.numbers("normalised_hammer_energy"), cumulative = t.numbers("cumulative_blows"),
               diameter = t.numbers("diameter_m"), wall = t.numbers("bottom_wall_thickness_mm"),
               final = t.numbers("final_penetration_m");
    std::vector<FieldRecord> all;
    std::map<std::string, std::size_t> index;
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
        const std::string& name = t.rows[r][static_cast<std::size_t>(loc)];
        auto [it, fresh] = index.emplace(name, all.size());
        if (fresh) {
            all.emplace_back();
            all.back().location = name;
        }
        FieldRecord& f = all[it->second];
        auto fail = [&](const std::string& col, const std::string& expected) {
            throw CaseError(path, t.lines[r], col, expected, "location " + name);
        };
        if (std::isnan(depth[r]) || (!f.cpt.depth.empty() && !(depth[r] > f.cpt.depth.back())))
            fail("depth_m", "depths that increase within a location");
        if (std::isnan(qc[r]) || std::isnan(fs[r]))
            fail("qc_MPa", "q_c and f_s at every depth");
        f.cpt.depth.push_back(depth[r]);
        f.cpt.qc.push_back(qc[r] * kMpa);
        f.cpt.fs.push_back(fs[r] * kMpa);
        f.cpt.u2.push_back(std::isnan(u2[r]) ? 0.0 : u2[r] * kMpa);
        if (!std::isnan(blows[r])) {
            if (std::isnan(energy[r])) fail("normalised_hammer_energy", "an energy wherever a blow count is given");
            f.driven_depth.push_back(depth[r]);
            f.blows_per_m.push_back(blows[r]);
            f.normalised_energy.push_back(energy[r]);
            f.cumulative_blows.push_back(cumulative[r]);
        }
        // The pile's columns are empty below its final penetration, where the CPT goes on.
        if (!std::isnan(diameter[r]) && !std::isnan(wall[r]) && !std::isnan(final[r])) {
            f.diameter = diameter[r];
            f.toe_wall = wall[r] * 1e-3;
            f.final_penetration = final[r];
        }
    }
    for (const auto& f : all)
        if (!(f.diameter > 0.0 && f.toe_wall > 0.0 && f.final_penetration > 0.0))
            throw CaseError(path, 0, "diameter_m", "the pile's diameter, toe wall and final penetration on some row",
                            "none for location " + f.location);
    if (only.empty()) return all;
    std::vector<FieldRecord> chosen;
    for (const auto& name : only) {
        auto it = index.find(name);
        if (it == index.end()) throw CaseError(path, 0, "location", "a location of the records file", "'" + name + "'");
        chosen.push_back(all[it->second]);
    }
    return chosen;
}

}  // namespace pilempm::io
