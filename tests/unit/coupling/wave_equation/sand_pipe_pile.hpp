#pragma once
// The drivability tests' common ground: a 30 m, 1.5 m x 25 mm steel pipe pile on 1 m rod
// elements in 40 m of dense sand (D_R 0.8, delta 28 deg), one best-estimate soil case
// (Alm & Hamre); each test adds its hammer and depths.
#include <cmath>

#include "coupling/wave_equation/drivability.hpp"
#include "fem/mesh/pile_geometry.hpp"
#include "fem/mesh/rod_mesh.hpp"

namespace pilempm::coupling {

inline DrivabilitySetup sand_pipe_pile() {
    DrivabilitySetup s;
    s.mesh = fem::mesh_rod(fem::make_pile_geometry({{30.0, 1.5, 0.025}}), 1.0);
    s.steel = {210e9, 0.3, 7850.0};
    s.outer_diameter = 1.5;
    s.wall_thickness = 0.025;
    s.pile_mass = 7850.0 * M_PI * (1.5 - 0.025) * 0.025 * 30.0;
    SoilLayer sand;
    sand.type = SoilType::Sand;
    sand.top = 0.0;
    sand.bottom = 40.0;
    sand.submerged_unit_weight = 10e3;
    sand.relative_density = 0.8;
    sand.interface_friction_angle = 28.0;
    s.soil.layers = {sand};
    s.cases = {{"best_estimate", SrdMethod::AlmHamre2001, 1.0}};
    return s;
}

}  // namespace pilempm::coupling
