#pragma once
// Linear elastic, perfectly plastic Mohr-Coulomb with non-associated flow (dilation angle
// psi) and a Rankine tension cut-off on each principal stress. Tension positive.
//
// With sorted principal stresses s1 >= s2 >= s3 (s1 the most tensile) the criteria are
//   Mohr-Coulomb  f = (1 + sin phi) s1 - (1 - sin phi) s3 - 2 c cos phi <= 0
//   tension       s_i - t <= 0
// and the plastic potential is f with psi in place of phi (tension planes: associated).
// The stress update is a closed-form multi-surface return in principal stress space:
// see mohr_coulomb.cpp for the regions and how the active one is chosen.
#include <array>
#include <initializer_list>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "mpm/materials/constitutive_model.hpp"

namespace pilempm::mpm {

class MohrCoulomb final : public ConstitutiveModel {
public:
    // Angles in degrees, 0 <= psi <= phi < 90; c >= 0 (c > 0 when phi = 0: Tresca).
    // tension_cutoff: largest allowed principal stress, Pa (may be +infinity); clamped to
    // c / tan(phi) when phi > 0, where it is the apex of the Mohr-Coulomb cone.
    MohrCoulomb(double youngs_modulus, double poisson_ratio, double friction_angle_deg,
                double dilation_angle_deg, double cohesion, double tension_cutoff);

    std::string name() const override { return "mohr_coulomb"; }
    int num_state() const override { return 1; }
    const char* state_name(int k) const override { return k == 0 ? "plastic_strain" : ""; }
    void initialise_state(const double* stress, double* state) const override;
    void update(int count, const int* points, const double* dstrain, double* stress, double* state,
                int stride) const override;
    double p_wave_modulus() const override { return lambda_ + 2.0 * mu_; }
    double shear_modulus() const override { return mu_; }

    // The tension cut-off after clamping to the apex, Pa (+infinity: none, Tresca only).
    double tension_cutoff() const { return t_; }
    // max(Mohr-Coulomb f, largest principal stress - cut-off) of a Voigt stress, Pa:
    // <= 0 on or inside the elastic domain.
    double yield_function(const double* stress) const;

private:
    // One principal-space face, edge or corner of the elastic domain (1 to 3 planes),
    // with what the return onto it needs, all constant for the material.
    struct ActiveSet {
        int n = 0;                                       // number of active planes
        std::array<int, 3> planes{};                     // indices into the plane table
        std::array<std::array<double, 3>, 3> inverse{};  // (a_i . D b_j)^-1, n x n
        std::array<double, 3> vertex{};                  // the corner stress when n == 3
    };
    static constexpr int kPlanes = 6;  // MC: s1-s3, s2-s3, s1-s2; tension: s1, s2, s3
    using Vec3 = std::array<double, 3>;
    void build_active_sets();
    void add_active_set(std::initializer_list<int> planes);
    bool clearly_elastic(const Eigen::Matrix3d& m) const;
    void plastic_corrector(const Eigen::Matrix3d& m, double* voigt, double& eps_p) const;
    void principal_return(const Vec3& trial, Vec3& out) const;
    double return_to_set(const ActiveSet& set, const Vec3& trial, Vec3& out,
                         double& min_multiplier) const;
    void radial_fallback(const Vec3& trial, Vec3& out) const;
    double principal_yield(const Vec3& s) const;
    double energy_distance(const Vec3& trial, const Vec3& out) const;
    Vec3 plastic_strain(const Vec3& stress_drop) const;
    double plastic_strain_increment(const Vec3& trial, const Vec3& out) const;

    double E_, nu_, lambda_, mu_;
    double sin_phi_, cos_phi_, sin_psi_;
    double t_;            // tension cut-off clamped to the apex (+inf possible for Tresca)
    bool tension_;        // whether the cut-off planes cut the cone (t below the apex)
    double apex_;         // c cot(phi) (+inf for Tresca)
    std::array<std::array<double, 3>, kPlanes> a_{}, Db_{};  // normals and D * flow dirs
    std::array<double, kPlanes> k_{};                        // f_i = a_i . s - k_i
    std::vector<ActiveSet> sets_;  // tried in order; the first consistent one is taken
};

}  // namespace pilempm::mpm
