#pragma once
// Static resistance to driving (SRD) of an open-ended pipe pile at a tip penetration:
// unit shaft friction and unit end bearing from published methods, integrated into a
// ResistanceDistribution for the Smith soil. Stresses in Pa, lengths in m, forces in N.
#include <string>

#include "coupling/wave_equation/resistance_distribution.hpp"
#include "coupling/wave_equation/soil_profile.hpp"

namespace pilempm::coupling {

enum class SrdMethod {
    AlmHamre2001,       // CPT-based, friction fatigue; coring (unplugged) pile
    StevensLowerBound,  // Stevens, Wiltsie & Turton (1982), lower bound
    StevensUpperBound,  // Stevens, Wiltsie & Turton (1982), upper bound
    Unified2020,        // Lehane et al. (2020) "unified" CPT method (ISO 19901-4:2025),
                        // coring or plugged, whichever resists less
};
const char* srd_method_name(SrdMethod m);  // "alm_hamre_2001", "stevens_lower_bound", ...

// Coefficients of the methods (Stevens' are recalled, not read from the paper: keep
// them editable).
struct SrdCoefficients {
    double atmospheric_pressure = 100e3;        // Pa
    double alm_hamre_sand_outside = 0.5;        // share of f on the outside perimeter
    double alm_hamre_sand_inside = 0.5;         // and on the inside
    double alm_hamre_clay_outside = 1.0;
    double alm_hamre_clay_inside = 1.0;
    double stevens_k_lower = 0.5;               // lateral earth pressure coefficient, sand
    double stevens_k_upper = 0.7;
    double unified_inside_share = 1.0;          // inner shaft friction / outer, coring mode
    double unified_clay_shaft_factor = 1.0;     // F_st (0.5 for sensitive clay)
    double toe_averaging_diameters = 1.5;       // q_c averaged over +- this many D at the toe
    double cone_diameter = 0.0357;              // m, d_CPT of a 10 cm^2 cone
};

// Alm & Hamre (2001). z: depth of the soil point, p: tip penetration (z <= p).
double alm_hamre_sand_shaft_friction(double qc, double sigma_v, double delta_deg, double z, double p,
                                     double pa);
double alm_hamre_clay_shaft_friction(double qt, double fs, double sigma_v, double z, double p);
double alm_hamre_sand_end_bearing(double qc, double sigma_v);  // 0.15 qc (qc/sigma'_v0)^0.2
double alm_hamre_clay_end_bearing(double qt);                   // 0.6 qt

// Lehane et al. (2020), "unified" method. h = p - z above the tip; stresses in Pa.
// A_re = 1 - tanh(0.3 sqrt(D_i / d_CPT)) (D_i / D)^2, the effective area ratio.
double unified_effective_area_ratio(double d_outer, double d_inner, double d_cone);
// tau = (q_c/44 A_re^0.3 max(1, h/D)^-0.4 + q_c/10 (q_c/sigma'_v0)^-0.33 d_CPT/D) tan(delta)
double unified_sand_shaft_friction(double qc, double sigma_v, double delta_deg, double h, double d_outer,
                                   double area_ratio, double d_cone);
// tau = 0.07 F_st q_t max(1, h/D*)^-0.25, D* = sqrt(D^2 - D_i^2)
double unified_clay_shaft_friction(double qt, double h, double d_outer, double d_inner, double f_st);
double unified_sand_base(double qp, double area_ratio);  // (0.12 + 0.38 A_re) q_p, gross area
// q_t averaged over [p - half_width, p + half_width] (within the mudline and the CPT).
double average_cone_resistance(const SoilProfile& soil, double p, double half_width);

// API RP2A (1993) limits used by the Stevens sand bounds: delta -> (f_lim, N_q, q_lim).
struct ApiSandLimits {
    double limiting_friction;  // Pa
    double bearing_factor;     // N_q
    double limiting_bearing;   // Pa
};
ApiSandLimits api_sand_limits(double delta_deg);

struct SrdDetails {
    bool plugged = false;           // Stevens: the plugged mode governed
    double shaft_outside = 0.0;     // N
    double shaft_inside = 0.0;      // N
    double toe = 0.0;               // N
};

// SRD at tip penetration `penetration` for a pipe pile of outer diameter `d_outer` and
// wall `wall` (constant over the embedded length), sampled at most `spacing` apart and at
// every layer boundary. `factor` scales shaft and toe (e.g. 1.25 for an upper bound).
ResistanceDistribution compute_srd(const SoilProfile& soil, SrdMethod method,
                                   const SrdCoefficients& k, double d_outer, double wall,
                                   double penetration, double spacing, double factor = 1.0,
                                   SrdDetails* details = nullptr);

}  // namespace pilempm::coupling
