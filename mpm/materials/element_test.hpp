#pragma once
// A single material point driven along a laboratory path: the triaxial cell (axial
// direction z = Voigt 2, lateral x and y kept equal), the oedometer and isotropic
// compression. Each direction is strain- or stress-controlled; the strains of the
// stress-controlled directions are found each step by Newton's method on the model itself
// (finite-difference tangent), so any model behind ConstitutiveModel can be tested.
// Signs: soil mechanics (compression positive) in the recorded path.
#include <string>
#include <vector>

#include "mpm/materials/constitutive_model.hpp"
#include "mpm/materials/material_parameters.hpp"

namespace pilempm::mpm {

struct ElementLeg {
    // Axial strain, axial stress or deviator q = sigma_a - sigma_r (Pa) as the axial target.
    enum Control { AxialStrain, AxialStress, Deviator };
    enum Lateral { LateralStress, LateralStrainZero, Undrained, LateralStressEqualsAxial };
    Control axial = AxialStrain;
    Lateral lateral = LateralStress;
    double axial_target = 0.0;  // strain, or stress / deviator (Pa), compression +, at the end
    int steps = 100;
};

struct ElementRecord {
    double axial_strain, volumetric_strain;     // compression positive
    double axial_stress, lateral_stress;        // effective, Pa, compression positive
    double p, q;                                // p' and q = sigma'_a - sigma'_r (Pa)
    std::vector<double> state;
};

// One laboratory test: a path of legs from the initial state.
struct ElementTestDefinition {
    std::string name, type;  // triaxial_drained | triaxial_undrained | oedometer | isotropic
    std::vector<ElementLeg> legs;
    double void_ratio = -1.0;  // > 0: start from this e instead of the material's
};

// A material and the tests run on it from one initial effective stress.
struct ElementTestSetup {
    MaterialParameters material;
    double axial_stress = 0.0, lateral_stress = 0.0;  // initial, effective, Pa, compression +
    std::vector<ElementTestDefinition> tests;
};

class ElementTest {
public:
    // stress0: initial effective stress, Voigt, tension positive (the code's convention).
    ElementTest(const ConstitutiveModel& model, const double* stress0, const std::vector<double>& state0);
    // Runs one leg from where the last ended; appends one record per step.
    void run(const ElementLeg& leg, std::vector<ElementRecord>& out);
    ElementRecord record() const;

private:
    void step(const double* de, double* stress, std::vector<double>& state) const;
    const ConstitutiveModel& model_;
    double stress_[6];
    double strain_[6] = {0, 0, 0, 0, 0, 0};  // tension positive, accumulated
    std::vector<double> state_;
};

}  // namespace pilempm::mpm
