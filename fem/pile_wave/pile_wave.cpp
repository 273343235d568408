#include "fem/pile_wave/pile_wave.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "fem/hammer/blow_stepper.hpp"
#include "fem/dynamics/section_gauge.hpp"

namespace pilempm::fem {

const Table& PileWaveResult::table(const std::string& name) const {
    for (const auto& t : tables)
        if (t.name == name) return t;
    throw std::out_of_range("no result table named " + name);
}

double pile_wave_stable_time_step(const fem::ExplicitPile& pile, const PileWaveSetup& setup) {
    return blow_stable_time_step(pile, setup.hammer, setup.ram_element_size);
}

namespace {

std::string gauge_table_name(double depth) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "gauge_%.2fm", depth);
    return buf;
}

// Max compression and tension over elements of one depth row, from per-element extremes.
Table stress_envelope(const fem::PileMesh& mesh, double length, const std::vector<double>& smin,
                      const std::vector<double>& smax) {
    std::map<long, std::pair<double, double>> rows;  // key: centroid z in micrometres
    std::size_t k = 0;
    for (const auto& b : mesh.blocks) {
        for (int e = 0; e < b.num_elements(); ++e, ++k) {
            const long key = std::lround(b.centroid_z[e] * 1e6);
            auto [it, fresh] = rows.try_emplace(key, -smin[k], smax[k]);
            if (!fresh) {
                it->second.first = std::max(it->second.first, -smin[k]);
                it->second.second = std::max(it->second.second, smax[k]);
            }
        }
    }
    Table t("stress_envelope", {"depth_below_head_m", "max_compression_Pa", "max_tension_Pa"});
    for (auto it = rows.rbegin(); it != rows.rend(); ++it)
        t.add_row({length - it->first * 1e-6, std::max(0.0, it->second.first),
                   std::max(0.0, it->second.second)});
    return t;
}

}  // namespace

PileWaveResult run_pile_wave(const PileWaveSetup& setup, PileWaveObserver* observer) {
    fem::ExplicitPile pile(setup.mesh, setup.steel, setup.toe);
    const auto& mesh = pile.mesh();
    BlowStepper stepper(pile, setup.hammer, setup.ram_element_size);
    const HammerChain* chain = stepper.chain();

    const double stable = pile_wave_stable_time_step(pile, setup);
    const double dt = setup.time_step > 0.0 ? setup.time_step : setup.time_step_factor * stable;
    if (!(dt > 0.0)) throw std::invalid_argument("time step must be positive");
    const long steps = static_cast<long>(std::ceil(setup.duration / dt - 1e-9));

    double length = 0.0;
    for (int n = 0; n < mesh.num_nodes(); ++n) length = std::max(length, mesh.z(n));
    const SectionGauge head(mesh, length), toe(mesh, 0.0);
    std::vector<SectionGauge> gauges;
    for (double d : setup.gauge_depths) gauges.emplace_back(mesh, length - d);

    const double c = setup.steel.wave_speed();
    const double impedance = head.area() * setup.steel.youngs_modulus / c;

    PileWaveResult result;
    Table head_t("pile_head", {"time_s", "force_compression_N", "velocity_down_m_s",
                               "impedance_times_velocity_N"});
    Table toe_t("toe", {"time_s", "force_compression_N", "velocity_down_m_s",
                        "displacement_down_m", "support_reaction_compression_N"});
    Table energy_t("energy", {"time_s", "pile_kinetic_J", "pile_strain_J", "hammer_kinetic_J",
                              "hammer_stored_J", "toe_dashpot_dissipated_J",
                              "work_of_prescribed_force_J", "enthru_J", "hammer_dissipated_J",
                              "gravity_work_on_hammer_J"});
    std::vector<Table> gauge_t;
    for (std::size_t g = 0; g < gauges.size(); ++g)
        gauge_t.emplace_back(gauge_table_name(setup.gauge_depths[g]),
                             std::vector<std::string>{"time_s", "force_compression_N",
                                                      "velocity_down_m_s", "stress_compression_Pa"});

    const int ne = mesh.num_elements();
    std::vector<double> stress(ne), smin(ne, 0.0), smax(ne, 0.0);
    const std::vector<double>& v_avg = stepper.velocity_at_step();
    double enthru = 0.0, max_enthru = 0.0, work = 0.0, dissipated = 0.0, peak_head = 0.0;
    double prev_power = 0.0, prev_work_power = 0.0, prev_diss = 0.0;
    const double snap = setup.snapshot_interval;
    double next_snapshot = 0.0;
    const long progress_every = std::max(1L, steps / 200);

    for (long n = 0; n <= steps; ++n) {
        const double t = n * dt;
        stepper.kick(t, dt);
        const double applied = stepper.applied_force();
        // Record the state at t_n: stress from u_n, velocity as the mean of the half steps.
        pile.axial_stress(stress);
        for (int e = 0; e < ne; ++e) {
            smin[e] = std::min(smin[e], stress[e]);
            smax[e] = std::max(smax[e], stress[e]);
        }
        const double f_head = head.force_compression(stress);
        const double v_head = head.velocity_down(v_avg, mesh);
        peak_head = std::max(peak_head, f_head);
        // Trapezoidal time integrals of the head power, the load's power and the dashpot.
        const double power = f_head * v_head;
        const double work_power = applied * v_head;
        const double diss = pile.dashpot_power(v_avg);
        if (n > 0) {
            enthru += 0.5 * dt * (power + prev_power);
            work += 0.5 * dt * (work_power + prev_work_power);
            dissipated += 0.5 * dt * (diss + prev_diss);
        }
        prev_power = power;
        prev_work_power = work_power;
        prev_diss = diss;
        max_enthru = std::max(max_enthru, enthru);

        head_t.add_row({t, f_head, v_head, impedance * v_head});
        toe_t.add_row({t, toe.force_compression(stress), toe.velocity_down(v_avg, mesh),
                       toe.displacement_down(pile.displacement(), mesh), pile.toe_reaction()});
        for (std::size_t g = 0; g < gauges.size(); ++g) {
            const double f = gauges[g].force_compression(stress);
            gauge_t[g].add_row({t, f, gauges[g].velocity_down(v_avg, mesh), f / gauges[g].area()});
        }
        energy_t.add_row({t, pile.kinetic_energy(v_avg), pile.strain_energy(),
                          chain ? chain->kinetic_energy() : 0.0, chain ? chain->stored_energy() : 0.0,
                          dissipated, work, enthru, chain ? chain->dissipated_energy() : 0.0,
                          chain ? chain->gravity_work() : 0.0});

        if (observer && snap > 0.0 && t >= next_snapshot - 1e-12) {
            observer->on_snapshot(t, pile, v_avg, stress);
            next_snapshot += snap;
        }
        if (observer && (n % progress_every == 0 || n == steps)) observer->on_progress(t, setup.duration, n);

        stepper.drift(dt);
    }

    auto& s = result.summary;
    s.peak_head_force = peak_head;
    s.enthru = enthru;
    s.max_enthru = max_enthru;
    if (chain) {
        s.hammer_energy = chain->impact_energy();
    }
    s.wave_speed = c;
    s.head_impedance = impedance;
    s.head_area = head.area();
    s.toe_area = toe.area();
    s.time_step = dt;
    s.stable_time_step = stable;
    s.steps = steps;
    s.elements = ne;
    s.nodes = mesh.num_nodes();
    s.pile_mass = pile.operators().total_mass;
    s.pile_length = length;

    result.envelope = stress_envelope(mesh, length, smin, smax);
    const auto& env = result.envelope;
    for (std::size_t r = 0; r < env.rows(); ++r) {
        if (env.data[1][r] > s.max_compression_stress) {
            s.max_compression_stress = env.data[1][r];
            s.max_compression_depth = env.data[0][r];
        }
        if (env.data[2][r] > s.max_tension_stress) {
            s.max_tension_stress = env.data[2][r];
            s.max_tension_depth = env.data[0][r];
        }
    }
    result.tables.push_back(std::move(head_t));
    result.tables.push_back(std::move(toe_t));
    result.tables.push_back(std::move(energy_t));
    for (auto& g : gauge_t) result.tables.push_back(std::move(g));
    result.final_displacement = pile.displacement();
    result.final_velocity = std::vector<double>(v_avg.begin(), v_avg.end());
    result.final_axial_stress = stress;
    return result;
}

}  // namespace pilempm::fem
