#include "mpm/materials/material_factory.hpp"

#include <cmath>
#include <numbers>

#include "mpm/materials/hardening_soil_small.hpp"
#include "mpm/materials/modified_cam_clay.hpp"
#include "mpm/materials/mohr_coulomb.hpp"
#include "mpm/materials/subloading_cam_clay.hpp"

namespace pilempm::mpm {

namespace {
double sin_deg(double a) { return std::sin(a * std::numbers::pi / 180.0); }

// The keys both Cam clay models read the same way.
template <class Parameters>
void set_critical_state_common(const MaterialParameters& m, Parameters& p) {
    p.lambda = m.lambda;
    p.kappa = m.kappa;
    p.poisson_ratio = m.poisson_ratio;
    p.void_ratio = m.void_ratio;
    p.ocr = m.ocr;
    p.p_min = m.min_pressure;
}
}  // namespace

std::unique_ptr<ConstitutiveModel> make_constitutive_model(const MaterialParameters& m) {
    if (m.model == "linear_elastic") return std::make_unique<LinearElastic>(m.youngs_modulus, m.poisson_ratio);
    if (m.model == "hardening_soil_small") {
        HardeningSoilSmallParameters p;
        p.E50_ref = m.e50_ref;
        p.Eoed_ref = m.eoed_ref;
        p.Eur_ref = m.eur_ref;
        p.nu_ur = m.poisson_ratio;
        p.G0_ref = m.g0_ref;
        p.gamma_07 = m.gamma_07;
        p.m = m.stiffness_exponent;
        p.p_ref = m.reference_pressure;
        p.phi = m.friction_angle;
        p.c = m.cohesion;
        p.psi = m.dilation_angle;
        p.R_f = m.failure_ratio;
        p.K0_nc = m.k0_nc;
        p.ocr = m.ocr;
        p.p_min = m.min_pressure;
        return std::make_unique<HardeningSoilSmall>(p);
    }
    if (m.model == "modified_cam_clay") {
        CamClayParameters p;
        set_critical_state_common(m, p);
        p.M = m.critical_state_ratio;
        p.peak_friction_angle = m.peak_friction_angle;
        return std::make_unique<ModifiedCamClay>(p);
    }
    if (m.model == "hypoplastic") {
        HypoplasticParameters p = m.hypo;
        p.phi_c = m.friction_angle;
        p.void_ratio = m.void_ratio;
        p.p_min = m.min_pressure;
        return std::make_unique<Hypoplastic>(p);
    }
    if (m.model == "mu_i_rheology") return std::make_unique<MuIRheology>(m.mu_i);
    if (m.model == "umat") return std::make_unique<UserMaterial>(m.umat);
    if (m.model == "subloading_cam_clay") {
        SubloadingCamClayParameters p;
        set_critical_state_common(m, p);
        p.friction_angle = m.friction_angle;  // M in compression = critical_state_ratio
        p.surface = m.critical_state_surface == "drucker_prager" ? CriticalStateSurface::DruckerPrager
                                                                 : CriticalStateSurface::MatsuokaNakai;
        p.a = m.subloading_a;
        p.peak_friction_angle = m.peak_friction_angle;
        return std::make_unique<SubloadingCamClay>(p);
    }
    return std::make_unique<MohrCoulomb>(m.youngs_modulus, m.poisson_ratio, m.friction_angle, m.dilation_angle,
                                              m.cohesion, m.tension_cutoff);
}

bool has_void_ratio(const MaterialParameters& m) {
    return m.model == "modified_cam_clay" || m.model == "subloading_cam_clay" || m.model == "hypoplastic";
}

double k0_of(const MaterialParameters& m) {
    if (m.k0 > 0.0) return m.k0;
    if (m.model == "hardening_soil_small" && m.k0_nc > 0.0) return m.k0_nc;
    if (m.model != "linear_elastic") return 1.0 - sin_deg(m.friction_angle);
    return m.poisson_ratio / (1.0 - m.poisson_ratio);
}

}  // namespace pilempm::mpm
