#pragma once
// Columns of numbers from a CSV file named in a case file (force records, CPT records):
// the path is relative to the case file; a header row and '#' comments are allowed; every
// row has the named columns and the first column increases. Errors are CaseErrors naming
// the case key (missing file) or the CSV file and row.
#include <string>
#include <vector>

#include "io/yaml/yaml_reader.hpp"

namespace pilempm::io {

struct NumericFile {
    std::string path;                        // as opened
    std::vector<std::vector<double>> columns;
};

NumericFile read_numeric_file(const MapReader& m, const std::string& key,
                              const std::vector<std::string>& column_names, std::size_t min_rows = 2);

}  // namespace pilempm::io
