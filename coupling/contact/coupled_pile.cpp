#include "coupling/contact/coupled_pile.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace pilempm::coupling {

CoupledPile::CoupledPile(fem::ExplicitPile& pile, ContactSettings contact, PileFrame frame, double gravity,
                         bool cut_fields, ToeSlipLine slip)
    : pile_(pile), contact_(contact), frame_(frame), gravity_(gravity), cut_fields_(cut_fields), slip_(slip),
      surface_(pile_contact_surface(pile.mesh())) {
    const auto& mass = pile_.operators().lumped_mass;
    surface_.inverse_mass.resize(pile_.mesh().num_nodes());
    for (int i = 0; i < pile_.mesh().num_nodes(); ++i) {
        surface_.inverse_mass[i] = 1.0 / mass[2 * i + 1];
        mass_ += mass[2 * i + 1];
    }
}

namespace {

// The head's target at time t of a stage: its velocity (down positive) or its force
// (compression positive), risen from the last stage's.
double head_target(const std::vector<PileHeadControl>& heads, int stage, double t) {
    const PileHeadControl& h = heads[stage];
    const double to = h.driven ? h.velocity_down : h.force;
    if (h.rise_time <= 0.0 || t >= h.rise_time) return to;
    double from = 0.0;
    if (stage > 0) {
        const PileHeadControl& last = heads[stage - 1];
        if (h.driven && last.driven) from = last.velocity_down;
        if (h.loaded && last.loaded) from = last.force;
    }
    const double s = std::sin(0.5 * std::numbers::pi * std::max(t, 0.0) / h.rise_time);
    return from + (to - from) * s * s;
}

}  // namespace

void CoupledPile::advance(mpm::MpmModel<2>& m, double dt, int stage, double time_in_stage) {
    place_pile_surface(surface_, pile_.mesh(), pile_.displacement(), pile_.velocity(), frame_);
    if (cut_fields_ || slip_.length > 0.0) {
        // Each cut doubles the fields (a point's field: the sum of the offsets of the cuts
        // between it and the node).
        int offset = m.grid.water ? 2 : 1;
        m.field_cuts.clear();
        auto add = [&](mpm::FieldCut cut, const char* what) {
            if (m.grid.fields < 2 * offset)
                throw std::invalid_argument(std::string(what) + " needs a grid of " + std::to_string(2 * offset) +
                                            " velocity fields");
            cut.offset = offset;
            cut.bound();
            m.field_cuts.push_back(std::move(cut));
            offset *= 2;
        };
        if (cut_fields_) add({pile_mid_line(pile_.mesh(), pile_.displacement(), frame_)}, "the soil either side of the pile's wall");
        if (slip_.length > 0.0) {
            mpm::FieldCut line{toe_slip_line(surface_, slip_.length)};
            line.contact_segments = 1;  // the slip line; the shaft above it is a wall
            line.friction = slip_.friction;
            add(std::move(line), "the toe's slip line");
        }
    }
    contact_.compute(m.particles, m.shape, surface_, dt, m.materials);
    const auto& segment_force = contact_.segment_force();
    if (stage != mean_stage_) mean_stage_ = stage, stage_time_ = 0.0, stage_impulse_.assign(segment_force.size(), 0.0);
    for (std::size_t k = 0; k < segment_force.size(); ++k) stage_impulse_[k] += segment_force[k] * dt;
    stage_time_ += dt;
    // The steel is impermeable: the pore water does not cross the surface the soil touches.
    m.water_walls.clear();
    if (m.grid.water)
        for (const ContactTouch& t : contact_.touches())
            m.water_walls.push_back({t.point, {t.normal[0], t.normal[1], 0.0}, {t.on_surface[0], t.on_surface[1], 0.0}});
    contact_dt_ = contact_.totals().stable_time_step;
    const PileHeadControl head = stage < static_cast<int>(head_.size()) ? head_[stage] : PileHeadControl{};
    // The target over the step: its mid-time's.
    const double target = head.driven || head.loaded ? head_target(head_, stage, time_in_stage + 0.5 * dt) : 0.0;
    // A damped stage damps the pile's vibration about its rigid motion: 5 % of critical in
    // its first axial mode (fixed-free, omega_1 = pi c / 2 L), less in the higher ones, and
    // stiffness-proportionally as much as halving its stable step allows (xi = 0.75 at the
    // highest mode; up to 5 % in the first mode, a short pile's).
    // Every stage damps what the soil's step cannot carry: stiffness-proportional,
    // 1 % of critical at omega = 1 / dt (a blow's first mode some 1e-5, a 1 ms pulse's band
    // 1e-4). The contact's force, held over the soil's step while the pile subcycles,
    // otherwise feeds the pile's modes near pi / dt (the resonance of multiple-time-step
    // methods): a struck pile left ringing in the soil grew without bound
    // (coupled-ringing-pile.yaml; README).
    const double length = pile_.mesh().z(pile_.mesh().head_nodes.front());
    const double omega1 = std::numbers::pi * pile_.steel().wave_speed() / (2.0 * length);
    const bool damped = m.local_damping > 0.0;
    const double strongest = std::min(2.0 * 0.05 / omega1, 0.75 * pile_.operators().stable_time_step);
    pile_.set_vibration_damping(damped ? 2.0 * 0.05 * omega1 : 0.0);
    // A damped stage's local damping also stills the pile on its contact springs, split into
    // its rigid motion and its vibration (ExplicitPile::set_split_damping; a nil step's pile
    // chattered there, the soil's unbalanced force 0.18 of its load after 20 000 steps),
    // unless the head is driven (it would drag a jacked pile).
    pile_.set_local_damping(settling_);
    pile_.set_split_damping(settling_ == 0.0 && damped && !head.driven ? m.local_damping : 0.0);
    pile_.set_stiffness_damping(std::max(2.0 * kStepModeDamping * dt, damped ? strongest : 0.0));
    double blow_impulse = 0.0;  // down positive
    if (head.struck && enthru_stage_ != stage) {
        // A new blow: the ram meets the head where it now is.
        enthru_ = 0.0, enthru_stage_ = stage;
        chain_.reset();
        if (head.hammer.kind == fem::HammerKind::RamCushion)
            chain_.emplace(head.hammer.ram_cushion, head.ram_element_size, pile_.head_displacement());
    }
    if (!head.struck) enthru_ = 0.0, enthru_stage_ = -1, chain_.reset();
    // Subcycles of the pile inside the soil's step, the contact force held over them.
    double pile_dt = 0.95 * pile_.damped_stable_time_step();
    if (chain_) pile_dt = std::min(pile_dt, 0.95 * chain_->stable_time_step(pile_.head_mass(), pile_.operators().max_frequency));
    substeps_ = std::max(1, static_cast<int>(std::ceil(dt / pile_dt)));
    const double sub = dt / substeps_;
    const auto& f = contact_.nodal_force();
    const auto& mass = pile_.operators().lumped_mass;
    const int nodes = pile_.mesh().num_nodes();
    double jack_impulse = 0.0;  // up positive
    for (int s = 0; s < substeps_; ++s) {
        pile_.compute_internal_force();
        pile_.clear_external_force();
        for (int i = 0; i < nodes; ++i) {
            pile_.add_nodal_force(2 * i, f[2 * i]);
            pile_.add_nodal_force(2 * i + 1, f[2 * i + 1] - mass[2 * i + 1] * gravity_ * gravity_factor_);
        }
        if (head.loaded) pile_.add_head_force(-target);
        double f_blow = 0.0;
        if (chain_) {
            chain_->compute_forces(pile_);  // the cushions' forces at t_n on the head
        } else if (head.struck) {
            // The hammer's force over the substep, at its mid-time (the blow starts with the stage).
            f_blow = head.hammer.force.at(time_in_stage + (s + 0.5) * sub);
            pile_.add_head_force(-f_blow);
        }
        pile_.advance_velocity(sub);
        if (chain_) {
            chain_->advance_velocity(sub);
            chain_->resolve_contacts(sub, pile_);  // a ram or helmet resting on the head: its impulse
            f_blow = chain_->force_on_head();
        }
        blow_impulse += f_blow * sub;
        if (head.driven) {
            // The jack sets the head plate's velocity: the impulse that takes is its force.
            const double dv = -target - pile_.head_velocity();
            pile_.add_head_velocity(dv);
            jack_impulse += pile_.head_mass() * dv;
        }
        const double head_before = pile_.head_displacement();
        pile_.advance_displacement(sub);
        if (chain_) chain_->advance_displacement(sub);
        enthru_ -= f_blow * (pile_.head_displacement() - head_before);  // the force down, the head down
    }
    head_force_ = head.struck ? blow_impulse / dt : head.loaded ? target : -jack_impulse / dt;
}

void CoupledPile::step(mpm::MpmSolver<2>& soil, mpm::MpmModel<2>& m, double dt, int stage) {
    advance(m, dt, stage);
    soil.step(dt);
    after_step(m, soil.stencils());
}

double CoupledPile::unbalanced_force_ratio() const {
    double up = 0.0;
    for (const auto& side : contact_.totals().force_by_side) up += side[1];
    const double weight = mass_ * gravity_ * gravity_factor_;
    const double scale = weight + std::abs(head_force_);
    return scale > 0.0 ? std::abs(up - weight - head_force_) / scale : 0.0;
}

double CoupledPile::weight_work() const {
    const auto& mass = pile_.operators().lumped_mass;
    const auto& u = pile_.displacement();
    double down = 0.0;  // sum of m u_z, settlement positive
    for (int i = 0; i < pile_.mesh().num_nodes(); ++i) down -= mass[2 * i + 1] * u[2 * i + 1];
    return down * gravity_ * gravity_factor_;
}

// A pause holds the contact forces while the soil consolidates under them: the pile moves
// with the soil it bears on (the mean settlement of the points it pushes, weighted by the
// vertical force on each), so that the next blow's first contact finds the gaps the forces
// were held at, not opened by the settlement (the pile then fell under its weight into the
// blow: the North Sea monopile's ENTHRU +3 %).
void CoupledPile::follow_soil(const mpm::MpmModel<2>& m, const std::vector<double>& x_before) {
    const auto& p = m.particles;
    double moved = 0.0, weight = 0.0;
    for (const ContactTouch& t : contact_.touches()) {
        const long i = t.point;
        const double w = std::abs(p.external_force[2 * i + 1]);  // the contact's force on it, held
        moved += w * (p.x[2 * i + 1] - x_before[2 * i + 1]);
        weight += w;
    }
    if (weight > 0.0) pile_.translate_axially(moved / weight);
    // The surface with it: the pause's history records where the pile is (the next blow's
    // first step places it anyway).
    place_pile_surface(surface_, pile_.mesh(), pile_.displacement(), pile_.velocity(), frame_);
}

std::vector<double> CoupledPile::stage_mean_segment_force() const {
    std::vector<double> mean(stage_impulse_.size(), 0.0);
    if (stage_time_ > 0.0)
        for (std::size_t k = 0; k < mean.size(); ++k) mean[k] = stage_impulse_[k] / stage_time_;
    return mean;
}

double CoupledPile::max_speed() const {
    const auto& v = pile_.velocity();
    double fastest = 0.0;
    for (std::size_t k = 0; k + 1 < v.size(); k += 2) fastest = std::max(fastest, std::hypot(v[k], v[k + 1]));
    return fastest;
}

std::array<double, 2> CoupledPile::momentum() const {
    std::array<double, 2> p{};
    const auto& v = pile_.velocity();
    const auto& mass = pile_.operators().lumped_mass;
    for (std::size_t k = 0; k < v.size(); ++k) p[k % 2] += mass[k] * v[k];
    return p;
}

std::vector<std::pair<std::string, std::vector<double>>> CoupledPile::state() const {
    std::vector<double> segment(contact_.segment().begin(), contact_.segment().end());
    std::vector<std::pair<std::string, std::vector<double>>> out = {{"pile_displacement", pile_.displacement()},
            {"pile_velocity", pile_.velocity()},
            {"pile_internal_force", pile_.internal_force()},
            {"contact_tangential_force", contact_.tangential_force()},
            {"contact_segment", segment},
            {"contact_overlap", contact_.overlap()},
            {"contact_started", {contact_.started() ? 1.0 : 0.0}},
            {"pile_head_force", {head_force_}},
            {"pile_enthru", {enthru_, static_cast<double>(enthru_stage_)}},
            {"hammer_chain", chain_ ? chain_->state() : std::vector<double>{}},
            {"contact_time_step", {contact_dt_}}};
    std::vector<double> mean = {static_cast<double>(mean_stage_), stage_time_};
    mean.insert(mean.end(), stage_impulse_.begin(), stage_impulse_.end());
    out.push_back({"contact_stage_impulse", std::move(mean)});
    for (auto& entry : contact_.outputs()) out.push_back(std::move(entry));
    return out;
}

void CoupledPile::restore(const std::vector<std::pair<std::string, std::vector<double>>>& arrays) {
    auto find = [&](const std::string& name) -> const std::vector<double>& {
        for (const auto& [key, values] : arrays)
            if (key == name) return values;
        throw std::runtime_error("the checkpoint has no " + name + " (written without the pile?)");
    };
    // What checkpoints before 2026-12-06 lack: the pile's internal force, the contact's outputs.
    auto has = [&](const std::string& name) {
        return std::any_of(arrays.begin(), arrays.end(), [&](const auto& entry) { return entry.first == name; });
    };
    pile_.restore(find("pile_displacement"), find("pile_velocity"),
                  has("pile_internal_force") ? find("pile_internal_force") : std::vector<double>{});
    const auto& seg = find("contact_segment");
    contact_.restore(find("contact_tangential_force"), std::vector<int>(seg.begin(), seg.end()), find("contact_overlap"),
                     find("contact_started").at(0) != 0.0);
    head_force_ = find("pile_head_force").at(0);
    enthru_ = find("pile_enthru").at(0);
    enthru_stage_ = static_cast<int>(find("pile_enthru").at(1));
    // A blow's chain back as it was: rebuilt from its stage's spec, then its state.
    chain_.reset();
    const auto& chain = find("hammer_chain");
    if (!chain.empty()) {
        const PileHeadControl& h = head_.at(static_cast<std::size_t>(enthru_stage_));
        chain_.emplace(h.hammer.ram_cushion, h.ram_element_size, 0.0);
        chain_->restore(chain);
    }
    contact_dt_ = find("contact_time_step").at(0);
    if (has("contact_totals"))
        contact_.restore_outputs(find("contact_nodal_force"), find("contact_segment_force"), find("contact_totals"),
                                 find("contact_touches"));
    // The stage's segment impulse so far (checkpoints before 2026-12-07 lack it: the mean
    // then starts at the resumed step).
    mean_stage_ = -1, stage_time_ = 0.0, stage_impulse_.clear();
    if (has("contact_stage_impulse")) {
        const auto& mean = find("contact_stage_impulse");
        mean_stage_ = static_cast<int>(mean.at(0));
        stage_time_ = mean.at(1);
        stage_impulse_.assign(mean.begin() + 2, mean.end());
    }
    // The surface where the restored pile is: a run resumed in a pause records its toe from
    // it before any step places it (it recorded the toe at 0 m).
    place_pile_surface(surface_, pile_.mesh(), pile_.displacement(), pile_.velocity(), frame_);
}

}  // namespace pilempm::coupling
