#pragma once
// The conventions every library follows, in one place.
// - Units: SI throughout (m, s, kg, N, Pa); nothing is converted inside the code.
// - Signs: stress is tension-positive; pore-water pressure is compression-positive; total
//   stress = effective stress - p I. Reports name their sign in the column
//   (force_compression_N, velocity_down_m_s).
// - Axes: 2D axisymmetric x = r, y = z (up); plane strain x horizontal, y up; 3D z up. The
//   FE pile's own axis runs along its length (toe at z = 0, head at the top).
// - Voigt order [xx, yy, zz, xy, yz, zx] with engineering shear strain (voigt.hpp).
// - Per radian: axisymmetric MPM carries mass, volume and forces per radian of the ring;
//   FE axisymmetric elements integrate the full ring (2 pi r). Convert once, with these.
#include <numbers>

namespace pilempm {

inline constexpr double kRadiansPerRing = 2.0 * std::numbers::pi;

// A quantity of the whole ring (FE) from its value per radian (MPM), and back.
constexpr double full_ring(double per_radian) { return kRadiansPerRing * per_radian; }
constexpr double per_radian(double full_ring_value) { return full_ring_value / kRadiansPerRing; }

}  // namespace pilempm
