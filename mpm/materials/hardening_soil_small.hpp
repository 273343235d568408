#pragma once
// Hardening Soil with small-strain stiffness (HS-small: Schanz et al. 1999, Benz 2007),
// effective stresses. Voigt tension positive outside; inside, stresses are compression
// positive with principal values s1 >= s2 >= s3 and a = c cot(phi) (stresses shifted by a
// make the model homogeneous in stress).
//
//   stiffness   E = E_ref w^m, w = (c cos phi + s3 sin phi) / (c cos phi + p_ref sin phi)
//               = (s3 + a) / (p_ref + a), floored at (p_min) / (p_ref + a)
//   small strain G_t = G0 (g07 / (g07 + 0.385 g_hist))^2 >= G_ur = E_ur / (2 (1 + nu_ur)),
//               nu_ur constant (K follows G); g_hist = sqrt(3) |H de| / |de| from the
//               deviatoric strain history H (reset per principal direction on reversal).
//               g = (3/2) eps_q: eps_1 - eps_3 in triaxial, (sqrt 3 / 2) gamma_xy in simple shear.
//   shear       f_s = q - min(q_y(gamma_p, s3), q_f), q = s1 - s3, with q_y the hyperbola
//               (2 - R_f)/E50 q / (1 - q / q_a) - 2 q / E_ur = gamma_p, q_a = q_f / R_f and
//               q_f = 2 sin phi / (1 - sin phi) (s3 + a) (Mohr-Coulomb, perfectly plastic).
//               Flow: Mohr-Coulomb potential with the mobilised (Rowe) dilatancy psi_m,
//               0 <= psi_m <= psi, and psi_m = 0 below sin phi_m = 3/4 sin phi.
//   cap         f_c = sqrt(qt^2 / alpha^2 + p*^2) - p_p*, qt = s1 + (d - 1) s2 - d s3,
//               d = (3 + sin phi) / (3 - sin phi), p* = p + a; associated; hardening
//               d eps_v^pc = beta / p_ref* (p_p* / p_ref*)^-m dp_p*. alpha and beta are set in
//               closed form so that a K0nc oedometer at s1 = p_ref gives Eoed_ref and K0nc.
//
// Integration: explicit, error-controlled substepping (modified Euler, Sloan et al. 2001)
// with Pegasus for the elastic part, Koiter's rule where both surfaces are active, and
// drift correction. Principal corners (triaxial compression / extension) average the
// gradients of the coinciding principal stresses (Koiter's rule with equal multipliers).
// Near the Mohr-Coulomb apex, in tension, or if substepping fails, the stress is returned
// by the closed-form Mohr-Coulomb return (no tensile strength), so nothing becomes NaN.
#include <string>

#include "mpm/materials/constitutive_model.hpp"
#include "mpm/materials/mohr_coulomb.hpp"

namespace pilempm::mpm {

struct HardeningSoilSmallParameters {
    double E50_ref = 48e6;    // Pa: secant stiffness in drained triaxial at p_ref
    double Eoed_ref = 48e6;   // Pa: tangent oedometric stiffness at sigma'_1 = p_ref
    double Eur_ref = 144e6;   // Pa: unloading-reloading stiffness
    double nu_ur = 0.2;
    double G0_ref = 114.4e6;  // Pa: very-small-strain shear modulus
    double gamma_07 = 1.2e-4; // shear strain where G_s = 0.722 G0
    double m = 0.45;          // stress exponent
    double p_ref = 100e3;     // Pa
    double phi = 38.0;        // deg, > 0
    double c = 0.0;           // Pa
    double psi = 0.0;         // deg, 0 <= psi <= phi
    double R_f = 0.9;         // failure ratio q_f / q_a
    double K0_nc = -1.0;      // <= 0: 1 - sin(phi)
    double ocr = 1.0;         // p_p = OCR x the cap through the initial stress
    double p_min = 1e3;       // Pa: stiffness floor on s3 + a
    double tolerance = 1e-6;  // relative local error of a substep and yield tolerance
};

class HardeningSoilSmall final : public ConstitutiveModel {
public:
    explicit HardeningSoilSmall(const HardeningSoilSmallParameters& parameters);

    std::string name() const override { return "hardening_soil_small"; }
    // H (6, tensor shear) | gamma_p | p_p (Pa, compression +) | G_t / G0 after the last step
    int num_state() const override { return 9; }
    int num_tensor_state() const override { return 1; }
    const char* state_name(int k) const override;
    void initialise_state(const double* stress, double* state) const override;
    void update(int count, const int* points, const double* dstrain, double* stress, double* state,
                int stride) const override;
    double p_wave_modulus() const override;  // at p_ref, with G0
    double shear_modulus() const override { return par_.G0_ref; }
    double p_wave_modulus_at(const double* stress, const double* state) const override;

    const HardeningSoilSmallParameters& parameters() const { return par_; }
    double cap_alpha() const { return alpha_; }
    double cap_beta() const { return beta_; }
    // Shear yield value q - min(q_y, q_f) and cap value R - p_p (Pa) of a Voigt stress.
    double shear_yield(const double* stress, const double* state) const;
    double cap_yield(const double* stress, const double* state) const;
    // The triaxial-compression Mohr-Coulomb deviator at a confining stress (Pa, compression +).
    double failure_deviator(double sigma3) const { return kf_ * (sigma3 + a_); }
    // Normalised secant curve tau / G0 of the small-strain overlay (with the G_ur floor).
    double secant_stress_ratio(double gamma) const;

private:
    struct Point {
        double t[6];  // stress, compression positive, tensor shear
        double gp;    // gamma_p
        double pp;    // p_p* = p_p + a
    };
    struct Principal;
    struct Surfaces;
    // Principal stresses and directions of t; hint: the decomposition of a nearby stress
    // (the same increment), used as the starting frame of the iteration.
    Principal principal(const double* t, const Principal* hint = nullptr) const;
    double stiffness_factor(double s3) const;  // w^m
    double stiffness_factor(double s3, const Principal& near) const;  // the same from near's
    double minor_principal(const double* t, const Principal& near) const;  // s3 of t
    void elastic_moduli(const Principal& pr, double ratio, double& lam, double& G) const;
    // out = in + the elastic step over de; pr_in: the decomposition of in.
    void elastic_step(const Point& in, const Principal& pr_in, const double* de, double ratio, Point& out) const;
    Surfaces surfaces(const Point& pt, const Principal& pr, bool with_gradients) const;
    double yield_max(const Point& pt, const Surfaces& S) const;  // max of f_s / scale and f_c / p_p
    bool plastic_rate(const Point& pt, const Principal& pr, const Surfaces& S, const double* Dde, double ratio,
                      double* ds, double& dgp, double& dpp, int& candidates) const;
    // pr: the decomposition of pt, kept current. S (with gradients) is left as the surfaces
    // of the returned pt when S_current is set.
    void correct_drift(Point& pt, Principal& pr, double ratio, Surfaces& S, bool& S_current) const;
    // false: leave to the fallback. pr: on true, the decomposition of the returned pt.
    bool integrate(Point& pt, const double* de, double ratio, Principal& pr) const;
    void fallback(Point& pt, const double* de, double ratio) const;
    double history_ratio(double* H, const double* dstrain, double& tangent_ratio) const;
    // derivatives false: q_y alone (dq_dg, dq_ds are then not for use).
    double qy(double gp, double s, double wm, double& dq_dg, double& dq_ds, bool& on_mc,
              bool derivatives = true) const;
    double cap_modulus(const Point& pt, const Surfaces& S) const;
    double gamma_of(double q, double s) const;  // gamma_p where q_y(gamma_p, s) = min(q, q_f)
    double cap_radius(const Principal& pr) const;

    HardeningSoilSmallParameters par_;
    double sin_phi_, sin_psi_, sin_cv_, a_, kf_, delta_, K0nc_;
    double pref_s_;        // p_ref + a
    double Gur_over_G0_;   // floor of the small-strain ratio
    double gamma_c_;       // where the tangent reaches G_ur
    double lam_over_G_;    // Lame lambda / G from nu_ur
    double alpha_, beta_;
    MohrCoulomb failure_;  // closed-form return near the apex and in tension
};

}  // namespace pilempm::mpm
