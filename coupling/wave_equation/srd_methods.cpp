#include "coupling/wave_equation/srd_methods.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace pilempm::coupling {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kMinStress = 1e3;  // Pa: spec section 0 guard, sigma'_v0 >= 1 kPa

double guarded(double sigma_v) {
    return std::max(sigma_v, kMinStress);
}
double tan_deg(double deg) {
    return std::tan(deg * kPi / 180.0);
}

// Alm & Hamre shape factor k = sqrt(q_t / sigma'_v0) / 80 in 1/m (spec 1.1).
double fatigue_rate(double qt, double sigma_v) {
    return std::sqrt(std::max(qt, 0.0) / guarded(sigma_v)) / 80.0;
}

// f = f_res + (f_i - f_res) exp(k (z - p)); a point at or below the tip keeps f_i.
double degrade(double f_initial, double f_residual, double k, double z, double p) {
    return f_residual + (f_initial - f_residual) * std::exp(k * std::min(z - p, 0.0));
}

// API RP2A (1993) siliceous sand rows (spec 3.1), in Pa.
struct ApiSandRow {
    double delta;
    ApiSandLimits limits;
};
constexpr std::array<ApiSandRow, 5> kApiSandTable{{
    {15.0, {47.8e3, 8.0, 1.9e6}},
    {20.0, {67.0e3, 12.0, 2.9e6}},
    {25.0, {81.3e3, 20.0, 4.8e6}},
    {30.0, {95.7e3, 40.0, 9.6e6}},
    {35.0, {114.8e3, 50.0, 12.0e6}},
}};

double lerp(double a, double b, double w) {
    return a + w * (b - a);
}

// ---- soil values at a shaft sample ------------------------------------------------

struct SoilPoint {
    const SoilLayer* layer;
    double sigma_v;  // Pa, effective
    double qt, fs;   // Pa, CPT or correlation
    double su;       // Pa (meaningful in clay)
};

SoilPoint soil_point(const SoilProfile& soil, double z) {
    return {&soil.layer_at(z), soil.vertical_effective_stress(z), soil.cone_resistance(z),
            soil.sleeve_friction(z), soil.undrained_shear_strength(z)};
}

// Values just above the boundary at the bottom of layer i: cut the profile below layer i,
// whose last layer then extends down. sigma'_v0 and the CPT record are continuous there,
// so the cut copy needs no record and the measured values come from the full profile.
SoilPoint soil_point_above(const SoilProfile& soil, std::size_t i, double z) {
    SoilProfile upper;
    upper.layers.assign(soil.layers.begin(),
                        soil.layers.begin() + static_cast<std::ptrdiff_t>(i) + 1);
    upper.water_depth = soil.water_depth;
    upper.clay_cone_factor = soil.clay_cone_factor;
    SoilPoint s = soil_point(upper, z);
    s.layer = &soil.layers[i];
    if (soil.has_cpt_at(z)) {
        s.qt = soil.cone_resistance(z);
        s.fs = soil.sleeve_friction(z);
    }
    return s;
}

// ---- pile and sampled shaft ---------------------------------------------------------

struct Pipe {
    double d_outer, d_inner;
    double area_gross() const { return kPi * d_outer * d_outer / 4.0; }
    double area_annulus() const { return area_gross() - kPi * d_inner * d_inner / 4.0; }
};

struct Faces {
    double outside, inside;  // N per m of pile
};

struct ShaftSamples {
    std::vector<double> depth, outside, inside;
    void add(double z, Faces f) {
        depth.push_back(z);
        outside.push_back(f.outside);
        inside.push_back(f.inside);
    }
};

double integrate(const std::vector<double>& depth, const std::vector<double>& per_metre,
                 double penetration) {
    ResistanceDistribution r;  // the same trapezoid rule as the consumers use
    r.penetration = penetration;
    r.depth = depth;
    r.shaft = per_metre;
    return r.shaft_total();
}

// Samples [a, b) at most `spacing` apart, each from the layer holding it.
template <class ShaftFn>
void sample_segment(const SoilProfile& soil, double a, double b, double spacing, ShaftFn& shaft,
                    ShaftSamples& out) {
    if (!(b > a)) return;
    const int n = std::max(1, static_cast<int>(std::ceil((b - a) / spacing)));
    for (int j = 0; j < n; ++j) {
        const double z = a + (b - a) * j / n;
        out.add(z, shaft(soil_point(soil, z), z));
    }
}

// 0 .. p, with an upper-layer and a lower-layer sample at each boundary inside (0, p) so
// the piecewise-linear integration keeps the jump. A tip exactly on a boundary takes the
// upper layer's value: the shaft lies above it.
template <class ShaftFn>
ShaftSamples sample_shaft(const SoilProfile& soil, double p, double spacing, ShaftFn shaft) {
    ShaftSamples out;
    double a = 0.0;
    for (std::size_t i = 0; i + 1 < soil.layers.size(); ++i) {
        const double b = soil.layers[i].bottom;
        if (b >= p) {
            sample_segment(soil, a, p, spacing, shaft, out);
            out.add(p, shaft(b == p ? soil_point_above(soil, i, p) : soil_point(soil, p), p));
            return out;
        }
        sample_segment(soil, a, b, spacing, shaft, out);
        out.add(b, shaft(soil_point_above(soil, i, b), b));
        a = b;
    }
    sample_segment(soil, a, p, spacing, shaft, out);
    out.add(p, shaft(soil_point(soil, p), p));
    return out;
}

// ---- the methods ---------------------------------------------------------------------

struct SrdModes {
    ShaftSamples shaft;
    double toe_unit = 0.0;  // Pa at the tip
};

Faces alm_hamre_faces(const SoilPoint& s, const SrdCoefficients& k, const Pipe& pipe, double z,
                      double p) {
    if (s.layer->type == SoilType::Sand) {
        const double f = alm_hamre_sand_shaft_friction(
            s.qt, s.sigma_v, s.layer->interface_friction_angle, z, p, k.atmospheric_pressure);
        return {k.alm_hamre_sand_outside * f * kPi * pipe.d_outer,
                k.alm_hamre_sand_inside * f * kPi * pipe.d_inner};
    }
    const double f = alm_hamre_clay_shaft_friction(s.qt, s.fs, s.sigma_v, z, p);
    return {k.alm_hamre_clay_outside * f * kPi * pipe.d_outer,
            k.alm_hamre_clay_inside * f * kPi * pipe.d_inner};
}

double alm_hamre_end_bearing(const SoilPoint& tip) {
    return tip.layer->type == SoilType::Sand ? alm_hamre_sand_end_bearing(tip.qt, tip.sigma_v)
                                             : alm_hamre_clay_end_bearing(tip.qt);
}

// Stevens et al. (1982): sand K sigma'_v0 tan(delta) <= f_lim; clay s_u,r (lower) or s_u.
double stevens_unit_friction(const SoilPoint& s, const SrdCoefficients& k, bool upper) {
    const SoilLayer& l = *s.layer;
    if (l.type == SoilType::Clay && upper) return s.su;
    if (l.type == SoilType::Clay) {
        if (!(l.sensitivity > 0.0))
            throw std::invalid_argument("Stevens SRD: clay layer '" + l.name +
                                        "' needs a positive sensitivity");
        return s.su / l.sensitivity;
    }
    const double kk = upper ? k.stevens_k_upper : k.stevens_k_lower;
    const double f = kk * s.sigma_v * tan_deg(l.interface_friction_angle);
    return std::min(f, api_sand_limits(l.interface_friction_angle).limiting_friction);
}

double stevens_end_bearing(const SoilPoint& tip) {
    if (tip.layer->type == SoilType::Clay) return 9.0 * tip.su;
    const ApiSandLimits lim = api_sand_limits(tip.layer->interface_friction_angle);
    return std::min(lim.bearing_factor * tip.sigma_v, lim.limiting_bearing);
}

SrdModes alm_hamre_modes(const SoilProfile& soil, const SrdCoefficients& k, const Pipe& pipe,
                         double p, double spacing) {
    auto faces = [&](const SoilPoint& s, double z) { return alm_hamre_faces(s, k, pipe, z, p); };
    return {sample_shaft(soil, p, spacing, faces), alm_hamre_end_bearing(soil_point(soil, p))};
}

SrdModes stevens_modes(const SoilProfile& soil, const SrdCoefficients& k, const Pipe& pipe,
                       double p, double spacing, bool upper) {
    // Stevens: the inside unit friction equals the outside one.
    auto faces = [&](const SoilPoint& s, double) {
        const double f = stevens_unit_friction(s, k, upper);
        return Faces{f * kPi * pipe.d_outer, f * kPi * pipe.d_inner};
    };
    return {sample_shaft(soil, p, spacing, faces), stevens_end_bearing(soil_point(soil, p))};
}

// Unified (Lehane et al. 2020): coring faces; the plug's base is checked in compute_srd.
SrdModes unified_coring_modes(const SoilProfile& soil, const SrdCoefficients& k, const Pipe& pipe,
                              double p, double spacing) {
    const double are = unified_effective_area_ratio(pipe.d_outer, pipe.d_inner, k.cone_diameter);
    auto faces = [&](const SoilPoint& s, double z) {
        const double h = p - z;
        const double f = s.layer->type == SoilType::Sand
                             ? unified_sand_shaft_friction(s.qt, s.sigma_v, s.layer->interface_friction_angle, h,
                                                           pipe.d_outer, are, k.cone_diameter)
                             : unified_clay_shaft_friction(s.qt, h, pipe.d_outer, pipe.d_inner,
                                                           k.unified_clay_shaft_factor);
        return Faces{f * kPi * pipe.d_outer, k.unified_inside_share * f * kPi * pipe.d_inner};
    };
    // The annulus bears like a cone: the averaged q_c in sand, Alm & Hamre's 0.6 q_t in clay.
    const double q = average_cone_resistance(soil, p, k.toe_averaging_diameters * pipe.d_outer);
    const bool sand = soil.layer_at(p).type == SoilType::Sand;
    return {sample_shaft(soil, p, spacing, faces), sand ? q : alm_hamre_clay_end_bearing(q)};
}

// The plugged base over the gross area: (0.12 + 0.38 A_re) q_p in sand, 9 s_u in clay.
double unified_plug_base(const SoilProfile& soil, const SrdCoefficients& k, const Pipe& pipe, double p) {
    if (soil.layer_at(p).type == SoilType::Clay) return 9.0 * soil.undrained_shear_strength(p);
    const double are = unified_effective_area_ratio(pipe.d_outer, pipe.d_inner, k.cone_diameter);
    return unified_sand_base(average_cone_resistance(soil, p, k.toe_averaging_diameters * pipe.d_outer), are);
}

// Plugged when that mode resists less: the inside friction exceeds q on the plug area.
bool stevens_plugs(const SrdModes& m, const Pipe& pipe, double p) {
    const double inside = integrate(m.shaft.depth, m.shaft.inside, p);
    return m.toe_unit * (pipe.area_gross() - pipe.area_annulus()) < inside;
}

ResistanceDistribution assemble(const SrdModes& m, const Pipe& pipe, bool plugged, double p,
                                double factor, SrdDetails* details) {
    ResistanceDistribution r;
    r.penetration = p;
    r.depth = m.shaft.depth;
    r.shaft.resize(r.depth.size());
    for (std::size_t i = 0; i < r.depth.size(); ++i)
        r.shaft[i] = factor * (m.shaft.outside[i] + (plugged ? 0.0 : m.shaft.inside[i]));
    r.toe = factor * m.toe_unit * (plugged ? pipe.area_gross() : pipe.area_annulus());
    if (details) {
        details->plugged = plugged;
        details->shaft_outside = factor * integrate(r.depth, m.shaft.outside, p);
        details->shaft_inside = plugged ? 0.0 : factor * integrate(r.depth, m.shaft.inside, p);
        details->toe = r.toe;
    }
    return r;
}

void check_srd_inputs(double d_outer, double wall, double penetration, double spacing,
                      double factor) {
    if (!(d_outer > 0.0) || !(wall > 0.0) || !(2.0 * wall <= d_outer))
        throw std::invalid_argument("compute_srd: need 0 < wall <= d_outer / 2");
    if (!(penetration >= 0.0)) throw std::invalid_argument("compute_srd: negative penetration");
    if (!(spacing > 0.0)) throw std::invalid_argument("compute_srd: spacing must be positive");
    if (!(factor >= 0.0)) throw std::invalid_argument("compute_srd: factor must be >= 0");
}

}  // namespace

const char* srd_method_name(SrdMethod m) {
    switch (m) {
        case SrdMethod::AlmHamre2001:
            return "alm_hamre_2001";
        case SrdMethod::StevensLowerBound:
            return "stevens_lower_bound";
        case SrdMethod::StevensUpperBound:
            return "stevens_upper_bound";
        case SrdMethod::Unified2020:
            return "unified_2020";
    }
    return "unknown";
}

double alm_hamre_sand_shaft_friction(double qc, double sigma_v, double delta_deg, double z,
                                     double p, double pa) {
    // f_s,i = 0.0132 q_c (sigma'_v0/p_a)^0.13 tan(delta); f_s,res = 0.2 f_s,i (spec 1.2).
    const double f_initial =
        0.0132 * qc * std::pow(guarded(sigma_v) / pa, 0.13) * tan_deg(delta_deg);
    return degrade(f_initial, 0.2 * f_initial, fatigue_rate(qc, sigma_v), z, p);
}

double alm_hamre_clay_shaft_friction(double qt, double fs, double sigma_v, double z, double p) {
    // The residual bracket turns negative above q_t/sigma'_v0 = 400: clip to [0, f_s,i].
    const double residual = 0.004 * qt * (1.0 - 0.0025 * qt / guarded(sigma_v));
    const double f_residual = std::max(0.0, std::min(residual, fs));
    return degrade(fs, f_residual, fatigue_rate(qt, sigma_v), z, p);
}

double alm_hamre_sand_end_bearing(double qc, double sigma_v) {
    const double q = std::max(qc, 0.0);
    return 0.15 * q * std::pow(q / guarded(sigma_v), 0.2);
}

double alm_hamre_clay_end_bearing(double qt) {
    return 0.6 * qt;
}

double unified_effective_area_ratio(double d_outer, double d_inner, double d_cone) {
    const double plug_length_ratio = std::tanh(0.3 * std::sqrt(d_inner / d_cone));
    return 1.0 - plug_length_ratio * (d_inner / d_outer) * (d_inner / d_outer);
}

double unified_sand_shaft_friction(double qc, double sigma_v, double delta_deg, double h, double d_outer,
                                   double area_ratio, double d_cone) {
    const double q = std::max(qc, 0.0);
    const double radial = q / 44.0 * std::pow(area_ratio, 0.3) * std::pow(std::max(1.0, h / d_outer), -0.4);
    const double dilation = q > 0.0 ? q / 10.0 * std::pow(q / guarded(sigma_v), -0.33) * d_cone / d_outer : 0.0;
    return (radial + dilation) * tan_deg(delta_deg);
}

double unified_clay_shaft_friction(double qt, double h, double d_outer, double d_inner, double f_st) {
    const double d_star = std::sqrt(d_outer * d_outer - d_inner * d_inner);
    return 0.07 * f_st * std::max(qt, 0.0) * std::pow(std::max(1.0, h / d_star), -0.25);
}

double unified_sand_base(double qp, double area_ratio) {
    return (0.12 + 0.38 * area_ratio) * std::max(qp, 0.0);
}

double average_cone_resistance(const SoilProfile& soil, double p, double half_width) {
    double a = std::max(p - half_width, 0.0), b = p + half_width;
    if (!soil.cpt.depth.empty() && p <= soil.cpt.depth.back()) b = std::min(b, soil.cpt.depth.back());
    if (!(b > a)) return soil.cone_resistance(p);
    // Trapezoids between the record's own depths are exact for the piecewise-linear
    // record; without a record the correlation is sampled every 5 cm.
    std::vector<double> z;
    const int n = std::max(2, static_cast<int>(std::ceil((b - a) / 0.05)));
    if (soil.cpt.depth.empty())
        for (int i = 0; i <= n; ++i) z.push_back(a + (b - a) * i / n);
    else {
        z.push_back(a);
        for (double d : soil.cpt.depth)
            if (d > a && d < b) z.push_back(d);
        z.push_back(b);
    }
    double sum = 0.0, prev = soil.cone_resistance(z[0]);
    for (std::size_t i = 1; i < z.size(); ++i) {
        const double q = soil.cone_resistance(z[i]);
        sum += 0.5 * (prev + q) * (z[i] - z[i - 1]);
        prev = q;
    }
    return sum / (b - a);
}

ApiSandLimits api_sand_limits(double delta_deg) {
    const double d = std::clamp(delta_deg, kApiSandTable.front().delta, kApiSandTable.back().delta);
    std::size_t i = 1;
    while (i + 1 < kApiSandTable.size() && d > kApiSandTable[i].delta) ++i;
    const ApiSandRow& lo = kApiSandTable[i - 1];
    const ApiSandRow& hi = kApiSandTable[i];
    const double w = (d - lo.delta) / (hi.delta - lo.delta);
    return {lerp(lo.limits.limiting_friction, hi.limits.limiting_friction, w),
            lerp(lo.limits.bearing_factor, hi.limits.bearing_factor, w),
            lerp(lo.limits.limiting_bearing, hi.limits.limiting_bearing, w)};
}

ResistanceDistribution compute_srd(const SoilProfile& soil, SrdMethod method,
                                   const SrdCoefficients& k, double d_outer, double wall,
                                   double penetration, double spacing, double factor,
                                   SrdDetails* details) {
    check_srd_inputs(d_outer, wall, penetration, spacing, factor);
    const Pipe pipe{d_outer, d_outer - 2.0 * wall};
    if (method == SrdMethod::AlmHamre2001) {
        // Alm & Hamre assume a coring pile: no plug check (spec 1.5).
        const SrdModes m = alm_hamre_modes(soil, k, pipe, penetration, spacing);
        return assemble(m, pipe, false, penetration, factor, details);
    }
    if (method == SrdMethod::Unified2020) {
        SrdModes m = unified_coring_modes(soil, k, pipe, penetration, spacing);
        const double plug = unified_plug_base(soil, k, pipe, penetration);
        const double inside = integrate(m.shaft.depth, m.shaft.inside, penetration);
        const bool plugged = plug * pipe.area_gross() < inside + m.toe_unit * pipe.area_annulus();
        if (plugged) m.toe_unit = plug;
        return assemble(m, pipe, plugged, penetration, factor, details);
    }
    const bool upper = method == SrdMethod::StevensUpperBound;
    const SrdModes m = stevens_modes(soil, k, pipe, penetration, spacing, upper);
    return assemble(m, pipe, stevens_plugs(m, pipe, penetration), penetration, factor, details);
}

}  // namespace pilempm::coupling
