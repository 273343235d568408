#pragma once
// A user material with the Abaqus UMAT interface, loaded from a shared library at run
// time, so a published soil UMAT can be used without changing pilempm.
//
// pilempm calls it as Abaqus/Standard would for a 3D continuum point (NDI = 3, NSHR = 3,
// NTENS = 6, component order 11 22 33 12 13 23, engineering shear strains, tension
// positive). The stress given to the UMAT has already been rotated objectively, so DROT
// is the identity; tensor state variables the UMAT keeps in STATEV are not rotated.
// STRAN is the strain summed over the point's increments (kept in the state array after
// the STATEV). A UMAT that returns PNEWDT < 1 gets the increment again in halves, up to
// 2^10 pieces. Its stiffness for the stable time step and absorbing boundaries is what
// the case states (p_wave_modulus, shear_modulus).
#include <mutex>
#include <string>
#include <vector>

#include "mpm/materials/constitutive_model.hpp"

namespace pilempm::mpm {

struct UserMaterialParameters {
    std::string library;            // path of the shared library
    std::string symbol;             // empty: try umat_, umat, UMAT
    std::string name = "UMAT";      // CMNAME
    std::vector<double> properties;  // PROPS
    int state_variables = 0;         // NSTATV
    std::vector<double> initial_state;  // STATEV at set-up (the rest zero)
    double p_wave_modulus = 0.0, shear_modulus = 0.0;  // Pa
    bool thread_safe = true;         // false: one call at a time
};

class UserMaterial final : public ConstitutiveModel {
public:
    // Throws std::runtime_error naming the library or symbol that cannot be loaded.
    explicit UserMaterial(const UserMaterialParameters& parameters);
    ~UserMaterial() override;
    UserMaterial(const UserMaterial&) = delete;
    UserMaterial& operator=(const UserMaterial&) = delete;

    std::string name() const override { return "umat"; }
    int num_state() const override { return nstatv_ + 6; }
    const char* state_name(int k) const override { return names_[k].c_str(); }
    void initialise_state(const double* stress, double* state) const override;
    void update(int count, const int* points, const double* dstrain, double* stress, double* state,
                int stride) const override;
    void set_time(double time, double dt) override {
        time_ = time;
        dt_ = dt;
    }
    double p_wave_modulus() const override { return par_.p_wave_modulus; }
    double shear_modulus() const override { return par_.shear_modulus; }

    using Function = void (*)(double*, double*, double*, double*, double*, double*, double*, double*, double*,
                              double*, double*, double*, double*, double*, double*, double*, double*, double*,
                              char*, int*, int*, int*, int*, double*, int*, double*, double*, double*, double*,
                              double*, double*, int*, int*, int*, int*, int*, int*, std::size_t);

private:
    // One call; false when the UMAT asked for a smaller increment.
    bool call(int point, const double* dstran_abaqus, double* stress_abaqus, double* statev, double* stran) const;
    void update_point(int point, const double* dstrain, double* stress, double* state) const;

    UserMaterialParameters par_;
    void* handle_ = nullptr;
    Function umat_ = nullptr;
    int nstatv_;
    std::vector<std::string> names_;
    double time_ = 0.0, dt_ = 1.0;
    mutable std::mutex serial_;
};

}  // namespace pilempm::mpm
