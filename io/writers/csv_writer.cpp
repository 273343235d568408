#include "io/writers/csv_writer.hpp"

#include <cstdio>
#include <memory>
#include <stdexcept>

namespace pilempm::io {

void write_csv(const std::filesystem::path& file, const Table& table) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(file.c_str(), "w"), &std::fclose);
    if (!f) throw std::runtime_error("cannot write " + file.string());
    for (std::size_t c = 0; c < table.columns.size(); ++c)
        std::fprintf(f.get(), "%s%s", c ? "," : "", table.columns[c].c_str());
    std::fputc('\n', f.get());
    const std::size_t rows = table.rows();
    for (std::size_t r = 0; r < rows; ++r) {
        for (std::size_t c = 0; c < table.columns.size(); ++c)
            std::fprintf(f.get(), "%s%.10g", c ? "," : "", table.data[c][r]);
        std::fputc('\n', f.get());
    }
    if (std::ferror(f.get())) throw std::runtime_error("error writing " + file.string());
}

}  // namespace pilempm::io
