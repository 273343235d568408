#include "coupling/wave_equation/soil_profile.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace pilempm::coupling {

namespace {

constexpr double kKpa = 1e3;                           // Pa per kPa
constexpr double kMinStress = 1.0 * kKpa;              // spec section 0 guard on sigma'_v0
constexpr double kSeawaterUnitWeight = 1025.0 * 9.81;  // N/m^3, hydrostatic pore water
constexpr double kDepthTolerance = 1e-9;               // m, for layer contiguity

[[noreturn]] void throw_layer_error(std::size_t index, const SoilLayer& layer,
                                    const std::string& what, double depth) {
    std::ostringstream msg;
    msg << "soil profile: layer " << index + 1 << " ('" << layer.name << "') " << what << " "
        << depth << " m below the mudline";
    throw std::invalid_argument(msg.str());
}

// Every query checks the layers: the profile is plain data and may be edited after use.
void check_layers(const std::vector<SoilLayer>& layers) {
    if (layers.empty()) throw std::invalid_argument("soil profile: no soil layers");
    double expected_top = 0.0;  // the first layer starts at the mudline
    for (std::size_t i = 0; i < layers.size(); ++i) {
        const SoilLayer& l = layers[i];
        if (std::abs(l.top - expected_top) > kDepthTolerance)
            throw_layer_error(i, l, "is not contiguous: it should start at", expected_top);
        if (!(l.bottom > l.top)) throw_layer_error(i, l, "has no thickness at", l.top);
        expected_top = l.bottom;
    }
}

// Linear interpolation of one CPT column; the caller has checked that z is covered.
double interpolate_cpt(const CptRecord& cpt, const std::vector<double>& column, double z) {
    if (column.size() != cpt.depth.size())
        throw std::invalid_argument("CPT record: a column's length differs from the depths'");
    const auto it = std::upper_bound(cpt.depth.begin(), cpt.depth.end(), z);
    if (it == cpt.depth.end()) return column.back();
    const std::size_t i = static_cast<std::size_t>(it - cpt.depth.begin());
    if (i == 0) return column.front();
    const double w = (z - cpt.depth[i - 1]) / (cpt.depth[i] - cpt.depth[i - 1]);
    return (1.0 - w) * column[i - 1] + w * column[i];
}

}  // namespace

double baldi_cone_resistance(double relative_density, double vertical_effective_stress) {
    // Published in kPa: q_c = 157 sigma'^0.55 exp(2.41 D_R).
    const double sigma_kpa = std::max(vertical_effective_stress, kMinStress) / kKpa;
    return 157.0 * std::pow(sigma_kpa, 0.55) * std::exp(2.41 * relative_density) * kKpa;
}

const SoilLayer& SoilProfile::layer_at(double z) const {
    check_layers(layers);
    for (const SoilLayer& l : layers)
        if (z < l.bottom) return l;
    return layers.back();
}

double SoilProfile::vertical_effective_stress(double z) const {
    check_layers(layers);
    double sigma = 0.0;
    for (std::size_t i = 0; i < layers.size() && z > layers[i].top; ++i) {
        const bool last = i + 1 == layers.size();
        const double bottom = last ? z : std::min(z, layers[i].bottom);
        sigma += layers[i].submerged_unit_weight * (bottom - layers[i].top);
    }
    return sigma;
}

double SoilProfile::undrained_shear_strength(double z) const {
    const SoilLayer& l = layer_at(z);
    return l.undrained_shear_strength + l.undrained_shear_strength_gradient * (z - l.top);
}

double SoilProfile::cone_resistance(double z) const {
    if (has_cpt_at(z)) return interpolate_cpt(cpt, cpt.qt, z);
    const SoilLayer& l = layer_at(z);
    const double sigma_eff = vertical_effective_stress(z);
    if (l.type == SoilType::Sand) return baldi_cone_resistance(l.relative_density, sigma_eff);
    // q_t = N_kt s_u + sigma_v0: the total stress includes the water column above the mudline.
    const double pore_pressure = kSeawaterUnitWeight * (water_depth + std::max(z, 0.0));
    return clay_cone_factor * undrained_shear_strength(z) + sigma_eff + pore_pressure;
}

double SoilProfile::sleeve_friction(double z) const {
    if (has_cpt_at(z)) return interpolate_cpt(cpt, cpt.fs, z);
    const SoilLayer& l = layer_at(z);
    if (l.type == SoilType::Sand) return 0.0;
    if (!(l.sensitivity > 0.0))
        throw std::invalid_argument("soil profile: clay layer '" + l.name +
                                    "' needs a positive sensitivity");
    return undrained_shear_strength(z) / l.sensitivity;
}

bool SoilProfile::has_cpt_at(double z) const {
    return !cpt.depth.empty() && cpt.depth.front() <= z && z <= cpt.depth.back();
}

}  // namespace pilempm::coupling
