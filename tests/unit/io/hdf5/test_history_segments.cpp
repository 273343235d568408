// A long run's history sealed in segment files beside its checkpoint: the segments and the
// tail the checkpoint carries join back into the history bit for bit; a segment written by
// an earlier build with fewer columns reads NaN in them; a missing or altered segment is a
// clear error naming its file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/table.hpp"
#include "io/hdf5/history_segments.hpp"
#include "io/hdf5/mpm_checkpoint.hpp"

namespace fs = std::filesystem;
using pilempm::Table;
using pilempm::io::assemble_history;
using pilempm::io::history_segment_path;
using pilempm::io::HistorySegments;

namespace {

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("pilempm-segments-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// Rows of values that differ in every bit pattern (no two alike, none round).
void grow(Table& t, std::size_t rows) {
    for (std::size_t r = t.rows(), end = t.rows() + rows; r < end; ++r)
        for (std::size_t k = 0; k < t.columns.size(); ++k)
            t.data[k].push_back(std::sin(1.0 + 0.37 * static_cast<double>(r)) * std::pow(10.0, static_cast<double>(k)) / 3.0);
}

bool same_bits(const Table& a, const Table& b) {
    if (a.columns != b.columns || a.rows() != b.rows()) return false;
    for (std::size_t k = 0; k < a.columns.size(); ++k)
        for (std::size_t r = 0; r < a.rows(); ++r)
            if (std::memcmp(&a.data[k][r], &b.data[k][r], sizeof(double)) != 0) return false;
    return true;
}

}  // namespace

TEST(HistorySegments, SealedSegmentsAndTheTailJoinBackIntoTheHistoryBitForBit) {
    const fs::path dir = scratch("join");
    Table history("history", {"time_s", "step", "force_N"});
    grow(history, 250);
    HistorySegments segments(dir, 100);
    Table tail = segments.seal(history);
    EXPECT_EQ(tail.rows(), 50u);
    EXPECT_EQ(segments.rows_per_segment(), (std::vector<double>{100.0, 100.0}));
    EXPECT_TRUE(fs::exists(history_segment_path(dir, 1)));
    EXPECT_FALSE(fs::exists(history_segment_path(dir, 2)));
    EXPECT_TRUE(same_bits(assemble_history(dir, segments.rows_per_segment(), tail), history));

    // A later checkpoint seals only what has grown into a whole segment since.
    const auto first_written = fs::last_write_time(history_segment_path(dir, 0));
    grow(history, 120);
    tail = segments.seal(history);
    EXPECT_EQ(tail.rows(), 70u);
    EXPECT_EQ(segments.sealed_rows(), 300u);
    EXPECT_EQ(fs::last_write_time(history_segment_path(dir, 0)), first_written);
    EXPECT_TRUE(same_bits(assemble_history(dir, segments.rows_per_segment(), tail), history));

    // A resumed run adopts its checkpoint's segments and goes on sealing after them.
    HistorySegments resumed(dir, 100);
    resumed.adopt(segments.rows_per_segment());
    grow(history, 40);
    tail = resumed.seal(history);
    EXPECT_EQ(resumed.rows_per_segment().size(), 4u);
    EXPECT_EQ(tail.rows(), 10u);
    EXPECT_TRUE(same_bits(assemble_history(dir, resumed.rows_per_segment(), tail), history));
    fs::remove_all(dir);
}

TEST(HistorySegments, ASegmentWithoutALaterBuildsColumnReadsNaNThere) {
    const fs::path dir = scratch("older");
    Table older("history", {"time_s", "step"});
    grow(older, 4);
    pilempm::io::write_table_file(history_segment_path(dir, 0), {older});
    Table tail("history", {"time_s", "step", "shaft_pore_pressure_Pa"});
    grow(tail, 2);
    const Table whole = assemble_history(dir, {4.0}, tail);
    ASSERT_EQ(whole.rows(), 6u);
    for (std::size_t r = 0; r < 4; ++r) {
        EXPECT_EQ(whole.data[0][r], older.data[0][r]);
        EXPECT_TRUE(std::isnan(whole.data[2][r]));
    }
    EXPECT_EQ(whole.data[2][4], tail.data[2][0]);
    fs::remove_all(dir);
}

TEST(HistorySegments, AMissingOrAlteredSegmentIsAnErrorNamingItsFile) {
    const fs::path dir = scratch("errors");
    Table history("history", {"time_s"});
    grow(history, 30);
    HistorySegments segments(dir, 10);
    const Table tail = segments.seal(history);
    auto message = [&](const std::vector<double>& rows) {
        try {
            assemble_history(dir, rows, tail);
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    // The checkpoint says the segment holds 12 rows; it holds 10.
    EXPECT_NE(message({10.0, 12.0, 10.0}).find("checkpoint-history-0001.h5: 10 rows, the checkpoint says 12"),
              std::string::npos);
    fs::remove(history_segment_path(dir, 2));
    EXPECT_NE(message({10.0, 10.0, 10.0}).find("checkpoint-history-0002.h5: missing"), std::string::npos);
    // A column the checkpoint's history does not have: not this run's segment.
    Table other("history", {"time_s", "elsewhere"});
    grow(other, 10);
    pilempm::io::write_table_file(history_segment_path(dir, 2), {other});
    EXPECT_NE(message({10.0, 10.0, 10.0}).find("column elsewhere is not in the checkpoint's history"), std::string::npos);
    fs::remove_all(dir);
}
