#pragma once
// The seabed soil for drivability: horizontal layers below the mudline, hydrostatic pore
// water, and the cone resistance either measured (CPT file) or derived from relative
// density. Depth z is positive down from the mudline; stresses in Pa.
#include <string>
#include <vector>

namespace pilempm::coupling {

enum class SoilType { Sand, Clay };

struct SoilLayer {
    double top = 0.0, bottom = 0.0;          // m below the mudline
    SoilType type = SoilType::Sand;
    double submerged_unit_weight = 0.0;      // N/m^3 (gamma')
    double relative_density = 0.0;           // fraction (sand); may exceed 1 as reported
    double friction_angle = 0.0;             // deg, peak (sand)
    double interface_friction_angle = 0.0;   // deg, delta
    double undrained_shear_strength = 0.0;   // Pa at the layer top (clay)
    double undrained_shear_strength_gradient = 0.0;  // Pa/m (clay)
    double sensitivity = 2.0;                // s_u / s_u,remoulded (clay)
    std::string name;                        // e.g. "very dense sand"
};

// A CPT record: cone resistance q_t and sleeve friction f_s against depth.
struct CptRecord {
    std::vector<double> depth;  // m, increasing
    std::vector<double> qt;     // Pa
    std::vector<double> fs;     // Pa
};

struct SoilProfile {
    std::vector<SoilLayer> layers;  // contiguous from the mudline down
    double water_depth = 0.0;       // m above the mudline (pore pressure is hydrostatic)
    CptRecord cpt;                  // empty: derive q_c from D_R (sand) or s_u (clay)
    double clay_cone_factor = 15.0; // N_kt: q_t = N_kt s_u + sigma_v0 for clay without a CPT

    const SoilLayer& layer_at(double z) const;  // the deepest layer is extended downward
    double vertical_effective_stress(double z) const;  // Pa, integral of gamma'
    double undrained_shear_strength(double z) const;   // Pa (clay layers)
    // q_t: from the CPT where it covers z, else Baldi et al. (1986) for NC sand,
    // q_c = 157 sigma'_v0^0.55 exp(2.41 D_R) (kPa), or N_kt s_u + sigma_v0 for clay.
    double cone_resistance(double z) const;
    // f_s: from the CPT, else s_u / S_t for clay (the sleeve measures about the remoulded
    // strength) and 0 for sand (not used by the sand methods).
    double sleeve_friction(double z) const;
    bool has_cpt_at(double z) const;
};

// Baldi et al. (1986), normally consolidated sand: q_c in Pa from sigma'_v0 in Pa.
double baldi_cone_resistance(double relative_density, double vertical_effective_stress);

}  // namespace pilempm::coupling
