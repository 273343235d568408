#include "mpm/verification/pore_water_checks.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "mpm/verification/dynamic_poroelastic_column.hpp"

namespace pilempm::mpm {

double terzaghi_excess_pressure(double z, double T) {
    if (T <= 0.0) return z > 0.0 ? 1.0 : 0.0;
    double u = 0.0;
    for (int k = 0; k < 100000; ++k) {
        const double M = std::numbers::pi * (2 * k + 1) / 2.0;
        const double decay = std::exp(-M * M * T);
        u += 2.0 / M * std::sin(M * z) * decay;
        if (2.0 / M * decay < 1e-14) break;
    }
    return u;
}

double terzaghi_degree_of_consolidation(double T) {
    if (T <= 0.0) return 0.0;
    double s = 0.0;
    for (int k = 0; k < 100000; ++k) {
        const double M = std::numbers::pi * (2 * k + 1) / 2.0;
        const double term = 2.0 / (M * M) * std::exp(-M * M * T);
        s += term;
        if (term < 1e-15) break;
    }
    return 1.0 - s;
}

namespace {

// The first material's skeleton and pore water: P-wave modulus M, bulk modulus K, porosity,
// Darcy resistance mu / kappa, and the water.
template <int D>
struct SaturatedFirstMaterial {
    double M, K, n, R, Kw, rho_w;
    explicit SaturatedFirstMaterial(const MpmModel<D>& m, const char* check) {
        if (m.drainage.empty() || !m.drainage.front().saturated())
            throw std::invalid_argument(std::string(check) + " needs a saturated first material");
        M = m.materials.front()->p_wave_modulus();
        K = M - 4.0 / 3.0 * m.materials.front()->shear_modulus();
        n = m.drainage.front().porosity;
        R = m.drainage.front().darcy_resistance;
        Kw = m.water.bulk_modulus;
        rho_w = m.water.density;
    }
};

double interpolate(const std::vector<double>& t, const std::vector<double>& v, double at) {
    const auto it = std::lower_bound(t.begin(), t.end(), at);
    if (it == t.begin()) return v.front();
    if (it == t.end()) return v.back();
    const std::size_t i = static_cast<std::size_t>(it - t.begin());
    const double s = (at - t[i - 1]) / (t[i] - t[i - 1]);
    return v[i - 1] + s * (v[i] - v[i - 1]);
}

// The initial elevation of the point nearest each probe (as the run builder picks them).
template <int D>
std::vector<double> probe_elevations(const MpmCheckContext& c, const std::vector<double>& x0) {
    std::vector<double> z;
    for (const auto& probe : c.probes) {
        std::size_t best = 0;
        double d2best = 1e300;
        for (std::size_t i = 0; i < x0.size() / D; ++i) {
            double d2 = 0.0;
            for (int d = 0; d < D; ++d) d2 += (x0[D * i + d] - probe[d]) * (x0[D * i + d] - probe[d]);
            if (d2 < d2best) d2best = d2, best = i;
        }
        z.push_back(x0[D * best + D - 1]);
    }
    return z;
}

}  // namespace

// A layer of height H (verification.height) drained at one face (verification.surface: its
// top, or its base under an impermeable load such as a pile's toe) and impermeable at the
// other, loaded at t = 0 by verification.load: the excess pressure starts at
// u0 = B q with the one-dimensional B = (K_w / n) / (M + K_w / n) and dissipates with
// c_v = kappa / mu / (1 / M + n / K_w). At T = 0.05, 0.2, 0.5 and 1: the largest error of the
// probes' excess pressure over u0, and the degree of consolidation from the probes' mean
// (probes at equal spacing through the layer), each within verification.pore_tolerance (0.03).
template <int D>
std::vector<VerificationCheck> terzaghi_consolidation(const MpmCheckContext& c, const MpmModel<D>& m,
                                                      const std::vector<double>& x0, const Table& history) {
    const char* check = "terzaghi_consolidation";
    const double q = parameter(c, "load", check), H = parameter(c, "height", check);
    const double surface = parameter(c, "surface", check);
    const double tol = c.parameters.count("pore_tolerance") ? c.parameters.at("pore_tolerance") : 0.03;
    const SaturatedFirstMaterial<D> s(m, check);
    const double Mu = s.Kw / s.n;
    const double u0 = q * Mu / (s.M + Mu);
    const double cv = 1.0 / (s.R * (1.0 / s.M + s.n / s.Kw));
    const auto z = probe_elevations<D>(c, x0);
    if (z.size() < 4) throw std::invalid_argument("terzaghi_consolidation needs output.probes through the layer (4 or more)");
    const auto& t = column(history, "time_s");
    std::vector<VerificationCheck> out;
    for (const double T : {0.05, 0.2, 0.5, 1.0}) {
        const double at = T * H * H / cv;
        if (at > t.back() * (1.0 + 1e-9))
            throw std::invalid_argument("terzaghi_consolidation: the run ends before T = " + std::to_string(T) + " (t = " +
                                        std::to_string(at) + " s)");
        double worst = 0.0, mean = 0.0;
        for (std::size_t k = 0; k < z.size(); ++k) {
            const double p = interpolate(t, column(history, "probe" + std::to_string(k) + "_excess_pore_pressure_Pa"), at);
            const double exact = u0 * terzaghi_excess_pressure(std::abs(surface - z[k]) / H, T);
            worst = std::max(worst, std::abs(p - exact) / u0);
            mean += p / u0 / static_cast<double>(z.size());
        }
        char tag[32];
        std::snprintf(tag, sizeof tag, "T%.2f", T);
        out.push_back(make_check(std::string("isochrone_max_error_over_u0_") + tag, worst, 0.0, tol, false,
                                 "largest |p - p_Terzaghi| / u0 over the probes at T_v = c_v t / H^2"));
        out.push_back(make_check(std::string("degree_of_consolidation_") + tag, 1.0 - mean,
                                 terzaghi_degree_of_consolidation(T), tol, false,
                                 "1 - mean probe excess pressure / u0 against Terzaghi's U(T_v)"));
    }
    return out;
}

// The travel time of a pressure pulse between two probes verification.depth apart, from
// each probe's half-peak arrival of the skeleton's vertical velocity, against depth / c:
// undrained (low permeability) c_u = sqrt((M + K_w/n) / rho_sat), within 2 %; and how the
// pulse's total stress splits at the deeper probe: p / (p - sigma'_v) against the undrained
// (K_w/n) / (M + K_w/n), within 2 %. Or (fast) the fast wave of the drag-free limit (high
// permeability): the largest root of the v-w wave operator without drag, within 2 %.
template <int D>
std::vector<VerificationCheck> saturated_wave_arrival(const MpmCheckContext& c, const MpmModel<D>& m,
                                                      const Table& history, bool fast) {
    const char* check = fast ? "fast_wave_speed" : "undrained_wave_speed";
    const double depth = parameter(c, "depth", check);
    const SaturatedFirstMaterial<D> s(m, check);
    const SaturatedWaveSpeeds speeds = saturated_wave_speeds(s.M, s.n, c.density - s.n * s.rho_w, m.water);
    const double speed = fast ? speeds.fastest : speeds.undrained;
    const auto& t = column(history, "time_s");
    auto half_peak_arrival = [&](const std::string& name) {
        const auto& v = column(history, name);
        double peak = 0.0, dt = 0.0;
        for (double x : v) peak = std::max(peak, std::abs(x));
        return arrival(t, v, peak, dt);  // where |v| first reaches half the peak
    };
    const double first = half_peak_arrival("probe0_velocity_vertical_m_s");
    const double second = half_peak_arrival("probe1_velocity_vertical_m_s");
    std::vector<VerificationCheck> out;
    auto k = make_check(std::string(fast ? "fast" : "undrained") + "_wave_travel_time_between_probes_s", second - first,
                        depth / speed, 0.02, true,
                        fast ? "half-peak arrivals at two probes against their distance / c_fast (drag-free v-w)"
                             : "half-peak arrivals at two probes against their distance / c_u, c_u = sqrt((M + K_w/n) / rho_sat)");
    k.note += " (c = " + std::to_string(speed) + " m/s)";
    out.push_back(k);
    if (!fast) {
        const auto& p = column(history, "probe1_excess_pore_pressure_Pa");
        const auto& sv = column(history, "probe1_stress_vertical_Pa");
        std::size_t at = 0;
        for (std::size_t i = 0; i < p.size(); ++i)
            if (std::abs(p[i]) > std::abs(p[at])) at = i;
        const double Mu = s.Kw / s.n;
        out.push_back(make_check("undrained_pore_pressure_share_of_total_stress", p[at] / (p[at] - sv[at]),
                                 Mu / (s.M + Mu), 0.02, true,
                                 "p / (p - sigma'_v) at the deeper probe's peak against (K_w/n) / (M + K_w/n)"));
    }
    return out;
}

// The column's reference: the first material as a half-space below verification.surface,
// loaded there by verification.load (Pa) as p sin^2(pi t / T), T = verification.
// pulse_duration (the case's pressure must be that pulse). The probes' depths are their
// points' initial ones; the reference is sampled at the history's times.
template <int D>
Table poroelastic_wave_histories(const MpmCheckContext& c, const MpmModel<D>& m, const std::vector<double>& x0,
                                 const Table& history) {
    const char* check = "poroelastic_wave_history";
    const SaturatedFirstMaterial<D> s(m, check);
    PoroelasticColumn half_space;
    half_space.p_wave_modulus = s.M;
    half_space.porosity = s.n;
    half_space.solid_density_partial = c.density - s.n * s.rho_w;
    half_space.water_density = s.rho_w;
    half_space.water_bulk_modulus = s.Kw;
    half_space.darcy_resistance = m.drainage.front().drainage == Drainage::Coupled ? s.R : 1e30;
    const ColumnLoad load{parameter(c, "load", check), parameter(c, "pulse_duration", check), ColumnPulse::SineSquared};
    const double surface = parameter(c, "surface", check);
    const auto z = probe_elevations<D>(c, x0);
    if (z.empty()) throw std::invalid_argument("poroelastic_wave_history needs output.probes in the column");
    const auto& t = column(history, "time_s");
    std::vector<std::string> names = {"time_s"};
    for (std::size_t k = 0; k < z.size(); ++k)
        for (const char* field : {"excess_pore_pressure_Pa", "stress_vertical_Pa"})
            for (const char* which : {"computed", "reference"})
                names.push_back("probe" + std::to_string(k) + "_" + field + "_" + which);
    Table out("poroelastic_wave_histories", names);
    out.data[0] = t;
    // The reference at even times, 200 per pulse or more, interpolated to the run's times
    // (linear interpolation of the sin^2 pulse: an error below 1e-4 of the load).
    const std::size_t steps = std::max<std::size_t>(2000, static_cast<std::size_t>(200.0 * t.back() / load.duration));
    std::vector<double> even(steps + 1);
    for (std::size_t j = 0; j <= steps; ++j) even[j] = t.back() * static_cast<double>(j) / static_cast<double>(steps);
    for (std::size_t k = 0; k < z.size(); ++k) {
        const auto at_even = poroelastic_column_history(half_space, load, surface - z[k], even);
        std::vector<double> p_even, s_even;
        for (const auto& r : at_even) p_even.push_back(r.excess_pore_pressure), s_even.push_back(r.effective_stress);
        std::vector<ColumnResponse> ref;
        for (double at : t) ref.push_back({interpolate(even, p_even, at), interpolate(even, s_even, at)});
        const std::string probe = "probe" + std::to_string(k) + "_";
        auto& p = out.data[1 + 4 * k];
        auto& p_ref = out.data[2 + 4 * k];
        auto& sv = out.data[3 + 4 * k];
        auto& sv_ref = out.data[4 + 4 * k];
        p = column(history, probe + "excess_pore_pressure_Pa");
        sv = column(history, probe + "stress_vertical_Pa");
        for (const auto& r : ref) {
            p_ref.push_back(r.excess_pore_pressure);
            sv_ref.push_back(r.effective_stress);
        }
    }
    return out;
}

// The largest difference between the computed and the reference history at each probe, of
// the excess pore pressure and of the vertical effective stress, over the load, within
// verification.history_tolerance (default 0.05).
template <int D>
std::vector<VerificationCheck> poroelastic_wave_history(const MpmCheckContext& c, const MpmModel<D>& m,
                                                        const std::vector<double>& x0, const Table& history) {
    const double q = parameter(c, "load", "poroelastic_wave_history");
    const double tol = c.parameters.count("history_tolerance") ? c.parameters.at("history_tolerance") : 0.05;
    const Table h = poroelastic_wave_histories<D>(c, m, x0, history);
    std::vector<VerificationCheck> out;
    for (std::size_t k = 0; 4 * k + 4 < h.columns.size(); ++k) {
        const char* fields[2] = {"pore_pressure", "effective_stress"};
        for (int f = 0; f < 2; ++f) {
            const auto& a = h.data[1 + 4 * k + 2 * f];
            const auto& b = h.data[2 + 4 * k + 2 * f];
            double worst = 0.0, peak = 0.0;
            for (std::size_t j = 0; j < a.size(); ++j) {
                worst = std::max(worst, std::abs(a[j] - b[j]));
                peak = std::max(peak, std::abs(b[j]));
            }
            auto check = make_check("probe" + std::to_string(k) + "_" + fields[f] + "_history_max_error_over_load",
                                    worst / q, 0.0, tol, false,
                                    "largest |computed - reference| over the run / load, against the dynamic "
                                    "poro-elastic half-space (Laplace domain, inverted)");
            check.note += " (reference peak " + std::to_string(peak / q) + " of the load)";
            out.push_back(check);
        }
    }
    return out;
}

// Saturated ground in equilibrium under its water column: the largest excess pore pressure
// over the hydrostatic pressure at the deepest point, and the largest displacement over the
// cell size, both below verification.pore_tolerance (default 1e-3).
template <int D>
std::vector<VerificationCheck> hydrostatic_equilibrium(const MpmCheckContext& c, const MpmModel<D>& m,
                                                       const std::vector<double>& x0) {
    const double tol = c.parameters.count("pore_tolerance") ? c.parameters.at("pore_tolerance") : 1e-3;
    const auto& p = m.particles;
    double deepest = 0.0, excess = 0.0, drift = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        deepest = std::max(deepest, m.water.hydrostatic_pressure(x0[D * i + D - 1]));
        excess = std::max(excess, std::abs(p.pore_pressure[i]));
        for (int d = 0; d < D; ++d) drift = std::max(drift, std::abs(p.x[D * i + d] - x0[D * i + d]));
    }
    if (!(deepest > 0.0)) throw std::invalid_argument("hydrostatic_equilibrium needs ground under a water surface (water.level)");
    double h = m.grid.spacing[0];
    for (int d = 1; d < D; ++d) h = std::min(h, m.grid.spacing[d]);
    return {make_check("excess_pore_pressure_max_over_hydrostatic", excess / deepest, 0.0, tol, false,
                       "largest |p_excess| over the hydrostatic pressure at the deepest point"),
            make_check("point_drift_max_over_cell", drift / h, 0.0, tol, false,
                       "largest |x - x0| over the cell size: ground in equilibrium under water stays put")};
}

// Undrained loading of an elastic skeleton: the change of pore pressure over the change of
// mean total stress (volume averages over the points; the run starts unstressed), against
// Gassmann's B = 1 / (1 + n K / K_w), within 1 %.
template <int D>
VerificationCheck skempton_b_check(const MpmCheckContext& c, const MpmModel<D>& m) {
    (void)c;
    const SaturatedFirstMaterial<D> s(m, "skempton_b");
    const auto& p = m.particles;
    double dp = 0.0, dmean = 0.0, volume = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double* sg = &p.stress[6 * i];
        const double pe = p.pore_pressure[i];
        const double mean_total = -(sg[0] + sg[1] + sg[2]) / 3.0 + pe;  // compression positive
        dp += pe * p.volume[i];
        dmean += mean_total * p.volume[i];
        volume += p.volume[i];
    }
    if (!(std::abs(dmean) > 0.0)) throw std::invalid_argument("skempton_b: the run changed no stress");
    auto k = make_check("skempton_b", dp / dmean, skempton_b(s.K, s.n, s.Kw), 0.01, true,
                        "dp / d(mean total stress) against Gassmann's B = 1 / (1 + n K / K_w)");
    k.note += " (K = " + std::to_string(s.K) + " Pa, n = " + std::to_string(s.n) + ")";
    return k;
}

#define PILEMPM_PORE_CHECKS(D)                                                                                  \
    template std::vector<VerificationCheck> terzaghi_consolidation<D>(const MpmCheckContext&, const MpmModel<D>&, \
                                                                      const std::vector<double>&, const Table&);   \
    template std::vector<VerificationCheck> saturated_wave_arrival<D>(const MpmCheckContext&, const MpmModel<D>&,    \
                                                                      const Table&, bool);                         \
    template std::vector<VerificationCheck> hydrostatic_equilibrium<D>(const MpmCheckContext&, const MpmModel<D>&, \
                                                                       const std::vector<double>&);                \
    template VerificationCheck skempton_b_check<D>(const MpmCheckContext&, const MpmModel<D>&);                   \
    template Table poroelastic_wave_histories<D>(const MpmCheckContext&, const MpmModel<D>&,                       \
                                                 const std::vector<double>&, const Table&);                        \
    template std::vector<VerificationCheck> poroelastic_wave_history<D>(const MpmCheckContext&, const MpmModel<D>&, \
                                                                        const std::vector<double>&, const Table&);
PILEMPM_PORE_CHECKS(2)
PILEMPM_PORE_CHECKS(3)
#undef PILEMPM_PORE_CHECKS

}  // namespace pilempm::mpm
