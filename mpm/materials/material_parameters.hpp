#pragma once
// The parameters of a soil material (MPM cases and element tests share them), one struct
// for every model; the factory (material_factory.hpp) builds the model they name.
#include <string>

#include "mpm/materials/hypoplastic.hpp"
#include "mpm/materials/mu_i_rheology.hpp"
#include "mpm/materials/user_material.hpp"

namespace pilempm::mpm {

struct MaterialParameters {
    // linear_elastic | mohr_coulomb | modified_cam_clay | subloading_cam_clay | hypoplastic |
    // hardening_soil_small | mu_i_rheology | umat
    std::string name, model;
    double density = 0.0, youngs_modulus = 0.0, poisson_ratio = 0.3;
    double friction_angle = 0.0, dilation_angle = 0.0, cohesion = 0.0, tension_cutoff = 0.0;
    // Modified (and subloading) Cam clay: NCL and unloading slopes, critical state ratio (or friction_angle),
    // initial void ratio, OCR, the stiffness floor; the friction angle of the Matsuoka-Nakai cone
    // that bounds the stress (deg; 0: none).
    double peak_friction_angle = 0.0;
    double lambda = 0.0, kappa = 0.0, critical_state_ratio = 0.0, void_ratio = 0.0, ocr = 1.0, min_pressure = 1e3;
    // Hypoplastic (von Wolffersdorff) with intergranular strain (Niemunis & Herle); phi_c,
    // e0 and p_min come from friction_angle, void_ratio and min_pressure.
    HypoplasticParameters hypo;
    // A user material (Abaqus UMAT in a shared library); library resolved against the case file.
    UserMaterialParameters umat;
    // Granular flow with mu(I) friction; E and nu as above, friction_angle = atan(mu_s) for K0.
    MuIParameters mu_i;
    // Subloading Cam clay besides: a of G(rho) = a rho^2 (required) and the shape of the
    // critical state surface in the deviatoric plane (matsuoka_nakai | drucker_prager).
    double subloading_a = 0.0;
    std::string critical_state_surface = "matsuoka_nakai";
    // Hardening soil small (poisson_ratio is nu_ur; friction, dilation, cohesion as above;
    // ocr and min_pressure as for Cam clay): stiffnesses in Pa, gamma_0.7, exponent m,
    // p_ref (Pa), failure ratio R_f, K0 of normal consolidation (<0: 1 - sin phi).
    double e50_ref = 0.0, eoed_ref = 0.0, eur_ref = 0.0, g0_ref = 0.0, gamma_07 = 0.0, stiffness_exponent = 0.5;
    double reference_pressure = 100e3, failure_ratio = 0.9, k0_nc = -1.0;
    // Pore water (MPM materials): dry | drained | undrained | coupled; the porosity of a
    // saturated material (density is then the saturated bulk density); a coupled one's
    // permeability as hydraulic conductivity k (m/s) or intrinsic permeability (m^2), one of them.
    std::string drainage = "dry";
    double porosity = 0.0, hydraulic_conductivity = 0.0, intrinsic_permeability = 0.0;
    double k0 = -1.0;  // <0: k0_nc (HS small), 1 - sin(phi) (frictional models) or nu / (1 - nu) (elastic)
};

}  // namespace pilempm::mpm
