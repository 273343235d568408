#pragma once
// The constitutive interface of the MPM soil: a model maps (stress, state, strain
// increment) to (stress, state) for a batch of material points, one virtual call per
// material per step. The caller has already rotated the stress (Jaumann), so models are
// pure small-increment updates. Voigt order and signs: voigt.hpp.
#include <memory>
#include <string>

#include "core/voigt.hpp"

namespace pilempm::mpm {

class ConstitutiveModel {
public:
    virtual ~ConstitutiveModel() = default;
    virtual std::string name() const = 0;
    virtual int num_state() const { return 0; }
    // How many symmetric tensors (6 components each, xx yy zz xy yz zx, tensor shear) open
    // the state array; the solver rotates them with the stress (e.g. intergranular strain).
    virtual int num_tensor_state() const { return 0; }
    virtual const char* state_name(int /*k*/) const { return ""; }
    // Sets the state of one point given its initial stress (e.g. after K0 initialisation).
    virtual void initialise_state(const double* /*stress*/, double* /*state*/) const {}
    // Updates `count` points whose indices are `points`; point p owns dstrain[6p..6p+5],
    // stress[6p..6p+5] and state[stride p .. stride p + num_state - 1].
    virtual void update(int count, const int* points, const double* dstrain, double* stress,
                        double* state, int stride) const = 0;
    // The time at the start of the coming update and its step, s, for rate-dependent models
    // (user materials are told both); the solver calls it before each update.
    virtual void set_time(double /*time*/, double /*dt*/) {}
    // Constrained (P-wave) modulus K + 4G/3 and shear modulus, Pa, for the stable time step
    // and the absorbing boundaries (the largest tangent stiffness the model can show).
    virtual double p_wave_modulus() const = 0;
    virtual double shear_modulus() const = 0;
    // The P-wave modulus at one point's stress and state, for models whose stiffness grows
    // with pressure (the stable time step is taken point by point).
    virtual double p_wave_modulus_at(const double* /*stress*/, const double* /*state*/) const {
        return p_wave_modulus();
    }
};

// The index of a model's state named "void_ratio" (-1: it keeps none). A saturated point's
// porosity is the one owner of its void ratio: the solvers set this state from it each step.
inline int void_ratio_state(const ConstitutiveModel& m) {
    for (int k = 0; k < m.num_state(); ++k)
        if (std::string(m.state_name(k)) == "void_ratio") return k;
    return -1;
}

// Isotropic linear elasticity.
class LinearElastic final : public ConstitutiveModel {
public:
    LinearElastic(double youngs_modulus, double poisson_ratio);
    std::string name() const override { return "linear_elastic"; }
    void update(int count, const int* points, const double* dstrain, double* stress, double* state,
                int stride) const override;
    double p_wave_modulus() const override { return lambda_ + 2.0 * mu_; }
    double shear_modulus() const override { return mu_; }
    double lambda() const { return lambda_; }

private:
    double lambda_, mu_;
};

}  // namespace pilempm::mpm
