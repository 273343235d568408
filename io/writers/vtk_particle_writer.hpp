#pragma once
// ParaView output of the MPM material points over time: one .vtu per step (an unstructured
// grid of VTK_VERTEX cells, one per point) plus a .pvd collection carrying the step times.
// VTK stays behind a pimpl: callers of this header need no VTK include paths.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "mpm/materials/pore_water.hpp"
#include "mpm/points/particles.hpp"

namespace pilempm::io {

// Writes dir/<basename>_NNNNNN.vtu per write() and dir/<basename>.pvd on finish() (a run
// calls it at each checkpoint and at its end).
// Points are padded to 3-D: in 2-D (x, y) -> (x, y, 0), y up (x = r when axisymmetric).
// Point data of every step:
//   velocity     3 components (2-D padded with 0), m/s
//   stress       6 components, Voigt [xx, yy, zz, xy, yz, zx], Pa, tension positive;
//                components named XX YY ZZ XY YZ XZ so ParaView treats it as a symmetric tensor
//   strain       6 components, same order and names, TENSOR shear (eps_xy = gamma_xy / 2),
//                i.e. Particles::strain with its engineering shear halved, so ParaView's
//                tensor filters (eigenvalues, invariants) see the true strain tensor
//   mean_stress  (s_xx + s_yy + s_zz) / 3, Pa, tension positive
//   von_mises    sqrt(3 J2), Pa
//   volume, mass (per unit thickness / per radian in 2-D), material (int)
//   one scalar per state variable k < p.state_stride, named state_names[k] when given and
//   not empty, "state_<k>" otherwise (names beyond state_stride are not used)
// With pore water (set_pore_water), besides:
//   pore_pressure (total: hydrostatic + excess) and excess_pore_pressure, Pa, compression
//   positive; water_velocity (3 components), m/s; porosity; mobilised_friction_angle (deg,
//   from the principal effective stresses) and degree_of_mobilisation (its sine over the
//   material's sin phi; 0 for materials without a friction angle)
// plus field data "TimeValue". Appended raw binary, zlib compressed. A .vtu appears under its
// final name only once complete (written to a temporary name and renamed).
template <int D>
class ParticleVtkSeries {
    static_assert(D == 2 || D == 3, "ParticleVtkSeries: D must be 2 or 3");

public:
    // Throws std::invalid_argument for a basename that is not a plain file name or state
    // names that repeat or collide with the fixed arrays; std::runtime_error when dir cannot
    // be created.
    explicit ParticleVtkSeries(std::filesystem::path dir, std::string basename = "particles",
                               std::vector<std::string> state_names = {});
    ~ParticleVtkSeries();  // calls finish(), so a run stopped by an exception still gets a .pvd
    ParticleVtkSeries(ParticleVtkSeries&&) noexcept;
    ParticleVtkSeries& operator=(ParticleVtkSeries&&) noexcept;
    ParticleVtkSeries(const ParticleVtkSeries&) = delete;
    ParticleVtkSeries& operator=(const ParticleVtkSeries&) = delete;

    // Throws std::invalid_argument when the arrays of p disagree with p.size() or time is not
    // finite, std::runtime_error (naming the file) when the file cannot be written.
    void write(double time, const mpm::Particles<D>& p);
    // Saturated soil: the water (for the hydrostatic part) and each material's friction angle, deg.
    void set_pore_water(const mpm::PoreWater& water, std::vector<double> friction_angle_deg);

    // Writes the .pvd listing all steps with their times; idempotent. Steps written after a
    // finish() are picked up by the next finish().
    void finish();

    std::size_t steps_written() const;
    std::vector<double> step_times() const;
    // A resumed run's series: the steps an earlier run wrote into dir (their files are there)
    // are listed again, so numbering and the .pvd carry on from them. Only before write().
    void adopt_written_steps(const std::vector<double>& times);
    std::filesystem::path pvd_path() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

extern template class ParticleVtkSeries<2>;
extern template class ParticleVtkSeries<3>;

// von Mises equivalent stress sqrt(3 J2) of a Voigt stress [xx, yy, zz, xy, yz, zx].
double von_mises_stress(const double* s);

}  // namespace pilempm::io
