#pragma once
// The soil for drivability from a piezocone sounding alone (q_c, f_s, u_2): corrected cone
// resistance, unit weight, in-situ stresses, Robertson's soil behaviour type index I_c,
// the sand/clay split with thin spurious layers smoothed away, s_u in clay and D_R in sand.
// Every correlation is named in `cpt_correlations()` so outputs can state them.
// Depth z positive down from the mudline; stresses in Pa.
#include <string>
#include <vector>

#include "coupling/wave_equation/soil_profile.hpp"
#include "core/table.hpp"

namespace pilempm::coupling {

// A CPT as measured: depth increasing, q_c, f_s and u_2 in Pa (u_2 relative to the
// mudline water pressure, as offshore records give it: hydrostatic u_0 = gamma_w z).
struct CptSounding {
    std::vector<double> depth, qc, fs, u2;
};

struct CptInterpretationOptions {
    double net_area_ratio = 0.8;           // a: q_t = q_c + (1 - a) u_2
    double u2_floor = -0.1e6;              // Pa: dilatant negative u_2 clipped for q_t
    double water_unit_weight = 10.05e3;    // N/m^3, sea water
    double atmospheric_pressure = 100e3;   // Pa
    double unit_weight_min = 14.0e3, unit_weight_max = 22.5e3;  // N/m^3 clip
    double sand_clay_boundary = 2.6;       // I_c: sand-like below, clay-like above
    double min_layer_thickness = 1.0;      // m: thinner sand/clay runs join their neighbours
    double cone_factor = 15.0;             // N_kt: s_u = (q_t - sigma_v0) / N_kt
    double clay_sensitivity = 2.0;         // S_t of the derived clay layers
    double interface_friction_angle = 29.0;  // deg, delta of the derived sand layers
};

// One interpreted CPT depth.
struct CptPoint {
    double depth = 0.0;
    double qc = 0.0, qt = 0.0, fs = 0.0, u2 = 0.0;    // Pa
    double unit_weight = 0.0;                          // N/m^3, total
    double sigma_v0 = 0.0, u0 = 0.0, sigma_v0_eff = 0.0;  // Pa
    double friction_ratio = 0.0;      // R_f = f_s / q_t, %
    double qtn = 0.0;                 // Q_tn, with the stress exponent n
    double fr = 0.0;                  // F_r = f_s / (q_t - sigma_v0), %
    double stress_exponent = 0.0;     // n
    double ic = 0.0;                  // I_c
    int zone = 0;                     // Robertson (1990/2009) soil behaviour type zone 2..7
    bool clay_like = false;           // I_c above the boundary, before smoothing
    SoilType type = SoilType::Sand;   // after smoothing thin layers
    double su = 0.0;                  // Pa (clay)
    double relative_density = 0.0;    // fraction (sand), Baldi et al. (1986) NC
    double friction_angle = 0.0;      // deg (sand), Kulhawy & Mayne (1990)
};

struct CptInterpretation {
    std::vector<CptPoint> points;
    SoilProfile profile;   // one layer per CPT interval, the record as its cone resistance
    int smoothed_points = 0;  // points whose soil type the smoothing changed
};

// Robertson's I_c with the stress exponent n found by fixed point (Robertson 2009).
struct BehaviourIndex {
    double ic, n, qtn, fr;
};
BehaviourIndex robertson_behaviour_index(double qt, double fs, double sigma_v0, double sigma_v0_eff,
                                         double pa);
int robertson_zone(double ic);  // 7 gravelly sand ... 2 organic soil (I_c boundaries)
// Robertson & Cabal (2010): gamma / gamma_w = 0.27 log R_f + 0.36 log(q_t / p_a) + 1.236.
double robertson_cabal_unit_weight(double qt, double fs, double gamma_w, double pa);

CptInterpretation interpret_cpt(const CptSounding& cpt, const CptInterpretationOptions& o,
                                double water_depth);

// Depth-by-depth table of an interpretation (the derived-profile CSV).
Table cpt_profile_table(const CptInterpretation& c, const std::string& name);

// The correlations used, one line each, for summaries and the README.
std::vector<std::string> cpt_correlations(const CptInterpretationOptions& o);

}  // namespace pilempm::coupling
