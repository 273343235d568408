#pragma once
// A body the soil's stages carry along (the FE pile): before each of the soil's steps it
// puts its contact forces on the points and advances itself over the step; it may ask for
// a shorter step; it comes to rest with the soil at a quasi-static stage's end.
#include <string>
#include <utility>
#include <vector>

#include "mpm/solver/mpm_solver.hpp"

namespace pilempm::coupling {

template <int D>
class CoupledBody {
public:
    virtual ~CoupledBody() = default;
    virtual double stable_time_step(const mpm::MpmModel<D>& m, double soil_dt) const = 0;
    // time_in_stage: s since the stage began (0 throughout a quasi-static stage).
    virtual void before_step(mpm::MpmModel<D>& m, int stage, bool quasi_static, double dt, double time_in_stage) = 0;
    virtual void come_to_rest() = 0;
    // After the soil's step: its grid masses and the points' weights of that step (a
    // contact's stable step from the grid).
    virtual void after_step(const mpm::MpmModel<D>& /*m*/, const std::vector<mpm::Stencil<D>>& /*stencils*/) {}
    // After a step in which the soil moved at rest (a pause's consolidation step), the body
    // follows the soil it bears on; x_before: the points' positions before that step.
    virtual void follow_soil(const mpm::MpmModel<D>& /*m*/, const std::vector<double>& /*x_before*/) {}
    // Its fastest node's speed (m/s) and its toe's elevation (m, the soil's frame): when a
    // blow has died out, and how far the body has gone.
    virtual double max_speed() const = 0;
    virtual double toe_elevation() const = 0;
    // Its out-of-balance force over the forces it carries (a quasi-static stage ends when
    // this and the soil's are both below its tolerance; 0: in balance whatever it does).
    virtual double unbalanced_force_ratio() const { return 0.0; }
    // A blow settling (StageSpec::settle_damping): the body damps its own motion, rigid
    // motion too, with Cundall's local damping alpha (0: not settling).
    virtual void set_settling(double /*alpha*/) {}
    // The stage's gravity over the case's (n g in a centrifuge) for the body's own weight.
    virtual void set_gravity_factor(double factor) = 0;
    // Its state for a checkpoint, and back: named arrays of doubles.
    virtual std::vector<std::pair<std::string, std::vector<double>>> state() const = 0;
    virtual void restore(const std::vector<std::pair<std::string, std::vector<double>>>& arrays) = 0;
};

}  // namespace pilempm::coupling
