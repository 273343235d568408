#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

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

// The toe's slip line leaves the outer corner along the bisector of its outward normals:
// 45 deg down on a flat toe, 15 deg down from a 60 deg cone's shoulder (normals at 0 and
// -30 deg); above it the polyline runs up the outer shaft to the head, ascending in y.
TEST(PileSurface, TheToesSlipLineBisectsTheCornerAndClimbsTheShaft) {
    const double L = 3.0, R = 0.4, length = 0.3, toe = 5.0;
    fem::PileGeometry g;
    g.stations = {{0.0, 0.0, R}, {L, 0.0, R}};
    fem::PileMesh mesh = fem::mesh_axisymmetric_wall(g, 0.1, 3, std::string(PILEMPM_SOURCE_DIR) + "/meshes/pile_wall_axisymmetric.geo");
    for (const double angle : {0.0, 60.0}) {
        if (angle > 0.0) fem::shape_conical_toe(mesh, angle);
        ContactSurface surface = pile_contact_surface(mesh);
        const std::vector<double> zero(2 * mesh.num_nodes(), 0.0);
        place_pile_surface(surface, mesh, zero, zero, PileFrame{toe});
        const auto line = toe_slip_line(surface, length);
        const double shoulder = toe + (angle > 0.0 ? R / std::tan(std::numbers::pi / 6.0) : 0.0);
        const double down = (angle > 0.0 ? 15.0 : 45.0) * std::numbers::pi / 180.0;
        EXPECT_NEAR(line[0], R + length * std::cos(down), 1e-12) << angle;
        EXPECT_NEAR(line[1], shoulder - length * std::sin(down), 1e-12) << angle;
        EXPECT_NEAR(line[2], R, 1e-12) << angle;
        EXPECT_NEAR(line[3], shoulder, 1e-12) << angle;
        EXPECT_NEAR(line[line.size() - 1], toe + L, 1e-12) << angle;
        for (std::size_t k = 2; k < line.size(); k += 2) EXPECT_NEAR(line[k], R, 1e-12) << angle;
        for (std::size_t k = 3; k < line.size(); k += 2) EXPECT_GT(line[k], line[k - 2]) << angle;
    }
}

}  // namespace
}  // namespace pilempm::coupling
