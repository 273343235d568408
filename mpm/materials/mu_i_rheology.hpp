#pragma once
// Elasto-viscoplastic granular flow with the mu(I) rheology (Jop, Forterre & Pouliquen
// 2006), in the Drucker-Prager form of Dunatunga & Kamrin (2015). Tension positive.
//
//   yield      tau <= mu(I) p,   tau = sqrt(s:s / 2),  p = -tr(sigma) / 3
//   friction   mu(I) = mu_s + (mu_2 - mu_s) / (I_0 / I + 1),  I = gdot_p d / sqrt(p / rho_s)
//   flow       isochoric, along s (no dilatancy): p is unchanged by plastic flow
//
// gdot_p is the equivalent plastic shear rate sqrt(2 D_p':D_p'), which is the shear rate
// itself in simple shear. A point whose elastic trial pressure is not compressive is
// disconnected: its grains have separated and it carries no stress. The grain diameter d
// is the rheology's length scale: it makes the friction of a thin, fast shear layer
// higher than that of a slow one, which a rate-independent Mohr-Coulomb cannot do.
#include <string>

#include "mpm/materials/constitutive_model.hpp"

namespace pilempm::mpm {

struct MuIParameters {
    double youngs_modulus = 5e6, poisson_ratio = 0.3;
    // Glass beads, d = 0.5 mm (Jop et al. 2006): tan 20.9 deg, tan 32.76 deg, 0.279.
    double mu_s = 0.382, mu_2 = 0.643, I_0 = 0.279;
    double grain_diameter = 0.5e-3;  // m
    double grain_density = 2450.0;   // kg/m^3, of the solid grains (not of the packing)
};

class MuIRheology final : public ConstitutiveModel {
public:
    explicit MuIRheology(const MuIParameters& p);

    std::string name() const override { return "mu_i_rheology"; }
    int num_state() const override { return 2; }
    const char* state_name(int k) const override;
    void update(int count, const int* points, const double* dstrain, double* stress, double* state,
                int stride) const override;
    // The plastic rate is the plastic strain increment over this step; without a step
    // (dt <= 0) the flow is quasi-static and the friction is mu_s.
    void set_time(double /*time*/, double dt) override { dt_ = dt; }
    double p_wave_modulus() const override { return lambda_ + 2.0 * mu_; }
    double shear_modulus() const override { return mu_; }

    // mu(I) and the inverse of I -> mu(I) on (mu_s, mu_2); for checks and output.
    double friction(double inertial_number) const;
    double inertial_number(double shear_rate, double pressure) const;

private:
    // The plastic shear strain increment dg that brings the trial shear stress tau_trial
    // at pressure p onto tau = mu(dg / dt) p; closed form (a quadratic in dg).
    double plastic_shear_increment(double tau_trial, double p) const;

    MuIParameters par_;
    double lambda_, mu_;
    double dt_ = 0.0;
};

}  // namespace pilempm::mpm
