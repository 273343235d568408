#pragma once
// A soil material as read from a case file (MPM cases and element tests share it); the
// model is built from it by mpm::make_constitutive_model.
#include <memory>
#include <string>

#include "io/yaml/yaml_reader.hpp"
#include "mpm/materials/material_factory.hpp"

namespace pilempm::io {

using MaterialInput = mpm::MaterialParameters;

// with_density: MPM materials need one; an element test does not.
MaterialInput read_material(MapReader m, bool with_density);

}  // namespace pilempm::io
