#pragma once
#include <filesystem>

#include "core/table.hpp"

namespace pilempm::io {

// Writes a table as CSV with a header row; full double precision so spreadsheets and
// scripts read back exactly what was computed.
void write_csv(const std::filesystem::path& file, const Table& table);

}  // namespace pilempm::io
