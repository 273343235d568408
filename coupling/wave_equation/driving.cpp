#include "coupling/wave_equation/driving.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "fem/hammer/blow_stepper.hpp"
#include "fem/dynamics/section_gauge.hpp"

namespace pilempm::coupling {

double BlowOutcome::energy_error() const {
    const double accounted = energy_pile + energy_hammer + energy_soil_plastic + energy_soil_damping +
                             energy_soil_elastic;
    return energy_in > 0.0 ? std::abs(accounted - energy_in) / energy_in : 0.0;
}

SmithSoil make_smith_soil(const fem::ExplicitPile& pile, const ResistanceDistribution& r,
                          const SmithParameters& p, double pile_impedance) {
    const auto& mesh = pile.mesh();
    if (mesh.dim != 1) throw std::invalid_argument("Smith soil needs the rod pile model");
    const int nn = mesh.num_nodes();
    const double L = mesh.length(), pen = r.penetration;
    const double total = r.total();
    auto dashpot = [&](double r_u, double j) {
        return p.law == DampingLaw::SmithViscous ? j * r_u
                                                 : (total > 0.0 ? j * pile_impedance * r_u / total : 0.0);
    };
    SmithSoil soil;
    // Nodes of the rod mesh are in z order (toe first).
    for (int i = 0; i < nn; ++i) {
        const double z = mesh.z(i);
        const double lo = i == 0 ? 0.0 : 0.5 * (mesh.z(i - 1) + z);
        const double hi = i + 1 == nn ? L : 0.5 * (z + mesh.z(i + 1));
        if (lo >= pen) break;
        const double r_u = r.shaft_between(pen - hi, pen - lo);  // depth = pen - z
        // Smith: the dashpots of the soil the node carries, each layer with its own J.
        const double c = p.law == DampingLaw::SmithViscous
                             ? r.shaft_dashpot_between(pen - hi, pen - lo, p.shaft_damping)
                             : dashpot(r_u, p.shaft_damping);
        if (r_u > 0.0) soil.add_point(i, r_u, p.shaft_quake, c, false);
    }
    if (r.toe > 0.0) soil.add_point(0, r.toe, p.toe_quake, dashpot(r.toe, p.toe_damping), true);
    return soil;
}

BlowOutcome simulate_blow(fem::ExplicitPile& pile, SmithSoil& soil, const fem::HammerSpec& hammer,
                          double ram_element_size, const BlowOptions& options, HeadRecord* record) {
    fem::BlowStepper stepper(pile, hammer, ram_element_size, &soil);
    const auto& mesh = pile.mesh();
    const double dt = options.time_step_factor * stepper.stable_time_step();
    const double L = mesh.length();
    const double round_trip = 2.0 * L / pile.steel().wave_speed();
    const bool prescribed = hammer.kind == fem::HammerKind::PrescribedForce;
    const double duration = options.dynamic_duration > 0.0 ? options.dynamic_duration
                            : prescribed ? hammer.force.end_time() + 4.0 * round_trip
                                         : 5.0 * round_trip + 0.02;
    const long steps = static_cast<long>(std::ceil(duration / dt));
    const fem::SectionGauge head(mesh, L);

    // Energy baseline of the state the blow starts from (residual stresses included).
    pile.compute_internal_force();
    const double strain0 = pile.strain_energy();
    const double soil_elastic0 = soil.elastic_energy(), plastic0 = soil.plastic_work;
    const double toe0 = pile.toe_displacement();

    BlowOutcome out;
    if (record) record->clear();
    std::vector<double> stress(mesh.num_elements());
    const auto& v = stepper.velocity_at_step();
    double enthru = 0.0, damping = 0.0, work = 0.0;
    double prev_power = 0.0, prev_damping = 0.0, prev_work = 0.0;
    for (long n = 0; n <= steps; ++n) {
        stepper.kick(n * dt, dt);
        pile.axial_stress(stress);
        for (double s : stress) {
            out.max_compression_stress = std::max(out.max_compression_stress, -s);
            out.max_tension_stress = std::max(out.max_tension_stress, s);
        }
        const double f_head = head.force_compression(stress), v_head = head.velocity_down(v, mesh);
        out.peak_head_force = std::max(out.peak_head_force, f_head);
        if (record) {
            record->time.push_back(n * dt);
            record->force.push_back(f_head);
            record->velocity.push_back(v_head);
        }
        const double power = f_head * v_head, damp = pile.dashpot_power(v);
        const double load = stepper.applied_force() * v_head;
        if (n > 0) {
            enthru += 0.5 * dt * (power + prev_power);
            damping += 0.5 * dt * (damp + prev_damping);
            work += 0.5 * dt * (load + prev_work);
        }
        prev_power = power, prev_damping = damp, prev_work = load;
        out.enthru = std::max(out.enthru, enthru);
        if (n == steps) {  // energy record at the end of the dynamic phase, t_n
            const fem::HammerChain* chain = stepper.chain();
            out.energy_in = chain ? chain->impact_energy() + chain->gravity_work() : work;
            out.energy_pile = pile.kinetic_energy(v) + pile.strain_energy() - strain0;
            out.energy_hammer = chain ? chain->kinetic_energy() + chain->stored_energy() +
                                            chain->dissipated_energy()
                                      : 0.0;
            out.energy_soil_plastic = soil.plastic_work - plastic0;
            out.energy_soil_damping = damping;
            out.energy_soil_elastic = soil.elastic_energy() - soil_elastic0;
        }
        stepper.drift(dt);
    }
    out.steps = steps + 1;

    // Kinetic damping to rest: zero every velocity at each peak of kinetic energy; done
    // when a peak is a negligible fraction of the blow's energy.
    const double tiny = 1e-9 * std::max(out.energy_in, 1.0);
    double ke_prev = 0.0, peak = 0.0;
    for (long k = 0; k < options.max_rest_steps; ++k) {
        stepper.kick((steps + 1 + k) * dt, dt);
        const double ke = stepper.kinetic_energy();
        peak = std::max(peak, ke);
        if (ke < ke_prev) {
            stepper.stop();
            if (peak < tiny) break;
            peak = 0.0;
            ke_prev = 0.0;
        } else {
            ke_prev = ke;
        }
        stepper.drift(dt);
        ++out.steps;
    }
    pile.stop();
    out.set = -(pile.toe_displacement() - toe0);
    return out;
}

PenetrationResult drive_at_penetration(const fem::PileMesh& mesh, const fem::LinearElasticSteel& steel,
                                       const ResistanceDistribution& srd, const SmithParameters& smith,
                                       const fem::HammerSpec& hammer, double ram_element_size,
                                       const DrivingOptions& options, HeadRecord* last_record) {
    fem::ExplicitPile pile(mesh, steel, {fem::ToeCondition::Free, 0.0});
    const fem::SectionGauge head(pile.mesh(), pile.mesh().length());
    const double impedance = head.area() * steel.youngs_modulus / steel.wave_speed();
    SmithSoil soil = make_smith_soil(pile, srd, smith, impedance);
    soil.attach_dashpots(pile);

    PenetrationResult r;
    r.penetration = srd.penetration;
    r.srd_shaft = srd.shaft_total();
    r.srd_toe = srd.toe;
    const double cap = 10.0 * options.refusal_blow_count;
    double previous = 0.0;
    for (int b = 1; b <= options.max_blows; ++b) {
        r.last = simulate_blow(pile, soil, hammer, ram_element_size, options.blow, last_record);
        r.blows = b;
        const double set = r.last.set;
        if (b >= 2 && std::abs(set - previous) <= options.steady_tolerance * std::abs(set)) {
            r.steady = true;
            break;
        }
        // Far beyond refusal the set is noise; no need to make it steady.
        if (b >= 2 && set < 0.25 / cap) break;
        previous = set;
    }
    r.set = r.last.set;
    r.blows_per_quarter_metre = r.set > 0.25 / cap ? 0.25 / r.set : cap;
    r.refusal = r.blows_per_quarter_metre > options.refusal_blow_count;
    return r;
}

double static_push_capacity(fem::ExplicitPile& pile, SmithSoil& soil, double velocity,
                            double displacement) {
    const auto& mesh = pile.mesh();
    const fem::SectionGauge head(mesh, mesh.length());
    const double dt = 0.9 * std::min(pile.stable_time_step(), soil.stable_time_step(pile));
    // A smooth start (cosine ramp over 10 round trips) so the push rings no waves.
    const double ramp = 20.0 * mesh.length() / pile.steel().wave_speed();
    std::vector<double> stress(mesh.num_elements());
    double peak = 0.0, pushed = 0.0;
    for (long n = 0; pushed < displacement && n < 50'000'000; ++n) {
        const double t = n * dt;
        const double v = velocity * (t < ramp ? 0.5 * (1.0 - std::cos(std::numbers::pi * t / ramp)) : 1.0);
        pile.compute_internal_force();
        pile.clear_external_force();
        soil.add_forces(pile);
        pile.advance_velocity(dt);
        pile.add_head_velocity(-v - pile.head_velocity());
        pile.axial_stress(stress);
        peak = std::max(peak, head.force_compression(stress));
        pile.advance_displacement(dt);
        pushed += v * dt;
    }
    return peak;
}

}  // namespace pilempm::coupling
