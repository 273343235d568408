#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "core/table.hpp"

namespace pilempm::io {

// Writes a table as CSV with a header row; full double precision so spreadsheets and
// scripts read back exactly what was computed.
void write_csv(const std::filesystem::path& file, const Table& table);

// The same with leading text columns (a location code, a soil case name): text[c][row].
void write_csv(const std::filesystem::path& file, const Table& table, const std::vector<std::string>& text_names,
               const std::vector<std::vector<std::string>>& text);

}  // namespace pilempm::io
