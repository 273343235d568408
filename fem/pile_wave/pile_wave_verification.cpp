#include "fem/pile_wave/pile_wave_verification.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>


namespace pilempm::fem {
namespace {

struct Series {
    const std::vector<double>& t;
    const std::vector<double>& y;
};
Series column(const Table& table, const std::string& name) {
    for (std::size_t c = 0; c < table.columns.size(); ++c)
        if (table.columns[c] == name) return {table.data[0], table.data[c]};
    throw std::out_of_range("table " + table.name + " has no column " + name);
}

// Index of the extreme of `sign * y` within [t0, t1].
std::size_t arg_extreme(const Series& s, double t0, double t1, double sign) {
    std::size_t best = 0;
    double v = -1e300;
    for (std::size_t i = 0; i < s.t.size(); ++i) {
        if (s.t[i] < t0 || s.t[i] > t1) continue;
        if (sign * s.y[i] > v) {
            v = sign * s.y[i];
            best = i;
        }
    }
    return best;
}

double value_at(const Series& s, double t) {
    const auto it = std::lower_bound(s.t.begin(), s.t.end(), t);
    if (it == s.t.begin()) return s.y.front();
    if (it == s.t.end()) return s.y.back();
    const std::size_t i = static_cast<std::size_t>(it - s.t.begin());
    const double w = (t - s.t[i - 1]) / (s.t[i] - s.t[i - 1]);
    return (1 - w) * s.y[i - 1] + w * s.y[i];
}

// First time after t_from that y crosses `level` going in direction `rising`.
double crossing(const Series& s, double level, double t_from, bool rising) {
    for (std::size_t i = 1; i < s.t.size(); ++i) {
        if (s.t[i] < t_from) continue;
        const double a = s.y[i - 1] - level, b = s.y[i] - level;
        if ((rising && a < 0 && b >= 0) || (!rising && a > 0 && b <= 0))
            return s.t[i - 1] + (s.t[i] - s.t[i - 1]) * a / (a - b);
    }
    return s.t.back();
}

double round_trip(const PileWaveResult& r) { return 2.0 * r.summary.pile_length / r.summary.wave_speed; }

}  // namespace

std::vector<VerificationCheck> check_rigid_ram_decay(const PileWaveSetup& s, const PileWaveResult& r) {
    const auto& rc = s.hammer.ram_cushion;
    const double Z = r.summary.head_impedance, m = rc.ram.mass, v0 = rc.impact_velocity;
    const double g = rc.gravity, tau = m / Z;
    if (tau >= round_trip(r))
        throw std::invalid_argument("rigid_ram_decay: m/Z must be shorter than 2L/c");
    const Series f = column(r.table("pile_head"), "force_compression_N");
    const double peak = f.y[arg_extreme(f, 0.0, round_trip(r), 1.0)];
    const double exact_tau = (Z * v0 - m * g) * std::exp(-1.0) + m * g;
    const double exact_2tau = (Z * v0 - m * g) * std::exp(-2.0) + m * g;
    std::vector<VerificationCheck> out;
    out.push_back(make_check("peak_head_force_N", peak, Z * v0, 0.02, true, "F(0) = Z v0"));
    out.push_back(make_check("head_force_at_one_time_constant_N", value_at(f, tau), exact_tau, 0.02,
                             true, "t = m/Z"));
    if (2 * tau < round_trip(r))
        out.push_back(make_check("head_force_at_two_time_constants_N", value_at(f, 2 * tau),
                                 exact_2tau, 0.02, true, "t = 2 m/Z"));
    return out;
}

std::vector<VerificationCheck> check_elastic_ram_pulse(const PileWaveSetup& s, const PileWaveResult& r) {
    const auto& rc = s.hammer.ram_cushion;
    if (!rc.ram.elastic) throw std::invalid_argument("elastic_ram_pulse needs an elastic ram");
    const double c_ram = std::sqrt(rc.ram.youngs_modulus / rc.ram.density);
    const double Zr = rc.ram.mass / (rc.ram.density * rc.ram.length) *
                      std::sqrt(rc.ram.youngs_modulus * rc.ram.density);
    const double Zp = r.summary.head_impedance;
    const double amplitude_ref = Zp * Zr / (Zp + Zr) * rc.impact_velocity;
    const double duration_ref = 2.0 * rc.ram.length / c_ram;
    if (duration_ref >= round_trip(r))
        throw std::invalid_argument("elastic_ram_pulse: the pulse must end before 2L/c");
    const Series f = column(r.table("pile_head"), "force_compression_N");
    // Plateau: mean over the middle half of the expected pulse.
    double sum = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < f.t.size(); ++i)
        if (f.t[i] >= 0.25 * duration_ref && f.t[i] <= 0.75 * duration_ref) sum += f.y[i], ++n;
    const double amplitude = n ? sum / n : 0.0;
    const double t_up = crossing(f, 0.5 * amplitude, 0.0, true);
    const double t_down = crossing(f, 0.5 * amplitude, t_up, false);
    return {make_check("pulse_amplitude_N", amplitude, amplitude_ref, 0.02, true,
                       "Z_p Z_r / (Z_p + Z_r) v0"),
            make_check("pulse_duration_s", t_down - t_up, duration_ref, 0.02, true,
                       "2 L_ram / c_ram, between half-amplitude crossings")};
}

std::vector<VerificationCheck> check_toe_reflection(const PileWaveSetup& s, const PileWaveResult& r) {
    if (s.hammer.kind != HammerKind::PrescribedForce || s.gauge_depths.empty())
        throw std::invalid_argument("toe_reflection needs a prescribed force and a gauge at mid-length");
    const double L = r.summary.pile_length, c = r.summary.wave_speed, dt = r.summary.time_step;
    const double T = s.hammer.force.end_time();
    if (T >= L / c) throw std::invalid_argument("toe_reflection: the pulse must be shorter than L/c");
    if (s.duration < 1.5 * T + 1.25 * round_trip(r))
        throw std::invalid_argument("toe_reflection: the duration must cover 1.5 t_i + 1.25 x 2L/c = " +
                                    std::to_string(1.5 * T + 1.25 * round_trip(r)) + " s");
    std::vector<VerificationCheck> out;
    // Arrival by cross-correlating the outgoing head velocity with the returning one:
    // robust to the small distortion the lumped head node gives the pulse peak.
    const Series v = column(r.table("pile_head"), "velocity_down_m_s");
    const double sign = s.toe.condition == fem::ToeCondition::Fixed ? -1.0 : 1.0;
    const std::size_t n_out = std::min(v.y.size(), static_cast<std::size_t>(1.5 * T / dt) + 1);
    auto correlation = [&](long lag) {
        double sum = 0.0;
        for (std::size_t i = 0; i < n_out && i + lag < v.y.size(); ++i) sum += v.y[i] * v.y[i + lag];
        return sign * sum;
    };
    const long lag_lo = static_cast<long>(0.75 * round_trip(r) / dt);
    const long lag_hi = std::min(static_cast<long>(1.25 * round_trip(r) / dt), static_cast<long>(v.y.size()) - 2);
    long best = lag_lo;
    for (long lag = lag_lo; lag <= lag_hi; ++lag)
        if (correlation(lag) > correlation(best)) best = lag;
    const double c0 = correlation(best - 1), c1 = correlation(best), c2 = correlation(best + 1);
    const double shift = (best + 0.5 * (c0 - c2) / (c0 - 2 * c1 + c2)) * dt;
    out.push_back(make_check("return_time_at_head_s", shift, 2.0 * L / c, dt, false,
                             "2 L / c within one time step (cross-correlation of head velocity)"));

    const Table& gauge = r.tables.at(3);  // tables: pile_head, toe, energy, then the gauges
    const Series g = column(gauge, "force_compression_N");
    const double incident = g.y[arg_extreme(g, 0.0, L / c, 1.0)];
    if (s.toe.condition == fem::ToeCondition::Free) {
        const double tension = -g.y[arg_extreme(g, 0.0, round_trip(r), -1.0)];
        out.push_back(make_check("reflected_tension_N", tension, incident, 0.03, true,
                                 "free toe: compression returns as equal tension"));
    } else if (s.toe.condition == fem::ToeCondition::Fixed) {
        const Series toe = column(r.table("toe"), "force_compression_N");
        const double peak = toe.y[arg_extreme(toe, 0.0, 1.5 * L / c, 1.0)];
        out.push_back(make_check("toe_force_N", peak, 2.0 * incident, 0.03, true,
                                 "fixed toe: the toe force doubles the incident force"));
    }
    return out;
}

std::vector<VerificationCheck> check_energy_conservation(const PileWaveSetup& s, const PileWaveResult& r) {
    // Energy in: the work of a prescribed force, or the ram's impact energy plus the work
    // of gravity on the hammer. Energy accounted: kinetic + strain of the pile, the toe
    // dashpot's loss, and the hammer's kinetic, stored and dissipated energy.
    const Table& e = r.table("energy");
    auto col = [&](const char* name) { return column(e, name).y; };
    const auto t = e.data[0];
    const auto pk = col("pile_kinetic_J"), ps = col("pile_strain_J"), hk = col("hammer_kinetic_J"),
               hs = col("hammer_stored_J"), td = col("toe_dashpot_dissipated_J"),
               wf = col("work_of_prescribed_force_J"), hd = col("hammer_dissipated_J"),
               wg = col("gravity_work_on_hammer_J");
    const bool prescribed = s.hammer.kind == HammerKind::PrescribedForce;
    double scale = 0.0;
    for (std::size_t i = 0; i < t.size(); ++i)
        scale = std::max(scale, prescribed ? wf[i] : r.summary.hammer_energy + wg[i]);
    double worst = 0.0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const double in = prescribed ? wf[i] : r.summary.hammer_energy + wg[i];
        const double accounted = pk[i] + ps[i] + td[i] + hk[i] + hs[i] + hd[i];
        worst = std::max(worst, std::abs(accounted - in) / scale);
    }
    std::vector<VerificationCheck> out{make_check(
        "max_energy_error_relative", worst, 0.0, 0.005, false,
        prescribed ? "|kinetic + strain + losses - work of the load| / work, over the run"
                   : "|pile + hammer energy + losses - (impact energy + gravity work)| / input")};
    if (prescribed && s.toe.condition == fem::ToeCondition::Free) {
        const double trips = (t.back() - s.hammer.force.end_time()) / round_trip(r);
        VerificationCheck cover = make_check("round_trips_after_load", trips, 5.0, 0.0, false,
                                             "at least 5 round trips 2L/c after the load ends");
        cover.at_least = true;
        cover.passed = trips >= 5.0;
        out.push_back(cover);
    }
    return out;
}

std::vector<VerificationCheck> check_half_sine_transfer(const PileWaveSetup& s, const PileWaveResult& r) {
    const auto& f = s.hammer.force;
    if (s.hammer.kind != HammerKind::PrescribedForce || !f.table_time.empty())
        throw std::invalid_argument("half_sine_transfer needs a half-sine hammer");
    const double Z = r.summary.head_impedance;
    const bool absorbing = s.toe.condition == fem::ToeCondition::Dashpot &&
                           std::abs(s.toe.impedance - Z) <= 1e-6 * Z;
    if (!absorbing && s.duration > round_trip(r))
        throw std::invalid_argument("half_sine_transfer needs a matched dashpot toe or a run shorter than 2L/c");
    return {make_check("peak_head_force_N", r.summary.peak_head_force, f.peak, 0.01, true,
                       "f_max of the half-sine pulse"),
            make_check("enthru_J", r.summary.enthru, f.peak * f.peak * f.duration / (2.0 * Z), 0.01, true,
                       "F0^2 t_i / (2 Z): all of the pulse's energy enters the pile")};
}

std::vector<VerificationCheck> check_model_agreement(const PileWaveResult& solid,
                                                     const PileWaveResult& rod) {
    const double L = solid.summary.pile_length, c = solid.summary.wave_speed;
    const Series ts = column(solid.table("toe"), "force_compression_N");
    const Series tr = column(rod.table("toe"), "force_compression_N");
    const double window = 1.5 * L / c;
    const double t_solid = ts.t[arg_extreme(ts, 0.0, window, 1.0)];
    const double t_rod = tr.t[arg_extreme(tr, 0.0, window, 1.0)];
    const double tol = std::max(2.0 * std::max(solid.summary.time_step, rod.summary.time_step), 0.01 * L / c);
    return {make_check("peak_head_force_N", solid.summary.peak_head_force, rod.summary.peak_head_force,
                       0.03, true, "axisymmetric solid (computed) against rod (reference)"),
            make_check("toe_peak_arrival_s", t_solid, t_rod, tol, false,
                       "time of the peak toe force, solid against rod")};
}

ConvergenceStudy convergence_of_peak_toe_stress(const std::vector<double>& sizes,
                                                const std::vector<PileWaveSetup>& setups,
                                                const std::vector<PileWaveResult>& results) {
    ConvergenceStudy st;
    st.element_sizes = sizes;
    for (const auto& r : results) {
        const Series f = column(r.table("toe"), "force_compression_N");
        st.peak_toe_stress.push_back(*std::max_element(f.y.begin(), f.y.end()) / r.summary.toe_area);
    }
    st.reference = 2.0 * setups.back().hammer.force.peak / results.back().summary.toe_area;
    const std::size_t n = st.peak_toe_stress.size();
    if (n >= 2) {
        const double e1 = std::abs(st.peak_toe_stress[n - 2] - st.reference);
        const double e2 = std::abs(st.peak_toe_stress[n - 1] - st.reference);
        st.observed_order = std::log(e1 / e2) / std::log(sizes[n - 2] / sizes[n - 1]);
    }
    return st;
}

std::vector<VerificationCheck> check_mesh_convergence(const ConvergenceStudy& st) {
    std::vector<VerificationCheck> out;
    const std::size_t n = st.peak_toe_stress.size();
    for (std::size_t k = 0; k < n; ++k) {
        char note[96];
        std::snprintf(note, sizeof note, "element size %.4g m", st.element_sizes[k]);
        auto c = make_check("peak_toe_stress_Pa_h" + std::to_string(k), st.peak_toe_stress[k],
                            st.reference, k + 1 == n ? 0.01 : 0.10, true, note);
        out.push_back(c);
    }
    const double e0 = std::abs(st.peak_toe_stress.front() - st.reference);
    const double e1 = std::abs(st.peak_toe_stress.back() - st.reference);
    auto dec = make_check("error_reduction_coarse_to_fine", e1 / std::max(e0, 1e-300), 0.0, 1.0, false,
                          "error of the finest mesh over that of the coarsest, below 1");
    dec.passed = e1 < e0;
    out.push_back(dec);
    auto order = make_check("observed_order", st.observed_order, 1.0, 0.0, false,
                            "order of convergence from the two finest meshes, at least 1");
    order.at_least = true;
    order.passed = st.observed_order >= 1.0;
    out.push_back(order);
    return out;
}

}  // namespace pilempm::fem
