#pragma once
// Restartable checkpoint of an MPM run (HDF5): the material points bit for bit plus the
// run's time, step, named scalars and a fingerprint of the case it belongs to. HDF5 stays
// out of this header.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/table.hpp"
#include "mpm/points/particles.hpp"

namespace pilempm::io {

// What a run keeps besides its particles and scalars: named arrays (the snapshot times)
// and tables (the history so far), so a resumed run carries on with all of them.
struct CheckpointExtras {
    std::vector<std::pair<std::string, std::vector<double>>> arrays;
    std::vector<Table> tables;
};

struct CheckpointInfo {
    double time = 0.0;
    long step = 0;
    std::vector<std::pair<std::string, double>> scalars;  // in the order written
    CheckpointExtras extras;
    std::string case_fingerprint;
    int dimension = 0;
};

// File layout (all datasets 1-D, row-major per point, little-endian):
//  /particles/x, v, external_force         D per point, double
//  /particles/mass, volume, volume0        1 per point, double
//  /particles/C, F, domain0                D*D per point, double
//  /particles/stress, strain               6 per point, double
//  /particles/material, field              1 per point, int32 (field: format 4)
//  /particles/state                        state_stride per point, double; attribute
//                                          "state_stride" (int)
//  /scalars                                double dataset, attribute "names" (string array)
//  /arrays/<name>                          double dataset per named array (format 3)
//  /tables/<name>/column_<k>               double dataset per column, the group's attribute
//                                          "columns" (string array) names them (format 3)
//  root attributes  format = "pilempm-mpm-checkpoint", format_version (int), dimension (int),
//                   num_points (int64), time (double), step (int64), fingerprint (string)
// Particles::dstrain is per-step scratch and is not stored (read_checkpoint zeroes it).
//
// The file is written as `file` + ".tmp" and renamed over `file` only once complete and
// synced, so a crash mid-write leaves the previous checkpoint intact. Throws
// std::runtime_error naming the file on any failure (the .tmp is removed); input whose
// arrays disagree with p.size() is refused before any file is touched.
template <int D>
void write_checkpoint(const std::filesystem::path& file, const mpm::Particles<D>& p, double time,
                      long step, const std::vector<std::pair<std::string, double>>& scalars,
                      const std::string& case_fingerprint, const CheckpointExtras& extras = {});

// Reads a checkpoint written by write_checkpoint<D> into p (replacing all its contents;
// dstrain becomes zeros). Throws std::runtime_error naming the file and the problem when the
// file cannot be opened or is not such a checkpoint, when it was written for another
// dimension, or when an array has the wrong rank, type or size; p is then left unchanged.
template <int D>
CheckpointInfo read_checkpoint(const std::filesystem::path& file, mpm::Particles<D>& p);

// A file of tables alone (the sealed parts of a long run's history, history_segments.hpp),
// laid out as a checkpoint's /tables (root attribute format = "pilempm-tables") and written
// the same way: Fletcher32 checksums, `file` + ".tmp" renamed over `file` once synced. Both
// throw std::runtime_error naming the file.
void write_table_file(const std::filesystem::path& file, const std::vector<Table>& tables);
std::vector<Table> read_table_file(const std::filesystem::path& file);

extern template void write_checkpoint<2>(const std::filesystem::path&, const mpm::Particles<2>&,
                                         double, long,
                                         const std::vector<std::pair<std::string, double>>&,
                                         const std::string&, const CheckpointExtras&);
extern template void write_checkpoint<3>(const std::filesystem::path&, const mpm::Particles<3>&,
                                         double, long,
                                         const std::vector<std::pair<std::string, double>>&,
                                         const std::string&, const CheckpointExtras&);
extern template CheckpointInfo read_checkpoint<2>(const std::filesystem::path&,
                                                  mpm::Particles<2>&);
extern template CheckpointInfo read_checkpoint<3>(const std::filesystem::path&,
                                                  mpm::Particles<3>&);

}  // namespace pilempm::io
