#pragma once
// Hypoplasticity for sand after von Wolffersdorff (1996), optionally with the intergranular
// strain of Niemunis & Herle (1997). Stress T tension positive (as everywhere in the code),
// shifted by p_t so that a cohesionless point keeps a little strength at zero stress:
//
//   T_s = T - p_t 1,  T^ = T_s / tr T_s,  T^* = T^ - 1/3
//   dT = f_b f_e / tr(T^^2) [F^2 D + a^2 T^ (T^:D)] + f_b f_e f_d / tr(T^^2) a F (T^ + T^*) |D|
//      = L:D + N |D|
//   e_i, e_c, e_d = e_i0, e_c0, e_d0 x exp(-(3 p_s / h_s)^n);  de = (1 + e) tr D
//
// With the intergranular strain delta (rho = |delta| / R_max) the stiffness after a reversal
// is m_R L, after a 90 degree turn m_T L, and it fades back to L + N |D| as delta builds up.
// Integration: modified Euler with local error control on each strain increment (as in
// Fellin & Ostermann 2002 for explicit hypoplastic updates). A point whose shifted mean
// stress would drop below p_min is put back on the isotropic state p_s = p_min, so a point
// at zero stress keeps a finite, tiny stiffness and never divides by zero.
#include <string>

#include "mpm/materials/constitutive_model.hpp"

namespace pilempm::mpm {

struct HypoplasticParameters {
    double phi_c = 33.0;      // critical friction angle, degrees
    double h_s = 1600e6;      // granular hardness, Pa
    double n = 0.19;          // exponent of the compression law
    double e_d0 = 0.44, e_c0 = 0.85, e_i0 = 1.00;  // minimum, critical, maximum void ratio at p = 0
    double alpha = 0.25, beta = 1.0;                // pycnotropy exponents
    double p_t = 1e3;         // Pa: shift of the stress (tensile strength, regularisation)
    double void_ratio = 0.645;  // initial e (for points set up from stress)
    // Intergranular strain (off when intergranular_strain is false).
    bool intergranular_strain = true;
    double m_T = 2.0, m_R = 5.0, R_max = 1e-4, beta_r = 0.5, chi = 6.0;
    // Set-up: delta = 0 (a fresh deposit: the reversal stiffness everywhere) or fully
    // mobilised along the initial stress (a state reached by proportional compression).
    bool delta_along_stress = false;
    double p_min = 1.0;       // Pa: least shifted mean stress
    double tolerance = 1e-5;  // relative local error of a substep
};

class Hypoplastic final : public ConstitutiveModel {
public:
    explicit Hypoplastic(const HypoplasticParameters& parameters);

    std::string name() const override { return "hypoplastic"; }
    // State: [delta (6, tensor shear) if intergranular strain] then void ratio.
    int num_state() const override { return igs_ ? 7 : 1; }
    int num_tensor_state() const override { return igs_ ? 1 : 0; }
    const char* state_name(int k) const override;
    // e = void_ratio; delta = 0 or R_max along the stress (delta_along_stress).
    void initialise_state(const double* stress, double* state) const override;
    void update(int count, const int* points, const double* dstrain, double* stress, double* state,
                int stride) const override;
    double p_wave_modulus() const override;  // at p_ref and e0 (absorbing boundaries)
    double shear_modulus() const override;
    double p_wave_modulus_at(const double* stress, const double* state) const override;

    // Characteristic void ratios at mean effective stress p (Pa, compression positive).
    double e_i(double p) const;
    double e_c(double p) const;
    double e_d(double p) const;
    const HypoplasticParameters& parameters() const { return par_; }

    struct Point {
        double T[6];      // stress, tension positive, tensor shear (Voigt order)
        double delta[6];  // intergranular strain, tensor shear
        double e;
    };
    // Rate of the stress and the intergranular strain for the strain increment d (tensor
    // shear), at the point's state: the model's constitutive equation, exposed for tests.
    void rate(const Point& pt, const double* d, double* dT, double* ddelta) const;

private:
    struct Stiffness;
    Stiffness stiffness(const Point& pt) const;
    void update_point(const double* d, Point& pt) const;
    void keep_compressive(Point& pt) const;
    double isotropic_p_wave(double p, double e) const;

    HypoplasticParameters par_;
    bool igs_;
    double a_, fb_factor_;  // a(phi_c); the e-independent factor of f_b
    static constexpr double p_ref_ = 100e3;  // Pa: where p_wave_modulus() is stated
};

}  // namespace pilempm::mpm
