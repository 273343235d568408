#pragma once
// A soil material as read from a case file (MPM cases and element tests share it), and the
// constitutive model built from it.
#include <memory>
#include <string>

#include "io/yaml_reader.hpp"
#include "mpm/constitutive_model.hpp"

namespace pilempm::io {

struct MaterialInput {
    std::string name, model;  // linear_elastic | mohr_coulomb | modified_cam_clay | hardening_soil_small
    double density = 0.0, youngs_modulus = 0.0, poisson_ratio = 0.3;
    double friction_angle = 0.0, dilation_angle = 0.0, cohesion = 0.0, tension_cutoff = 0.0;
    // Modified Cam clay: NCL and unloading slopes, critical state ratio (or friction_angle),
    // initial void ratio, OCR, the stiffness floor.
    double lambda = 0.0, kappa = 0.0, critical_state_ratio = 0.0, void_ratio = 0.0, ocr = 1.0, min_pressure = 1e3;
    // Hardening soil small (poisson_ratio is nu_ur; friction, dilation, cohesion as above;
    // ocr and min_pressure as for Cam clay): stiffnesses in Pa, gamma_0.7, exponent m,
    // p_ref (Pa), failure ratio R_f, K0 of normal consolidation (<0: 1 - sin phi).
    double e50_ref = 0.0, eoed_ref = 0.0, eur_ref = 0.0, g0_ref = 0.0, gamma_07 = 0.0, stiffness_exponent = 0.5;
    double reference_pressure = 100e3, failure_ratio = 0.9, k0_nc = -1.0;
    double k0 = -1.0;  // <0: k0_nc (HS small), 1 - sin(phi) (frictional models) or nu / (1 - nu) (elastic)
};

// with_density: MPM materials need one; an element test does not.
MaterialInput read_material(MapReader m, bool with_density);
std::unique_ptr<mpm::ConstitutiveModel> make_constitutive_model(const MaterialInput& m);
double k0_of(const MaterialInput& m);

}  // namespace pilempm::io
