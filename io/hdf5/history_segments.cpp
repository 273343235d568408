#include "io/hdf5/history_segments.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "io/hdf5/mpm_checkpoint.hpp"

namespace pilempm::io {

namespace fs = std::filesystem;

namespace {

// Rows [begin, end) of t, in its columns.
Table rows_of(const Table& t, std::size_t begin, std::size_t end) {
    Table part(t.name, t.columns);
    for (std::size_t k = 0; k < t.columns.size(); ++k)
        part.data[k].assign(t.data[k].begin() + static_cast<std::ptrdiff_t>(begin),
                            t.data[k].begin() + static_cast<std::ptrdiff_t>(end));
    return part;
}

}  // namespace

fs::path history_segment_path(const fs::path& dir, std::size_t index) {
    char name[40];
    std::snprintf(name, sizeof name, "checkpoint-history-%04zu.h5", index);
    return dir / name;
}

HistorySegments::HistorySegments(fs::path dir, std::size_t segment_rows)
    : dir_(std::move(dir)), segment_rows_(segment_rows) {
    if (segment_rows_ == 0) throw std::invalid_argument("HistorySegments: segment_rows must be positive");
}

void HistorySegments::adopt(std::vector<double> rows_per_segment) {
    rows_ = std::move(rows_per_segment);
    sealed_ = 0;
    for (double r : rows_) sealed_ += static_cast<std::size_t>(r);
}

Table HistorySegments::seal(const Table& history) {
    const std::size_t rows = history.rows();
    if (rows < sealed_)
        throw std::logic_error("HistorySegments: the history has fewer rows than are sealed");
    while (rows - sealed_ >= segment_rows_) {
        write_table_file(history_segment_path(dir_, rows_.size()),
                         {rows_of(history, sealed_, sealed_ + segment_rows_)});
        rows_.push_back(static_cast<double>(segment_rows_));
        sealed_ += segment_rows_;
    }
    return rows_of(history, sealed_, rows);
}

Table assemble_history(const fs::path& dir, const std::vector<double>& rows_per_segment, const Table& tail) {
    std::size_t total = tail.rows();
    for (double r : rows_per_segment) total += static_cast<std::size_t>(r);
    Table whole(tail.name, tail.columns);
    for (auto& column : whole.data) column.reserve(total);
    for (std::size_t s = 0; s < rows_per_segment.size(); ++s) {
        const fs::path file = history_segment_path(dir, s);
        if (!fs::exists(file))
            throw std::runtime_error(file.string() + ": missing (the checkpoint's history continues in it)");
        const std::vector<Table> tables = read_table_file(file);
        if (tables.size() != 1 || tables.front().name != tail.name)
            throw std::runtime_error(file.string() + ": not a segment of the " + tail.name + " table");
        const Table& part = tables.front();
        const auto expected = static_cast<std::size_t>(rows_per_segment[s]);
        if (part.rows() != expected)
            throw std::runtime_error(file.string() + ": " + std::to_string(part.rows()) + " rows, the checkpoint says " +
                                     std::to_string(expected));
        for (const auto& name : part.columns) {
            bool known = false;
            for (const auto& c : tail.columns) known = known || c == name;
            if (!known)
                throw std::runtime_error(file.string() + ": column " + name + " is not in the checkpoint's history");
        }
        for (std::size_t k = 0; k < whole.columns.size(); ++k) {
            const std::vector<double>* from = nullptr;
            for (std::size_t j = 0; j < part.columns.size(); ++j)
                if (part.columns[j] == whole.columns[k]) from = &part.data[j];
            if (from) whole.data[k].insert(whole.data[k].end(), from->begin(), from->end());
            else whole.data[k].insert(whole.data[k].end(), expected, std::numeric_limits<double>::quiet_NaN());
        }
    }
    for (std::size_t k = 0; k < whole.columns.size(); ++k)
        whole.data[k].insert(whole.data[k].end(), tail.data[k].begin(), tail.data[k].end());
    return whole;
}

}  // namespace pilempm::io
