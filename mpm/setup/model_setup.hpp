#pragma once
// Building an MPM model: material points filling regions of the grid, boundary conditions
// on grid planes, and the K0 initial stress of horizontally layered ground.
#include <functional>
#include <vector>

#include "mpm/grid/grid.hpp"
#include "mpm/points/particles.hpp"

namespace pilempm::mpm {

// Puts per_cell^D points in every cell whose sub-cell centres fall in `inside`.
// Mass = density x volume (volume per radian, area x r, when axisymmetric).
template <int D>
int fill_region(const Grid<D>& grid, Particles<D>& p, const std::function<bool(const double*)>& inside,
                int per_cell, double density, int material, bool axisymmetric);

enum class BoundaryKind { Fixed, Roller, Absorbing, Frictional };

// A boundary on the grid plane x_axis = min (side 0) or max (side 1). Fixed: all velocity
// components held; roller: the normal one. Absorbing (Lysmer-Kuhlemeyer): dashpots
// rho c_p on the normal and rho c_s on the tangential components, over each node's
// tributary face area (x r in axisymmetry). Frictional: a rigid wall the material cannot
// enter and slides on with Coulomb friction `friction` (it may lift off).
// Saturated soil: an absorbing boundary's pore-pressure dashpot water_impedance (Pa s/m,
// on the normal component of the water field) over the same areas; a drained boundary's
// supports hold the skeleton only, the water flows through.
// far_field_distance R > 0 (m): each absorbing node also gets springs of the far field's
// static stiffness over its area, 2 G / R normal (a cylindrical cavity's in an elastic
// medium) and G / R along the boundary, G = density c_s^2 (a Kelvin-Voigt boundary).
template <int D>
void apply_boundary(Grid<D>& grid, int axis, int side, BoundaryKind kind, double density = 0.0,
                    double p_wave_speed = 0.0, double shear_wave_speed = 0.0, bool axisymmetric = false,
                    double friction = 0.0, double water_impedance = 0.0, bool drained = false,
                    double far_field_distance = 0.0);

// K0 stress of horizontally layered ground whose surface is at elevation `surface`
// (vertical axis D-1): sigma_v = -g int rho dz from the surface down, sigma_h = K0 sigma_v,
// where density(z) and k0(z) give the layer at elevation z; `surcharge` (Pa, compression
// positive) adds to sigma_v everywhere (a calibration chamber's top pressure). Tension positive.
template <int D>
void apply_k0_stress(Particles<D>& p, double surface, double gravity, const std::function<double(double)>& density,
                     const std::function<double(double)>& k0, double surcharge = 0.0);

}  // namespace pilempm::mpm
