#pragma once
// ParaView output of the pile over time: one .vtu per step plus a .pvd collection that
// carries the step times, so ParaView animates the stress wave running down the pile.
// VTK stays behind a pimpl: callers of this header need no VTK include paths.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "fem/mesh/pile_mesh.hpp"

namespace pilempm::io {

// Writes the pile mesh over time as dir/<basename>_NNNNNN.vtu files plus
// dir/<basename>.pvd (ParaView collection).
class PileVtkSeries {
public:
    PileVtkSeries(std::filesystem::path dir, const fem::PileMesh& mesh,
                  std::string basename = "pile");
    ~PileVtkSeries();  // calls finish(), so a run stopped by an exception still gets a .pvd
    PileVtkSeries(PileVtkSeries&&) noexcept;
    PileVtkSeries& operator=(PileVtkSeries&&) noexcept;
    PileVtkSeries(const PileVtkSeries&) = delete;
    PileVtkSeries& operator=(const PileVtkSeries&) = delete;

    // displacement, velocity: mesh.num_dofs() values (mesh.dim per node); axial_stress: one
    // value per element over all blocks in block order (Pa, tension positive).
    void write(double time, const std::vector<double>& displacement,
               const std::vector<double>& velocity, const std::vector<double>& axial_stress);

    // The same with each node's contact force (2 per node: radial and axial, N), for a
    // pile in MPM soil; the array is written as point data "contact_force_N".
    void write(double time, const std::vector<double>& displacement, const std::vector<double>& velocity,
               const std::vector<double>& axial_stress, const std::vector<double>& contact_force);

    // A resumed run: the steps the interrupted run wrote, at these times, stay in the series.
    void adopt_written_steps(const std::vector<double>& times);

    // Writes the .pvd listing all steps with their times; idempotent. Steps written after
    // a finish() are picked up by the next finish().
    void finish();

    std::size_t steps_written() const;
    std::filesystem::path pvd_path() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace pilempm::io
