#pragma once
// What a run records into its history, one row per sample: each recorder adds its columns
// (named with units and sign) and fills them from the model and solver. The coupled model
// adds its own (pile head, contact forces) beside these.
#include <memory>
#include <string>
#include <vector>

#include "core/table.hpp"
#include "mpm/solver/mpm_solver.hpp"

namespace pilempm::coupling {

template <int D>
class Recorder {
public:
    virtual ~Recorder() = default;
    virtual void add_columns(std::vector<std::string>& columns) const = 0;
    virtual void sample(const mpm::MpmModel<D>& m, const mpm::MpmSolver<D>& solver, std::vector<double>& row) const = 0;
};

// Kinetic and elastic energy, the energy the absorbing boundaries took out, the unbalanced
// force ratio of the last step, and the work the external forces did.
template <int D>
class EnergyRecorder final : public Recorder<D> {
public:
    void add_columns(std::vector<std::string>& columns) const override;
    void sample(const mpm::MpmModel<D>& m, const mpm::MpmSolver<D>& solver, std::vector<double>& row) const override;
};

// What a long run must not lose: the points' mass (the grains' where the soil is coupled to
// its water, the whole soil's where dry or undrained), their volume and the pore water's
// volume n V; the grains' volume (1 - n) V is the difference. Per radian in axisymmetry, as
// the soil's energies.
template <int D>
class ConservationRecorder final : public Recorder<D> {
public:
    void add_columns(std::vector<std::string>& columns) const override;
    void sample(const mpm::MpmModel<D>& m, const mpm::MpmSolver<D>& solver, std::vector<double>& row) const override;
};

// Sum of the reactions of the grid nodes with prescribed velocities, per axis, N.
template <int D>
class ReactionRecorder final : public Recorder<D> {
public:
    explicit ReactionRecorder(std::vector<int> nodes) : nodes_(std::move(nodes)) {}
    void add_columns(std::vector<std::string>& columns) const override;
    void sample(const mpm::MpmModel<D>& m, const mpm::MpmSolver<D>& solver, std::vector<double>& row) const override;

private:
    std::vector<int> nodes_;
};

// Vertical velocity, vertical stress and horizontal (x) velocity of given material points;
// with pore water also their excess pore pressure and vertical water velocity.
template <int D>
class ProbeRecorder final : public Recorder<D> {
public:
    explicit ProbeRecorder(std::vector<int> points, bool pore_water = false)
        : points_(std::move(points)), pore_water_(pore_water) {}
    void add_columns(std::vector<std::string>& columns) const override;
    void sample(const mpm::MpmModel<D>& m, const mpm::MpmSolver<D>& solver, std::vector<double>& row) const override;

private:
    std::vector<int> points_;
    bool pore_water_;
};

// 0.5 sigma : eps V summed over the points (the strain energy of a linear-elastic body).
template <int D>
double elastic_energy(const mpm::Particles<D>& p);
// The strain energy of the pore water's excess pressure, 0.5 p^2 n / K_w V (0 when dry).
template <int D>
double pore_water_energy(const mpm::MpmModel<D>& m);

}  // namespace pilempm::coupling
