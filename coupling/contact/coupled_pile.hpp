#pragma once
// The FE pile in the MPM soil, one MPM step at a time: the contact forces from the points
// and the pile at t_n, then the pile subcycled over the step (its stable step is smaller)
// with those forces held, then the soil's step with the same forces on its points. The
// interface impulse f dt is therefore the same on both sides: pile + soil momentum is
// conserved to round-off. Per stage the head is free, driven at a set velocity (jacking, a
// displacement-controlled load test; 0 holds it; the jack's force recorded) or pushed by a
// set force (a maintained load test).
#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "coupling/contact/penalty_contact.hpp"
#include "coupling/contact/pile_surface.hpp"
#include "coupling/driver/coupled_body.hpp"
#include "fem/dynamics/explicit_pile.hpp"
#include "fem/hammer/hammer.hpp"
#include "mpm/solver/mpm_solver.hpp"

namespace pilempm::coupling {

struct PileHeadControl {
    bool driven = false;         // the head driven at velocity_down (0: held)
    double velocity_down = 0.0;  // m/s
    bool loaded = false;         // the head pushed down by force (a maintained load test)
    double force = 0.0;          // N, compression positive
    // s: the velocity (or force) goes over from the last stage's (0 when it had none) to
    // this one's as sin^2 over this time, so the jack does not ring the pile; 0: at once.
    double rise_time = 0.0;
    // A blow: the hammer strikes the head at the stage's start (the head otherwise free):
    // a prescribed force, or a ram-cushion chain stepped with the pile (its rod elements
    // the pile's element size).
    bool struck = false;
    fem::HammerSpec hammer;
    double ram_element_size = 0.0;  // m
};

// A slip line through the soil from the toe's outer corner (pile_surface.hpp, toe_slip_line):
// the soil pushed ahead of the toe and the soil beside the shaft on grid fields of their
// own, in frictional contact along it, so the soil ahead does not drag the shaft's soil
// down through the grid nodes they would share. length 0: none.
struct ToeSlipLine {
    double length = 0.0;    // m
    double friction = 0.0;  // Coulomb coefficient across it: tan of the soil's friction angle
};

class CoupledPile final : public CoupledBody<2> {
public:
    // gravity: the pile's own weight, m/s^2 down, at a stage's gravity factor of 1. cut_fields: the
    // soil inside and outside an open wall on their own grid fields (a grid of 2 fields, 4
    // with water), the cut along the wall's mid-line moving with it. slip: a toe slip line
    // moving with the pile (twice the fields again).
    CoupledPile(fem::ExplicitPile& pile, ContactSettings contact, PileFrame frame, double gravity = 0.0,
                bool cut_fields = true, ToeSlipLine slip = {});

    // The head's control in each stage (index); stages beyond the list leave it free.
    void set_head_control(std::vector<PileHeadControl> per_stage) { head_ = std::move(per_stage); }

    // Contact and the pile over dt (stage: whose head control, time_in_stage: where in its
    // rise), the soil's step left to the caller.
    void advance(mpm::MpmModel<2>& m, double dt, int stage = 0, double time_in_stage = 1e300);
    // advance(), then the soil's step: the whole coupled step.
    void step(mpm::MpmSolver<2>& soil, mpm::MpmModel<2>& m, double dt, int stage = 0);

    // The soil's step, or the contact's where it is shorter (its penalty's stability).
    double stable_time_step(const mpm::MpmModel<2>&, double soil_dt) const override {
        return std::min(soil_dt, contact_dt_);
    }
    void before_step(mpm::MpmModel<2>& m, int stage, bool quasi_static, double dt, double time_in_stage) override {
        advance(m, dt, stage, quasi_static ? 1e300 : time_in_stage);
    }
    // The contact's step from the grid the soil's step scattered to (PenaltyContact::grid_stable_time_step).
    void after_step(const mpm::MpmModel<2>& m, const std::vector<mpm::Stencil<2>>& stencils) override {
        if (stencils.size() == m.particles.size())
            contact_dt_ = contact_.grid_stable_time_step(m.grid.mass, stencils, surface_);
    }
    // At rest, the last blow over (its ENTHRU and hammer gone: a pause records none).
    void come_to_rest() override {
        pile_.stop();
        enthru_ = 0.0, enthru_stage_ = -1;
        chain_.reset();
    }
    double max_speed() const override;
    double toe_elevation() const override { return frame_.toe_elevation + pile_.toe_displacement(); }
    // |soil's axial force + weight + head load| over weight + |head load|, of the last step.
    double unbalanced_force_ratio() const override;
    void set_gravity_factor(double factor) override { gravity_factor_ = factor; }
    void set_settling(double alpha) override { settling_ = alpha; }
    void follow_soil(const mpm::MpmModel<2>& m, const std::vector<double>& x_before) override;
    std::vector<std::pair<std::string, std::vector<double>>> state() const override;
    void restore(const std::vector<std::pair<std::string, std::vector<double>>>& arrays) override;

    fem::ExplicitPile& pile() { return pile_; }
    const fem::ExplicitPile& pile() const { return pile_; }
    const PenaltyContact& contact() const { return contact_; }
    // The mean force on each surface segment (2 per segment, N, the master's measure) over
    // the last stage the pile stepped in: its impulse over the stage's time. A contact that
    // chatters puts the whole load on a segment one step and none the next; the mean is what
    // the soil bore there (a traction profile to compare with measured ones).
    std::vector<double> stage_mean_segment_force() const;
    double stage_time() const { return stage_time_; }  // s (pseudo-time in a quasi-static stage)
    const ContactSurface& surface() const { return surface_; }
    const PileFrame& frame() const { return frame_; }
    int substeps() const { return substeps_; }
    // The jack's force on the head over the last step (N, compression positive; 0 when free).
    double head_force() const { return head_force_; }
    // The hammer's work on the head since the blow's stage began (J, the whole ring): the
    // energy it has put through the head, a PDA's ENTHRU; 0 outside blows.
    double enthru() const { return enthru_; }
    double head_settlement() const { return -pile_.head_displacement(); }  // m, down positive
    // The work of the pile's weight (at the present gravity factor) since it was placed: its
    // mass times g times its centre of mass's settlement, J (the blow's energy ledger).
    double weight_work() const;
    double mass() const { return mass_; }  // kg, the whole ring's (the lumped axial mass)
    // The pile's momentum (the whole ring; velocities at the last half step), N s.
    std::array<double, 2> momentum() const;
    // Damping ratio of the pile at omega = 1 / dt in an undamped stage (coupled_pile.cpp).
    static constexpr double kStepModeDamping = 0.01;

private:
    fem::ExplicitPile& pile_;
    PenaltyContact contact_;
    PileFrame frame_;
    double gravity_;
    double gravity_factor_ = 1.0;
    double mass_ = 0.0;  // kg, summed once: the pile's mass does not change
    double settling_ = 0.0;  // Cundall's alpha on the pile while a blow settles
    bool cut_fields_;
    ToeSlipLine slip_;
    ContactSurface surface_;
    std::vector<PileHeadControl> head_;
    int substeps_ = 1;
    double contact_dt_ = 1e300;  // s: the step the contact allows (none yet)
    double head_force_ = 0.0;
    double enthru_ = 0.0;     // J, this blow's so far
    int enthru_stage_ = -1;   // the stage it counts
    std::optional<fem::HammerChain> chain_;  // a ram-cushion blow's hammer, from its impact on
    int mean_stage_ = -1;                 // the stage the segments' impulse is summed over
    double stage_time_ = 0.0;             // s, its steps' sum
    std::vector<double> stage_impulse_;   // N s, 2 per segment
};

}  // namespace pilempm::coupling
