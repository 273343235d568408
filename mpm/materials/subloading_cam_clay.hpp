#pragma once
// Subloading Cam clay (SubCam: Hashiguchi & Ueno 1977; Nakai & Hinokio 2004; Pedroso,
// Farias & Nakai 2005), effective stresses, p' and q compression positive inside.
//
// Normal yield surface: the modified Cam clay ellipse with a Lode-dependent critical state
// ratio M(theta),  f = q^2 / M(theta)^2 + p (p - p_c) = 0.  The stress always lies on the
// similar subloading surface of size p_s = p + q^2 / (M^2 p) <= p_c, measured by
//   rho = (lambda - kappa) ln(p_c / p_s)  (>= 0; the void-ratio distance to the NCL, Nakai).
// Associated flow on the subloading surface, deps^p = dl df/dsigma. Evolution:
//   dp_c / p_c = v / (lambda - kappa) deps_v^p            (as modified Cam clay)
//   drho       = -v G(rho) p_s dl,  G(rho) = a rho^2  (Nakai & Hinokio 2004; p_s dl =
//                deps_v^p under isotropic stress, so drho = -v a rho^2 deps_v^p there)
// Consistency on the subloading surface gives the multiplier
//   dl = n : De de / (n : De n + p dp_s/dl),
//   dp_s/dl = p_s v / (lambda - kappa) [(2p - p_s) + G(rho) p_s],
// i.e. the MCC hardening modulus augmented by G(rho): plastic strain starts at once on any
// loading, and rho -> 0 (back to modified Cam clay on the normal surface) as it goes on.
//
// Critical state surface: Matsuoka-Nakai, I1 I2 / I3 = (9 - sin^2 phi) / (1 - sin^2 phi),
// written as M(theta) in ordinary stress space (the cubic in eta = q / p' for cos 3theta,
// solved by Newton's method), so that with M constant (drucker_prager) the model is exactly
// modified Cam clay at rho = 0; M(compression) = 6 sin phi / (3 - sin phi), M(extension) =
// 6 sin phi / (3 + sin phi).
//
// Failure surface: the subloading surface passes through the origin, so on the dry side an
// unloading (elastic) path leaves the Matsuoka-Nakai cone and reaches tension (a drained
// extension from OCR 4 peaks at |q| / p' = 2.0 against M_e = 0.96, its axial stress tensile;
// beside a jacked pile a cohesionless sand stood off the steel on hoop stress alone). The stress
// is therefore bounded by the Matsuoka-Nakai cone of peak_friction_angle (no tension): a
// stress the Cam clay step leaves outside it goes back to it at constant p' and Lode angle,
// the return of an isochoric plastic potential g = q (zero dilatancy on the cone), p_c
// unchanged, the plastic strain counted. peak_friction_angle 0: no bound (the model as
// published).
//
// Integration as ModifiedCamClay: explicit modified Euler with error-controlled substeps
// (Sloan et al. 2001) and drift correction onto the subloading surface; an unloading
// increment is elastic (hypoelastic, exact kappa line) and the subloading surface shrinks to
// the new stress. Below p_min the stiffness is that at p_min; no NaN at zero stress.
#include <cmath>
#include <string>

#include "mpm/materials/constitutive_model.hpp"
#include "mpm/materials/friction_cone.hpp"

namespace pilempm::mpm {

enum class CriticalStateSurface { MatsuokaNakai, DruckerPrager };

struct SubloadingCamClayParameters {
    double lambda = 0.15;          // slope of the NCL in v - ln p'
    double kappa = 0.013;          // slope of an unloading line
    double friction_angle = 35.0;  // deg, at critical state (M in triaxial compression from it)
    CriticalStateSurface surface = CriticalStateSurface::MatsuokaNakai;
    double poisson_ratio = 0.3;
    double void_ratio = 0.62;      // initial e (for points set up from stress)
    double ocr = 1.0;              // p_c / p_s at set-up (1: on the normal surface, rho = 0)
    double a = 2000.0;             // subloading parameter of G(rho) = a rho^2
    double peak_friction_angle = 0.0;  // deg, the bounding cone (>= friction_angle); 0: none
    double p_min = 1.0e3;          // Pa: stiffness floor and least p_c
    double tolerance = 1e-6;       // relative local error of a substep (and |f| / p_s^2)
};

class SubloadingCamClay final : public ConstitutiveModel {
public:
    explicit SubloadingCamClay(const SubloadingCamClayParameters& parameters);

    std::string name() const override { return "subloading_cam_clay"; }
    int num_state() const override { return 4; }
    // p_c, e, rho and the accumulated plastic strain (integral of |deps^p|, tensor norm).
    const char* state_name(int k) const override;
    // p_c = OCR x the size p_s of the surface through the stress; rho = (lambda - kappa) ln OCR.
    void initialise_state(const double* stress, double* state) const override;
    void update(int count, const int* points, const double* dstrain, double* stress, double* state,
                int stride) const override;
    double p_wave_modulus() const override;  // at p_ref (absorbing boundaries)
    double shear_modulus() const override;
    double p_wave_modulus_at(const double* stress, const double* state) const override;

    // Critical state ratio q / p' at the Lode angle of `stress` (any M at q = 0), and at
    // cos 3theta (1: triaxial compression, -1: extension).
    double critical_state_ratio(const double* stress) const;
    double critical_state_ratio_at(double cos3theta) const;
    // p_s of the surface similar to the normal one through the stress (0 at p' <= 0).
    double subloading_size(const double* stress) const;
    // The subloading surface function q^2 / M^2 + p (p - p_c exp(-rho / (lambda - kappa))).
    double yield_function(const double* stress, double pc, double rho) const;
    // df/dsigma of the subloading surface at (stress, state), engineering form (shear x 2).
    void flow_direction(const double* stress, const double* state, double* n) const;
    const SubloadingCamClayParameters& parameters() const { return par_; }

private:
    struct Point {
        double s[6];
        double pc, rho, v, eps_p;
    };
    struct Gradient;
    struct Lode;
    Lode lode(const double* s, double p, double q) const;
    Gradient gradient(const Point& pt) const;
    double ps_of(const Point& pt) const;  // p_c exp(-rho / (lambda - kappa))
    double rho_of_stress(const double* s, double pc) const;
    // rho < 0 (a hair outside the normal surface) is drift, corrected onto it: G = 0 there, so
    // the hardening modulus never falls below modified Cam clay's.
    double G_of(double rho) const { return rho > 0.0 ? par_.a * rho * rho : 0.0; }
    double f(const Point& pt) const { return yield_function(pt.s, pt.pc, pt.rho); }
    double drift_tolerance(const Point& pt) const;
    void update_point(const double* de, Point& pt) const;
    // Elasto-plastic tangent increments of stress, p_c, rho, accumulated plastic strain.
    double plastic_rate(const Point& pt, const double* de, double* ds, double& dpc, double& drho, double& deps) const;
    void correct_drift(Point& pt) const;
    void bound_by_peak_cone(Point& pt) const;
    double bulk(double p, double v) const;

    SubloadingCamClayParameters par_;
    double g_over_k_;               // G / K from Poisson's ratio
    double M_c_, k_mn_;             // M in compression; Matsuoka-Nakai I1 I2 / I3
    FrictionCone critical_, peak_;  // the critical state cone; the bounding one (if any)
    double p_floor_;                // least p_s for rho (zero stress gives a finite rho)
    static constexpr double p_ref_ = 100e3;  // Pa: where p_wave_modulus() is stated
};

}  // namespace pilempm::mpm
