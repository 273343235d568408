#pragma once
// A long run's history beside its checkpoint, in two parts: whole segments of rows sealed
// once into files of their own (checkpoint-history-0000.h5, ...) and never rewritten, and
// the rows after them, which each checkpoint carries. A checkpoint's cost then stays that of
// one segment however long the drive (a blow records ~2 500 rows; after 300 blows each
// checkpoint rewrote 265 MB of history, twice a blow).
#include <cstddef>
#include <filesystem>
#include <vector>

#include "core/table.hpp"

namespace pilempm::io {

class HistorySegments {
public:
    // dir: the run's working folder (the checkpoint's); segment_rows > 0.
    HistorySegments(std::filesystem::path dir, std::size_t segment_rows);

    // A resumed run: the segments its checkpoint names (rows in each, in order).
    void adopt(std::vector<double> rows_per_segment);
    // Seals into new files the whole segments of `history` past the rows already sealed and
    // returns the rows after all sealed ones (what the checkpoint carries). A segment file
    // left by a run that stopped before its next checkpoint is written over.
    Table seal(const Table& history);

    const std::vector<double>& rows_per_segment() const { return rows_; }
    std::size_t sealed_rows() const { return sealed_; }

private:
    std::filesystem::path dir_;
    std::size_t segment_rows_;
    std::vector<double> rows_;  // double: the checkpoint stores it as an array
    std::size_t sealed_ = 0;
};

// The file of segment `index` in `dir`.
std::filesystem::path history_segment_path(const std::filesystem::path& dir, std::size_t index);

// The history a checkpoint stands for: its segments' rows in order, then `tail`, in the
// tail's columns. A column a segment lacks (written by an earlier build) reads NaN in its
// rows. Throws std::runtime_error naming the file when a segment is missing, holds other
// rows than the checkpoint says, or a column the tail does not have.
Table assemble_history(const std::filesystem::path& dir, const std::vector<double>& rows_per_segment,
                       const Table& tail);

}  // namespace pilempm::io
