#pragma once
// The single results file of a run (HDF5): every table, the mesh and the final state, so a
// post-processing script needs nothing else. HDF5 stays out of this header.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/table.hpp"
#include "fem/mesh/pile_mesh.hpp"

namespace pilempm::io {

// Writes the results file (truncating it):
//  /<table.name>      one group per Table, one 1-D double dataset per column (dataset name =
//                     column name) and a string-array attribute "columns" listing them in order;
//  /mesh              "coordinates" (N x dim), "block_<k>" connectivity (elements x nodes, int)
//                     with string attribute "kind" = element_kind_name(kind), "head_nodes",
//                     "toe_nodes"; attribute "dim";
//  /final_state       "displacement", "velocity" (N x dim), "axial_stress_Pa" (one per element),
//                     left out when all three are empty (a study of many blows);
//  root attributes    numeric from `attributes`, strings from `text_attributes`.
// '/' in table or column names becomes '_' (HDF5 path separator); '.' is kept.
// Throws std::runtime_error naming the file on any failure, and removes the partial file.
void write_results_h5(const std::filesystem::path& file, const std::vector<Table>& tables,
                      const fem::PileMesh& mesh, const std::vector<double>& displacement,
                      const std::vector<double>& velocity,
                      const std::vector<double>& axial_stress,
                      const std::vector<std::pair<std::string, double>>& attributes,
                      const std::vector<std::pair<std::string, std::string>>& text_attributes);

// The HDF5 object name used for a table or column name.
std::string hdf5_object_name(const std::string& name);

}  // namespace pilempm::io
