#pragma once
// The coupled pile's columns in a run's history: the head's settlement and the jack's
// force, the soil's axial resistance on the pile split into outer shaft, inner shaft (and
// their sum) and base (the toe's annulus), the points in contact, those let go inside the pile and the
// deepest penetration, the toe's elevation and the head's velocity (down positive), the
// hammer's work (ENTHRU), the steel's largest axial compression and tension, the mean excess
// pore pressure just below the toe, the length of the soil plug (open piles), the
// pile's own energy (strain and kinetic) and its weight's work, and the mean excess pore
// pressure beside the outer shaft in the upper, middle and lower third of its embedment
// below the seabed.
#include "coupling/contact/coupled_pile.hpp"
#include "coupling/driver/recorders.hpp"

#include <vector>

namespace pilempm::coupling {

class PileRecorder final : public Recorder<2> {
public:
    // ground_elevation: the seabed in the soil's frame, m (the top of the embedment).
    PileRecorder(const CoupledPile& pile, double ground_elevation) : pile_(pile), ground_(ground_elevation) {}
    void add_columns(std::vector<std::string>& columns) const override;
    void sample(const mpm::MpmModel<2>& m, const mpm::MpmSolver<2>& solver, std::vector<double>& row) const override;

private:
    const CoupledPile& pile_;
    double ground_;
    mutable std::vector<double> stress_;  // per element, reused
};

}  // namespace pilempm::coupling
