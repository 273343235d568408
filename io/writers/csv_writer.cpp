#include "io/writers/csv_writer.hpp"

#include <cstdio>
#include <memory>
#include <stdexcept>

namespace pilempm::io {

void write_csv(const std::filesystem::path& file, const Table& table) {
    write_csv(file, table, {}, {});
}

void write_csv(const std::filesystem::path& file, const Table& table, const std::vector<std::string>& text_names,
               const std::vector<std::vector<std::string>>& text) {
    const std::size_t rows = table.rows();
    if (text.size() != text_names.size()) throw std::logic_error("write_csv: text columns and names differ");
    for (const auto& col : text)
        if (col.size() != rows) throw std::logic_error("write_csv: a text column's length differs from the table's");
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(file.c_str(), "w"), &std::fclose);
    if (!f) throw std::runtime_error("cannot write " + file.string());
    bool first = true;
    auto sep = [&first, &f] {
        if (!first) std::fputc(',', f.get());
        first = false;
    };
    for (const auto& n : text_names) sep(), std::fputs(n.c_str(), f.get());
    for (const auto& n : table.columns) sep(), std::fputs(n.c_str(), f.get());
    std::fputc('\n', f.get());
    for (std::size_t r = 0; r < rows; ++r) {
        first = true;
        for (const auto& col : text) sep(), std::fputs(col[r].c_str(), f.get());
        for (std::size_t c = 0; c < table.columns.size(); ++c) sep(), std::fprintf(f.get(), "%.10g", table.data[c][r]);
        std::fputc('\n', f.get());
    }
    if (std::ferror(f.get())) throw std::runtime_error("error writing " + file.string());
}

}  // namespace pilempm::io
