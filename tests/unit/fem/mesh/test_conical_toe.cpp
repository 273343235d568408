#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "fem/mesh/axisymmetric_mesher.hpp"
#include "fem/mesh/conical_toe.hpp"

namespace pilempm::fem {
namespace {

PileMesh solid_pile(double length, double radius, double element_size, int radial_divisions) {
    PileGeometry g;
    g.stations = {{0.0, 0.0, radius}, {length, 0.0, radius}};
    return mesh_axisymmetric_wall(g, element_size, radial_divisions,
                                  std::string(PILEMPM_SOURCE_DIR) + "/meshes/pile_wall_axisymmetric.geo");
}

// The steel's volume, 2 pi x (the integral of r over each quad), by Green's theorem on the
// quad's straight edges: exact for any straight-sided quad, so for a cone on the edges.
double volume_of_revolution(const PileMesh& mesh) {
    double v = 0.0;
    const ElementBlock& b = mesh.blocks.front();
    for (int e = 0; e < b.num_elements(); ++e)
        for (int a = 0; a < 4; ++a) {
            const double* p = &mesh.coordinates[2 * b.connectivity[4 * e + a]];
            const double* q = &mesh.coordinates[2 * b.connectivity[4 * e + (a + 1) % 4]];
            // integral of r dA = (1/2) closed integral of r^2 dz (counter-clockwise)
            v += 0.5 * (q[1] - p[1]) * (p[0] * p[0] + p[0] * q[0] + q[0] * q[0]) / 3.0;
        }
    return 2.0 * std::numbers::pi * v;
}

TEST(ConicalToe, SixtyDegreeConeHasTheConesVolumeAndItsToeOnTheCone) {
    for (int divisions : {2, 4}) {
        const double L = 3.0, R = 0.4;
        PileMesh mesh = solid_pile(L, R, 0.1, divisions);
        const double h = shape_conical_toe(mesh, 60.0);
        EXPECT_NEAR(h, R * std::sqrt(3.0), 1e-12);
        // A cylinder less the ring of revolution the cone leaves out: pi R^2 (L - 2h/3).
        const double expected = std::numbers::pi * R * R * (L - 2.0 * h / 3.0);
        EXPECT_NEAR(volume_of_revolution(mesh), expected, 1e-9 * expected) << divisions << " divisions";
        for (int node : mesh.toe_nodes)
            EXPECT_NEAR(mesh.z(node), h * mesh.coordinates[2 * node] / R, 1e-12);
        // Everything from 2h up is where the mesher put it; every quad stays counter-clockwise.
        const PileMesh flat = solid_pile(L, R, 0.1, divisions);
        for (int i = 0; i < mesh.num_nodes(); ++i)
            if (flat.z(i) >= 2.0 * h) {
                EXPECT_EQ(mesh.z(i), flat.z(i));
            }
        const ElementBlock& b = mesh.blocks.front();
        for (int e = 0; e < b.num_elements(); ++e) {
            double twice = 0.0;
            for (int a = 0; a < 4; ++a) {
                const double* p = &mesh.coordinates[2 * b.connectivity[4 * e + a]];
                const double* q = &mesh.coordinates[2 * b.connectivity[4 * e + (a + 1) % 4]];
                twice += p[0] * q[1] - q[0] * p[1];
            }
            EXPECT_GT(twice, 0.0) << "element " << e;
        }
    }
}

TEST(ConicalToe, RejectsAnOpenToeABadAngleAndAShortPile) {
    PileGeometry tube;
    tube.stations = {{0.0, 0.38, 0.4}, {3.0, 0.38, 0.4}};
    PileMesh open = mesh_axisymmetric_wall(tube, 0.1, 2, std::string(PILEMPM_SOURCE_DIR) + "/meshes/pile_wall_axisymmetric.geo");
    EXPECT_THROW(shape_conical_toe(open, 60.0), std::invalid_argument);
    PileMesh solid = solid_pile(3.0, 0.4, 0.1, 2);
    EXPECT_THROW(shape_conical_toe(solid, 0.0), std::invalid_argument);
    EXPECT_THROW(shape_conical_toe(solid, 180.0), std::invalid_argument);
    PileMesh stub = solid_pile(1.0, 0.4, 0.1, 2);  // 2 h = 1.39 m
    EXPECT_THROW(shape_conical_toe(stub, 60.0), std::invalid_argument);
}

}  // namespace
}  // namespace pilempm::fem
