#pragma once
// Field records of pile driving as CSV with a header row (the layout of the ISFOG 2020
// records, shared/data/isfog2020/README.md): per location and depth the CPT (q_c, f_s,
// u_2 in MPa) and, where driven, the blow count, the normalised hammer energy and the
// cumulative blows, with the pile's diameter, toe wall and final penetration. Columns are
// found by name; empty cells are missing values. Errors name the file, row and column.
#include <string>
#include <vector>

#include "coupling/wave_equation/cpt_interpretation.hpp"

namespace pilempm::io {

// A CSV file's cells by header name.
struct HeaderedCsv {
    std::string path;
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;  // rows[r][c], trimmed
    std::vector<int> lines;                      // file line of each row
    int column(const std::string& name) const;   // -1 when absent
    // The column as numbers (NaN for an empty cell); a missing column or a cell that is
    // not a number is a CaseError naming the file, line and column.
    std::vector<double> numbers(const std::string& name) const;
};
HeaderedCsv read_headered_csv(const std::string& path);

struct FieldRecord {
    std::string location;
    coupling::CptSounding cpt;           // Pa
    // The driven depths (blow count recorded), increasing.
    std::vector<double> driven_depth, blows_per_m, normalised_energy, cumulative_blows;
    double diameter = 0.0, toe_wall = 0.0, final_penetration = 0.0;  // m
};

// All locations of a records file in their order of appearance; `only` (if not empty)
// selects and orders them, and a location it names that the file lacks is an error.
std::vector<FieldRecord> read_field_records(const std::string& path, const std::vector<std::string>& only = {});

}  // namespace pilempm::io
