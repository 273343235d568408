#pragma once
// Modified Cam Clay (Roscoe & Burland 1968), effective stresses, tension positive inside
// (p = -tr(sigma)/3 is compression positive here, as in soil mechanics).
//
//   yield      f = q^2 / M^2 + p (p - p_c) = 0            (associated flow)
//   elasticity K = v p / kappa, G = 3 K (1 - 2 nu) / (2 (1 + nu)), v = 1 + e
//   hardening  dp_c / p_c = v / (lambda - kappa) d(eps_v^p, compression positive)
//
// The update is explicit with error-controlled substepping (Sloan et al. 2001): the
// elastic part of the increment is found on the yield surface (Pegasus), the plastic part
// is integrated by modified Euler with a local error tolerance and each substep is pulled
// back onto the surface (drift correction). Below p_min the stiffness is that at p_min, so
// a point at zero stress stays finite.
#include <string>

#include "mpm/materials/constitutive_model.hpp"
#include "mpm/materials/friction_cone.hpp"

namespace pilempm::mpm {

struct CamClayParameters {
    double lambda = 0.15;        // slope of the NCL in v - ln p'
    double kappa = 0.013;        // slope of an unloading line
    double M = 1.2;              // critical state stress ratio q / p'
    double poisson_ratio = 0.3;
    double void_ratio = 0.62;    // initial e (for points set up from stress)
    double ocr = 1.0;            // isotropic overconsolidation ratio p_c / p_y at set-up
    double p_min = 1.0e3;        // Pa: stiffness floor and least p_c
    double tolerance = 1e-6;     // relative local error of a substep (and |f| / p_c^2)
    // deg: the Matsuoka-Nakai cone that bounds the stress (no tension on the dry side, as
    // subloading Cam clay's); 0: none.
    double peak_friction_angle = 0.0;
};

class ModifiedCamClay final : public ConstitutiveModel {
public:
    explicit ModifiedCamClay(const CamClayParameters& parameters);

    std::string name() const override { return "modified_cam_clay"; }
    int num_state() const override { return 2; }
    const char* state_name(int k) const override { return k == 0 ? "preconsolidation_pressure" : "void_ratio"; }
    // p_c = OCR x the p' where the yield surface through the stress cuts the p' axis.
    void initialise_state(const double* stress, double* state) const override;
    void update(int count, const int* points, const double* dstrain, double* stress, double* state,
                int stride) const override;
    double p_wave_modulus() const override;  // at p_ref (absorbing boundaries)
    double shear_modulus() const override;
    double p_wave_modulus_at(const double* stress, const double* state) const override;

    double yield_function(const double* stress, double pc) const;
    const CamClayParameters& parameters() const { return par_; }

private:
    struct Point {
        double s[6];
        double pc, v;
    };
    struct Gradient;
    Gradient gradient(const Point& pt) const;
    void update_point(const double* de, Point& pt) const;
    void elastic_step(const Point& in, const double* de, Point& out) const;
    // Elasto-plastic tangent increment of stress and p_c for the strain increment de.
    void plastic_rate(const Point& pt, const double* de, double* ds, double& dpc) const;
    void correct_drift(Point& pt) const;
    double f(const Point& pt) const { return yield_function(pt.s, pt.pc); }
    double bulk(double p, double v) const;

    CamClayParameters par_;
    FrictionCone peak_;  // the cone bounding the stress, if any
    double g_over_k_;     // G / K from Poisson's ratio
    static constexpr double p_ref_ = 100e3;  // Pa: where p_wave_modulus() is stated
};

}  // namespace pilempm::mpm
