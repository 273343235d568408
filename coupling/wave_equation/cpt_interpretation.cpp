#include "coupling/wave_equation/cpt_interpretation.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <stdexcept>

namespace pilempm::coupling {

namespace {

constexpr double kKpa = 1e3;

void check_sounding(const CptSounding& c) {
    const std::size_t n = c.depth.size();
    if (n < 2) throw std::invalid_argument("CPT: at least two depths are needed");
    if (c.qc.size() != n || c.fs.size() != n || c.u2.size() != n)
        throw std::invalid_argument("CPT: q_c, f_s and u_2 need one value per depth");
    for (std::size_t i = 0; i < n; ++i) {
        if (!(c.depth[i] > (i == 0 ? 0.0 : c.depth[i - 1])))
            throw std::invalid_argument("CPT: depths must be positive and increase (row " +
                                        std::to_string(i + 1) + ")");
        if (!std::isfinite(c.qc[i]) || !std::isfinite(c.fs[i]) || !std::isfinite(c.u2[i]))
            throw std::invalid_argument("CPT: a missing value at " + std::to_string(c.depth[i]) + " m");
    }
}

// Runs of one soil type thinner than `min_thickness` take their neighbours' type, the
// thinnest first, so a single clay-like reading in sand (or a sand streak in clay) does
// not become a layer of its own. Returns how many points changed.
int smooth_thin_runs(std::vector<SoilType>& type, const std::vector<double>& thickness,
                     double min_thickness) {
    int changed = 0;
    for (;;) {
        struct Run {
            std::size_t begin, end;
            double thickness;
        };
        std::vector<Run> runs;
        for (std::size_t i = 0; i < type.size(); ++i) {
            if (runs.empty() || type[i] != type[runs.back().begin]) runs.push_back({i, i, 0.0});
            runs.back().end = i + 1;
            runs.back().thickness += thickness[i];
        }
        if (runs.size() < 2) return changed;
        std::size_t thinnest = 0;
        for (std::size_t r = 1; r < runs.size(); ++r)
            if (runs[r].thickness < runs[thinnest].thickness) thinnest = r;
        if (runs[thinnest].thickness >= min_thickness) return changed;
        const Run& r = runs[thinnest];
        const SoilType other = type[r.begin] == SoilType::Sand ? SoilType::Clay : SoilType::Sand;
        for (std::size_t i = r.begin; i < r.end; ++i) type[i] = other;
        changed += static_cast<int>(r.end - r.begin);
    }
}

double baldi_relative_density(double qc, double sigma_v0_eff) {
    // Inverse of Baldi et al. (1986), NC sand, kPa: q_c = 157 sigma'^0.55 exp(2.41 D_R).
    const double s = std::max(sigma_v0_eff, 1.0 * kKpa) / kKpa;
    const double dr = std::log(std::max(qc, 1.0) / kKpa / (157.0 * std::pow(s, 0.55))) / 2.41;
    return std::clamp(dr, 0.0, 1.45);
}

double kulhawy_mayne_friction_angle(double qt, double sigma_v0_eff, double pa) {
    const double s = std::max(sigma_v0_eff, 1.0 * kKpa) / pa;
    const double phi = 17.6 + 11.0 * std::log10(std::max(qt, pa) / pa / std::sqrt(s));
    return std::clamp(phi, 20.0, 50.0);
}

std::string layer_name(const CptPoint& p) {
    std::ostringstream s;
    s.precision(3);
    s << (p.type == SoilType::Sand ? "sand" : "clay") << " (CPT, I_c " << p.ic << ")";
    return s.str();
}

}  // namespace

BehaviourIndex robertson_behaviour_index(double qt, double fs, double sigma_v0, double sigma_v0_eff,
                                         double pa) {
    const double net = std::max(qt - sigma_v0, 1e-3 * pa);
    const double s = std::max(sigma_v0_eff, 1e-3 * pa);
    // F_r and Q_tn are clipped to the chart (F_r >= 0.1 %, Q_tn >= 1) so that log10 stays finite.
    const double fr = std::max(100.0 * fs / net, 0.1);
    double n = 1.0, ic = 0.0, qtn = 0.0;
    for (int it = 0; it < 200; ++it) {
        qtn = std::max(net / pa * std::pow(pa / s, n), 1.0);
        ic = std::hypot(3.47 - std::log10(qtn), std::log10(fr) + 1.22);
        const double next = std::clamp(0.381 * ic + 0.05 * s / pa - 0.15, 0.0, 1.0);
        if (std::abs(next - n) < 1e-9) break;
        n = 0.5 * (n + next);  // damped: the plain iteration can oscillate near n = 1
    }
    return {ic, n, qtn, fr};
}

int robertson_zone(double ic) {
    if (ic < 1.31) return 7;
    if (ic < 2.05) return 6;
    if (ic < 2.60) return 5;
    if (ic < 2.95) return 4;
    if (ic < 3.60) return 3;
    return 2;
}

double robertson_cabal_unit_weight(double qt, double fs, double gamma_w, double pa) {
    const double rf = std::max(100.0 * fs / std::max(qt, 1e-3 * pa), 0.1);
    return gamma_w * (0.27 * std::log10(rf) + 0.36 * std::log10(std::max(qt, 1e-3 * pa) / pa) + 1.236);
}

CptInterpretation interpret_cpt(const CptSounding& cpt, const CptInterpretationOptions& o,
                                double water_depth) {
    check_sounding(cpt);
    if (!(o.net_area_ratio > 0.0 && o.net_area_ratio <= 1.0))
        throw std::invalid_argument("CPT: the net area ratio must lie in (0, 1]");
    const std::size_t n = cpt.depth.size();
    CptInterpretation out;
    out.points.resize(n);
    double sigma = 0.0, z_prev = 0.0, gamma_prev = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        CptPoint& p = out.points[i];
        p.depth = cpt.depth[i];
        p.qc = cpt.qc[i];
        p.fs = std::max(cpt.fs[i], 0.0);
        p.u2 = cpt.u2[i];
        p.qt = std::max(p.qc + (1.0 - o.net_area_ratio) * std::max(p.u2, o.u2_floor), 0.0);
        p.unit_weight = std::clamp(robertson_cabal_unit_weight(p.qt, p.fs, o.water_unit_weight,
                                                               o.atmospheric_pressure),
                                   o.unit_weight_min, o.unit_weight_max);
        // Stresses relative to the mudline, as offshore q_c and u_2 are zeroed there; the
        // first reading's unit weight stands for the soil above it.
        const double g0 = i == 0 ? p.unit_weight : gamma_prev;
        sigma += 0.5 * (g0 + p.unit_weight) * (p.depth - z_prev);
        p.sigma_v0 = sigma;
        p.u0 = o.water_unit_weight * p.depth;
        p.sigma_v0_eff = std::max(sigma - p.u0, 0.0);
        p.friction_ratio = 100.0 * p.fs / std::max(p.qt, 1.0);
        const BehaviourIndex b =
            robertson_behaviour_index(p.qt, p.fs, p.sigma_v0, p.sigma_v0_eff, o.atmospheric_pressure);
        p.ic = b.ic;
        p.stress_exponent = b.n;
        p.qtn = b.qtn;
        p.fr = b.fr;
        p.zone = robertson_zone(b.ic);
        p.clay_like = b.ic > o.sand_clay_boundary;
        z_prev = p.depth;
        gamma_prev = p.unit_weight;
    }

    // Each reading stands for the interval between the midpoints to its neighbours.
    std::vector<double> top(n), bottom(n), thickness(n);
    std::vector<SoilType> type(n);
    for (std::size_t i = 0; i < n; ++i) {
        top[i] = i == 0 ? 0.0 : 0.5 * (cpt.depth[i - 1] + cpt.depth[i]);
        bottom[i] = i + 1 == n ? cpt.depth[i] + 0.5 * (cpt.depth[i] - cpt.depth[i - 1])
                               : 0.5 * (cpt.depth[i] + cpt.depth[i + 1]);
        thickness[i] = bottom[i] - top[i];
        type[i] = out.points[i].clay_like ? SoilType::Clay : SoilType::Sand;
    }
    out.smoothed_points = smooth_thin_runs(type, thickness, o.min_layer_thickness);

    SoilProfile& s = out.profile;
    s.water_depth = water_depth;
    s.clay_cone_factor = o.cone_factor;
    s.cpt.depth = cpt.depth;
    for (std::size_t i = 0; i < n; ++i) {
        CptPoint& p = out.points[i];
        p.type = type[i];
        p.su = std::max(p.qt - p.sigma_v0, 0.0) / o.cone_factor;
        p.relative_density = baldi_relative_density(p.qc, p.sigma_v0_eff);
        p.friction_angle = kulhawy_mayne_friction_angle(p.qt, p.sigma_v0_eff, o.atmospheric_pressure);
        SoilLayer l;
        l.top = top[i];
        l.bottom = bottom[i];
        l.type = p.type;
        l.submerged_unit_weight = std::max(p.unit_weight - o.water_unit_weight, 1.0);
        l.relative_density = p.relative_density;
        l.friction_angle = p.friction_angle;
        l.interface_friction_angle = o.interface_friction_angle;
        l.undrained_shear_strength = std::max(p.su, 1.0);
        l.sensitivity = o.clay_sensitivity;
        l.name = layer_name(p);
        s.layers.push_back(l);
        s.cpt.qt.push_back(p.qt);
        s.cpt.fs.push_back(p.fs);
    }
    return out;
}

Table cpt_profile_table(const CptInterpretation& c, const std::string& name) {
    Table t(name, {"depth_m", "qc_Pa", "qt_Pa", "fs_Pa", "u2_Pa", "unit_weight_N_per_m3", "sigma_v0_Pa",
                   "u0_Pa", "sigma_v0_eff_Pa", "friction_ratio_percent", "Qtn", "Fr_percent", "n", "Ic",
                   "sbt_zone", "clay_like", "soil_type_clay", "su_Pa", "relative_density",
                   "friction_angle_deg"});
    for (const auto& p : c.points)
        t.add_row({p.depth, p.qc, p.qt, p.fs, p.u2, p.unit_weight, p.sigma_v0, p.u0, p.sigma_v0_eff,
                   p.friction_ratio, p.qtn, p.fr, p.stress_exponent, p.ic, static_cast<double>(p.zone),
                   p.clay_like ? 1.0 : 0.0, p.type == SoilType::Clay ? 1.0 : 0.0, p.su, p.relative_density,
                   p.friction_angle});
    return t;
}

std::vector<std::string> cpt_correlations(const CptInterpretationOptions& o) {
    std::ostringstream a, t, c, s;
    a << "q_t = q_c + (1 - a) u_2, a = " << o.net_area_ratio << ", u_2 >= " << o.u2_floor * 1e-6
      << " MPa (Lunne et al. 1997)";
    t << "clay-like where I_c > " << o.sand_clay_boundary << "; sand or clay runs thinner than "
      << o.min_layer_thickness << " m take their neighbours' type";
    c << "s_u = (q_t - sigma_v0) / N_kt, N_kt = " << o.cone_factor << "; clay sensitivity "
      << o.clay_sensitivity;
    s << "sand interface friction angle delta = " << o.interface_friction_angle << " deg";
    return {a.str(),
            "unit weight: Robertson & Cabal (2010), gamma/gamma_w = 0.27 log10 R_f + 0.36 log10(q_t/p_a) + 1.236, "
            "clipped to [" + std::to_string(static_cast<int>(o.unit_weight_min * 1e-3)) + ", " +
                std::to_string(o.unit_weight_max * 1e-3).substr(0, 4) + "] kN/m^3",
            "stresses from the mudline: sigma_v0 = integral of gamma, u_0 = gamma_w z (q_c, u_2 zeroed at the seabed)",
            "soil behaviour type index I_c (Robertson 2009): Q_tn = (q_t - sigma_v0)/p_a (p_a/sigma'_v0)^n, "
            "F_r = f_s/(q_t - sigma_v0), I_c = sqrt((3.47 - log Q_tn)^2 + (log F_r + 1.22)^2), "
            "n = 0.381 I_c + 0.05 sigma'_v0/p_a - 0.15 <= 1",
            t.str(), c.str(),
            "relative density: Baldi et al. (1986), NC sand, D_R = ln(q_c / (157 sigma'_v0^0.55)) / 2.41 (kPa)",
            "friction angle: Kulhawy & Mayne (1990), phi' = 17.6 + 11 log10((q_t/p_a) / (sigma'_v0/p_a)^0.5)",
            s.str()};
}

}  // namespace pilempm::coupling
