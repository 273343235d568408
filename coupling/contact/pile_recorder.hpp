#pragma once
// The coupled pile's columns in a run's history: the head's settlement and the jack's
// force, the soil's axial resistance on the pile split into outer shaft, inner shaft and
// base (the toe's annulus), the points in contact, those let go inside the pile and the
// deepest penetration, the toe's elevation and the head's velocity (down positive), the
// hammer's work (ENTHRU), the steel's largest axial compression and tension, the mean excess
// pore pressure just below the toe, the length of the soil plug (open piles) and the
// pile's own energy (strain and kinetic).
#include "coupling/contact/coupled_pile.hpp"
#include "coupling/driver/recorders.hpp"

#include <vector>

namespace pilempm::coupling {

class PileRecorder final : public Recorder<2> {
public:
    explicit PileRecorder(const CoupledPile& pile) : pile_(pile) {}
    void add_columns(std::vector<std::string>& columns) const override;
    void sample(const mpm::MpmModel<2>& m, const mpm::MpmSolver<2>& solver, std::vector<double>& row) const override;

private:
    const CoupledPile& pile_;
    mutable std::vector<double> stress_;  // per element, reused
};

}  // namespace pilempm::coupling
