#include "io/cases/material_input.hpp"

#include <cmath>
#include <filesystem>
#include <numbers>


namespace pilempm::io {

namespace {
double sin_deg(double a) { return std::sin(a * std::numbers::pi / 180.0); }
// Keys as in the literature (Herle & Gudehus 1999 calibration): phi_c as friction_angle.
void read_hypoplastic(MapReader& m, MaterialInput& mat) {
    auto& h = mat.hypo;
    mat.friction_angle = m.number("friction_angle", {"the critical friction angle phi_c, 10 to 60 deg",
                                                     [](double x) { return x >= 10 && x < 60; }});
    h.h_s = m.number("h_s", positive("granular hardness h_s in Pa"));
    h.n = m.number("n", in_open_range(0.0, 1.0, "the exponent n of the compression law"));
    h.e_d0 = m.number("e_d0", positive("minimum void ratio at p = 0"));
    h.e_c0 = m.number("e_c0", {"critical void ratio at p = 0, above e_d0", [d = h.e_d0](double x) { return x > d; }});
    h.e_i0 = m.number("e_i0", {"maximum void ratio at p = 0, above e_c0", [c = h.e_c0](double x) { return x > c; }});
    h.alpha = m.number("alpha", non_negative("pycnotropy exponent alpha"));
    h.beta = m.number("beta", non_negative("pycnotropy exponent beta"));
    h.p_t = m.number_or("p_t", 0.0, non_negative("stress shift p_t in Pa"));
    mat.void_ratio = m.number("void_ratio", {"initial void ratio between e_d0 / 2 and e_i0",
                                             [&h](double x) { return x > 0.5 * h.e_d0 && x <= h.e_i0; }});
    h.intergranular_strain = m.boolean_or("intergranular_strain", true);
    if (h.intergranular_strain) {
        h.m_T = m.number_or("m_T", 2.0, {"m_T >= 1", [](double x) { return x >= 1.0; }});
        h.m_R = m.number_or("m_R", 5.0, {"m_R >= m_T", [t = h.m_T](double x) { return x >= t; }});
        h.R_max = m.number_or("R_max", 1e-4, positive("the elastic range R of the intergranular strain"));
        h.beta_r = m.number_or("beta_r", 0.5, positive("beta_r"));
        h.chi = m.number_or("chi", 6.0, positive("chi"));
        h.delta_along_stress = m.choice_or("initial_intergranular_strain", "zero", {"zero", "along_stress"}) == "along_stress";
    }
    mat.min_pressure = m.number_or("min_pressure", 1.0, positive("least shifted mean stress in Pa"));
}

// A UMAT's own parameters are opaque: PROPS and STATEV as the UMAT's documentation lists
// them; pilempm needs only the moduli for its stable time step.
void read_user_material(MapReader& m, MaterialInput& mat) {
    auto& u = mat.umat;
    const std::string library = m.text_or("library", "");
    if (library.empty()) m.fail("library", "the path of the UMAT's shared library (.so)", "none");
    std::filesystem::path path(library);
    if (path.is_relative()) path = std::filesystem::path(m.file()).parent_path() / path;
    if (!std::filesystem::is_regular_file(path))
        m.fail("library", "an existing shared library (a relative path starts at the case file)", path.string());
    u.library = path.string();
    u.symbol = m.text_or("symbol", "");
    u.name = m.text_or("cmname", "UMAT");
    u.properties = m.numbers("properties", {"any number", [](double) { return true; }});
    u.state_variables = m.integer_or("state_variables", 0, 0);
    if (m.has("initial_state")) {
        u.initial_state = m.numbers("initial_state", {"any number", [](double) { return true; }});
        if (static_cast<int>(u.initial_state.size()) > u.state_variables)
            m.fail("initial_state", "at most state_variables = " + std::to_string(u.state_variables) + " values",
                   std::to_string(u.initial_state.size()));
    }
    u.p_wave_modulus = m.number("p_wave_modulus", positive("the largest constrained modulus K + 4G/3 in Pa"));
    u.shear_modulus = m.number("shear_modulus", positive("the largest shear modulus in Pa"));
    u.thread_safe = m.boolean_or("thread_safe", true);
    mat.friction_angle = m.number_or("friction_angle", 30.0, {"an angle from 0 to 89 deg (for K0)",
                                                              [](double x) { return x >= 0 && x < 89; }});
}

// The friction law's keys as in Jop, Forterre & Pouliquen (2006); the defaults are their
// glass beads, so a case names what it changes.
void read_mu_i(MapReader& m, MaterialInput& mat) {
    auto& r = mat.mu_i;
    r.youngs_modulus = mat.youngs_modulus;
    r.poisson_ratio = mat.poisson_ratio;
    r.mu_s = m.number_or("mu_s", r.mu_s, in_open_range(0.0, 2.0, "the static friction coefficient mu_s"));
    r.mu_2 = m.number_or("mu_2", r.mu_2, {"a limiting friction coefficient mu_2 >= mu_s", [s = r.mu_s](double x) { return x >= s && x < 5.0; }});
    r.I_0 = m.number_or("I_0", r.I_0, positive("the inertial number I_0 halfway from mu_s to mu_2"));
    r.grain_diameter = m.number_or("grain_diameter", r.grain_diameter, in_open_range(0.0, 0.1, "a grain diameter in m"));
    r.grain_density = m.number_or("grain_density", r.grain_density, positive("the density of the grains in kg/m^3"));
    mat.friction_angle = std::atan(r.mu_s) * 180.0 / std::numbers::pi;
}

// How a saturated material drains. Porosity has one owner: a model with a void ratio gives
// it (n = e / (1 + e)) unless porosity is stated, and then the two must agree.
void read_pore_water(MapReader& m, MaterialInput& mat) {
    mat.drainage = m.choice_or("drainage", "dry", {"dry", "drained", "undrained", "coupled"});
    if (mat.drainage == "dry") {
        for (const char* key : {"porosity", "hydraulic_conductivity", "intrinsic_permeability"})
            if (m.has(key)) m.fail(key, std::string("no ") + key + " for a dry material (drainage: dry)", "one");
        return;
    }
    const double from_void_ratio = mat.void_ratio > 0.0 ? mat.void_ratio / (1.0 + mat.void_ratio) : 0.0;
    if (m.has("porosity")) {
        mat.porosity = m.number("porosity", in_open_range(0.0, 1.0, "a porosity n between 0 and 1"));
        if (from_void_ratio > 0.0 && std::abs(mat.porosity - from_void_ratio) > 1e-3)
            m.fail("porosity", "the porosity of the void ratio, e / (1 + e) = " + std::to_string(from_void_ratio),
                   std::to_string(mat.porosity));
    } else if (from_void_ratio > 0.0) {
        mat.porosity = from_void_ratio;
    } else {
        m.fail("porosity", "the porosity of a saturated material", "none");
    }
    if (mat.drainage != "coupled") {
        for (const char* key : {"hydraulic_conductivity", "intrinsic_permeability"})
            if (m.has(key)) m.fail(key, std::string("no ") + key + " unless drainage: coupled", "one");
        return;
    }
    if (m.has("hydraulic_conductivity") == m.has("intrinsic_permeability"))
        m.fail("hydraulic_conductivity", "one of hydraulic_conductivity (m/s) or intrinsic_permeability (m^2)",
               "both or neither");
    if (m.has("hydraulic_conductivity"))
        mat.hydraulic_conductivity = m.number("hydraulic_conductivity", positive("a hydraulic conductivity k in m/s"));
    else
        mat.intrinsic_permeability = m.number("intrinsic_permeability", positive("an intrinsic permeability in m^2"));
}

}  // namespace

MaterialInput read_material(MapReader m, bool with_density) {
    MaterialInput mat;
    mat.name = m.text_or("name", "");
    if (with_density && mat.name.empty()) m.fail("name", "a material name", "none");
    mat.model = m.choice("model", {"linear_elastic", "mohr_coulomb", "modified_cam_clay", "subloading_cam_clay",
                                   "hypoplastic", "hardening_soil_small", "mu_i_rheology", "umat"});
    if (with_density) mat.density = m.number("density", positive("density in kg/m^3"));
    if (mat.model != "hypoplastic" && mat.model != "umat")
        mat.poisson_ratio = m.number("poisson_ratio", in_open_range(-1.0, 0.5, "a Poisson's ratio"));
    const Expect angle{"an angle from 0 to 89 deg", [](double x) { return x >= 0 && x < 89; }};
    const bool cam_clay = mat.model == "modified_cam_clay" || mat.model == "subloading_cam_clay";
    if (cam_clay) {
        mat.lambda = m.number("lambda", positive("slope of the normal compression line"));
        mat.kappa = m.number("kappa", {"a swelling slope below lambda", [l = mat.lambda](double x) { return x > 0 && x < l; }});
        if (m.has("critical_state_ratio") == m.has("friction_angle"))
            m.fail("critical_state_ratio", "one of critical_state_ratio (M) or friction_angle (deg)", "both or neither");
        if (m.has("friction_angle")) {
            mat.friction_angle = m.number("friction_angle", {"an angle from 0 to 89 deg", [](double x) { return x > 0 && x < 89; }});
            const double s = sin_deg(mat.friction_angle);
            mat.critical_state_ratio = 6.0 * s / (3.0 - s);  // triaxial compression
        } else {
            mat.critical_state_ratio = m.number("critical_state_ratio", in_open_range(0.0, 3.0, "M = q / p' at critical state"));
            mat.friction_angle = std::asin(3.0 * mat.critical_state_ratio / (6.0 + mat.critical_state_ratio)) * 180.0 / std::numbers::pi;
        }
        mat.void_ratio = m.number("void_ratio", positive("initial void ratio"));
        mat.ocr = m.number_or("ocr", 1.0, {"an overconsolidation ratio >= 1", [](double x) { return x >= 1.0; }});
        mat.min_pressure = m.number_or("min_pressure", 1e3, positive("stiffness floor in Pa"));
        // The stress stays inside this Matsuoka-Nakai cone (no tension); 0, the default, is the
        // model as published, whose dry side reaches tension (README, subloading Cam clay).
        mat.peak_friction_angle = m.number_or(
            "peak_friction_angle", 0.0,
            {"0 (no bound) or an angle from friction_angle to 89 deg",
             [phi = mat.friction_angle](double x) { return x == 0.0 || (x >= phi && x < 89.0); }});
        if (mat.model == "subloading_cam_clay") {
            // No default: a sets how fast the overconsolidated soil reaches the normal surface.
            mat.subloading_a = m.number("subloading_a", positive("the subloading parameter a of G(rho) = a rho^2"));
            mat.critical_state_surface = m.choice_or("critical_state_surface", "matsuoka_nakai",
                                                     {"matsuoka_nakai", "drucker_prager"});
        }
    } else if (mat.model == "hypoplastic") {
        read_hypoplastic(m, mat);
    } else if (mat.model == "umat") {
        read_user_material(m, mat);
    } else if (mat.model == "hardening_soil_small") {
        mat.e50_ref = m.number("e50_ref", positive("secant triaxial stiffness E50 at p_ref in Pa"));
        mat.eoed_ref = m.number("eoed_ref", positive("oedometric stiffness at p_ref in Pa"));
        mat.eur_ref = m.number("eur_ref", {"an unloading-reloading stiffness in Pa above e50_ref",
                                           [e = mat.e50_ref](double x) { return x > e; }});
        mat.g0_ref = m.number("g0_ref", {"a small-strain shear modulus in Pa >= eur_ref / (2 (1 + poisson_ratio))",
                                         [e = mat.eur_ref, nu = mat.poisson_ratio](double x) { return x >= e / (2.0 * (1.0 + nu)); }});
        mat.gamma_07 = m.number("gamma_07", in_open_range(0.0, 0.1, "the shear strain where G = 0.722 G0"));
        mat.stiffness_exponent = m.number("stiffness_exponent", {"a power m from 0 to 1", [](double x) { return x >= 0 && x <= 1; }});
        mat.reference_pressure = m.number_or("reference_pressure", 100e3, positive("reference pressure in Pa"));
        mat.friction_angle = m.number("friction_angle", {"an angle above 0 and below 89 deg", [](double x) { return x > 0 && x < 89; }});
        mat.dilation_angle = m.number_or("dilation_angle", 0.0, {"an angle from 0 to the friction angle",
                                                                 [phi = mat.friction_angle](double x) { return x >= 0 && x <= phi; }});
        mat.cohesion = m.number_or("cohesion", 0.0, non_negative("cohesion in Pa"));
        mat.failure_ratio = m.number_or("failure_ratio", 0.9, in_open_range(0.0, 1.0, "R_f = q_f / q_a"));
        const double s = sin_deg(mat.friction_angle);
        mat.k0_nc = m.number_or("k0_nc", 1.0 - s, {"K0 of normal consolidation between (1 - sin phi) / (1 + sin phi) and 1",
                                                    [s](double x) { return x > (1.0 - s) / (1.0 + s) && x < 1.0; }});
        mat.ocr = m.number_or("ocr", 1.0, {"an overconsolidation ratio >= 1", [](double x) { return x >= 1.0; }});
        mat.min_pressure = m.number_or("min_pressure", 1e3, positive("stiffness floor in Pa"));
    } else {
        mat.youngs_modulus = m.number("youngs_modulus", positive("Young's modulus in Pa"));
    }
    if (mat.model == "mohr_coulomb") {
        mat.friction_angle = m.number("friction_angle", angle);
        mat.dilation_angle = m.number_or("dilation_angle", 0.0, {"an angle from 0 to the friction angle",
                                                                 [phi = mat.friction_angle](double x) { return x >= 0 && x <= phi; }});
        mat.cohesion = m.number_or("cohesion", 0.0, non_negative("cohesion in Pa"));
        mat.tension_cutoff = m.number_or("tension_cutoff", 0.0, non_negative("tensile strength in Pa"));
    }
    if (mat.model == "mu_i_rheology") read_mu_i(m, mat);
    mat.k0 = m.number_or("k0", -1.0, positive("earth pressure coefficient at rest"));
    if (with_density) read_pore_water(m, mat);
    m.finish();
    return mat;
}

}  // namespace pilempm::io
