#pragma once
// Builds the constitutive model a material's parameters name, and the quantities of the
// initial state that depend on the model (K0, whether a void ratio is carried).
#include <memory>

#include "mpm/materials/constitutive_model.hpp"
#include "mpm/materials/material_parameters.hpp"

namespace pilempm::mpm {

std::unique_ptr<ConstitutiveModel> make_constitutive_model(const MaterialParameters& m);
// K0 of the initial stress: the given k0, else K0nc (HS small), 1 - sin(phi) (frictional
// models) or nu / (1 - nu) (elastic).
double k0_of(const MaterialParameters& m);
// Whether the model carries the void ratio as a state variable named "void_ratio".
bool has_void_ratio(const MaterialParameters& m);

}  // namespace pilempm::mpm
