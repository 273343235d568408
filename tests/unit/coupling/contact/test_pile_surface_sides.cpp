#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "coupling/contact/pile_surface.hpp"
#include "fem/mesh/axisymmetric_mesher.hpp"
#include "fem/mesh/conical_toe.hpp"

namespace pilempm::coupling {
namespace {

// Length of the surface on each side, from the segments' ends.
std::array<double, 5> length_by_side(const ContactSurface& s) {
    std::array<double, 5> by{};
    for (int k = 0; k < s.num_segments(); ++k)
        by[static_cast<int>(s.side[k])] += std::hypot(s.x[2 * s.b[k]] - s.x[2 * s.a[k]], s.x[2 * s.b[k] + 1] - s.x[2 * s.a[k] + 1]);
    return by;
}

// A solid pile, L = 3 m, R = 0.4 m: flat, its toe is the disc's radius; with a 60 degree
// cone, the cone's slant R / sin 30 and the shaft above the shoulder, L - R / tan 30.
TEST(PileSurface, AConesFaceIsTheToeAndTheShaftStartsAtItsShoulder) {
    const double L = 3.0, R = 0.4;
    fem::PileGeometry g;
    g.stations = {{0.0, 0.0, R}, {L, 0.0, R}};
    fem::PileMesh mesh = fem::mesh_axisymmetric_wall(g, 0.1, 3, std::string(PILEMPM_SOURCE_DIR) + "/meshes/pile_wall_axisymmetric.geo");
    auto flat = length_by_side(pile_contact_surface(mesh));
    EXPECT_NEAR(flat[static_cast<int>(SurfaceSide::Toe)], R, 1e-12);
    EXPECT_NEAR(flat[static_cast<int>(SurfaceSide::Outer)], L, 1e-12);
    fem::shape_conical_toe(mesh, 60.0);
    auto cone = length_by_side(pile_contact_surface(mesh));
    EXPECT_NEAR(cone[static_cast<int>(SurfaceSide::Toe)], R / std::sin(std::numbers::pi / 6.0), 1e-12);
    EXPECT_NEAR(cone[static_cast<int>(SurfaceSide::Outer)], L - R / std::tan(std::numbers::pi / 6.0), 1e-12);
    EXPECT_NEAR(cone[static_cast<int>(SurfaceSide::Head)], R, 1e-12);
    EXPECT_EQ(cone[static_cast<int>(SurfaceSide::Inner)], 0.0);
}

}  // namespace
}  // namespace pilempm::coupling
