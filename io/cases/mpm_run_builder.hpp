#pragma once
// An MPM case turned into a run: the model (grid, points, materials, boundaries, initial
// stress), the loads and stages the stage driver switches, and what the recorders watch.
#include <vector>

#include "coupling/contact/coupled_pile.hpp"
#include "coupling/driver/stage_driver.hpp"
#include "io/cases/mpm_case.hpp"

namespace pilempm::io {

template <int D>
struct MpmRun {
    mpm::MpmModel<D> model;
    std::vector<coupling::StageSpec> stages;
    std::vector<coupling::StageLoad> loads;
    coupling::DriverSettings settings;
    std::vector<int> probe_points;    // the material point nearest each output.probes entry
    std::vector<int> reaction_nodes;  // grid nodes with prescribed velocities
    std::vector<double> x0;           // initial point positions
    // The FE pile (pile.present): its wall mesh and steel, the contact, its frame and
    // weight, the head's control per stage.
    struct Pile {
        bool present = false;
        fem::PileMesh mesh;
        fem::LinearElasticSteel steel;
        coupling::ContactSettings contact;
        coupling::PileFrame frame;
        double gravity = 0.0;
        bool cut_fields = true;
        coupling::ToeSlipLine toe_slip_line;
        std::vector<coupling::PileHeadControl> heads;
    } pile;
};

// Throws std::runtime_error when the regions hold no material point.
template <int D>
MpmRun<D> build_mpm_run(const MpmCase& c);

// The names of the state arrays written per point: those of the material with the most.
template <int D>
std::vector<std::string> state_names(const mpm::MpmModel<D>& m);

extern template MpmRun<2> build_mpm_run<2>(const MpmCase&);
extern template MpmRun<3> build_mpm_run<3>(const MpmCase&);

}  // namespace pilempm::io
