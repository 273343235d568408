#include "io/yaml/numeric_file.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace pilempm::io {

NumericFile read_numeric_file(const MapReader& m, const std::string& key,
                              const std::vector<std::string>& names, std::size_t min_rows) {
    std::string header;
    for (std::size_t i = 0; i < names.size(); ++i) header += (i ? "," : "") + names[i];
    namespace fs = std::filesystem;
    MapReader copy = m;
    fs::path p(copy.text_or(key, ""));
    if (p.is_relative()) p = fs::path(m.file()).parent_path() / p;
    NumericFile out{p.string(), std::vector<std::vector<double>>(names.size())};
    std::ifstream in(p);
    if (!in)
        throw CaseError(m.file(), m.line_of(key), m.path() + "." + key, "a readable CSV file of " + header,
                        p.string() + " missing");
    std::string line;
    int lineno = 0;
    std::size_t rows = 0;
    while (std::getline(in, line)) {
        ++lineno;
        if (line.empty() || line[0] == '#') continue;
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream s(line);
        std::vector<double> row(names.size());
        bool ok = true;
        for (double& x : row) ok = ok && static_cast<bool>(s >> x);
        if (!ok) {
            if (rows == 0 && lineno == 1) continue;  // a header row
            throw CaseError(out.path, lineno, header, std::to_string(names.size()) + " numbers per row",
                            "'" + line + "'");
        }
        if (rows > 0 && !(row[0] > out.columns[0].back()))
            throw CaseError(out.path, lineno, names[0], "values that increase row by row", std::to_string(row[0]));
        for (std::size_t c = 0; c < row.size(); ++c) out.columns[c].push_back(row[c]);
        ++rows;
    }
    if (rows < min_rows)
        throw CaseError(out.path, lineno, header, "at least " + std::to_string(min_rows) + " rows", std::to_string(rows));
    return out;
}

}  // namespace pilempm::io
