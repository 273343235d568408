#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "fem/mesh/axisymmetric_mesher.hpp"
#include "fem/mesh/pile_geometry.hpp"
#include "fem/mesh/pile_mesh.hpp"

namespace pilempm::fem {
namespace {

std::string wall_geo() {
    return std::string(PILEMPM_SOURCE_DIR) + "/meshes/pile_wall_axisymmetric.geo";
}

PileGeometry uniform_tube(double length, double outer_radius, double thickness) {
    PileGeometry g;
    g.stations = {{0.0, outer_radius - thickness, outer_radius},
                  {length, outer_radius - thickness, outer_radius}};
    return g;
}

// Signed area of element e in the (r, z) plane (shoelace formula).
double element_area(const PileMesh& mesh, int e) {
    const ElementBlock& b = mesh.blocks.front();
    double twice = 0.0;
    for (int a = 0; a < 4; ++a) {
        const int p = b.connectivity[4 * e + a], q = b.connectivity[4 * e + (a + 1) % 4];
        twice += mesh.coordinates[2 * p] * mesh.coordinates[2 * q + 1] -
                 mesh.coordinates[2 * q] * mesh.coordinates[2 * p + 1];
    }
    return 0.5 * twice;
}

// Sums the element areas, requiring each to be positive (counter-clockwise nodes).
double total_area_all_positive(const PileMesh& mesh) {
    double total = 0.0;
    for (int e = 0; e < mesh.blocks.front().num_elements(); ++e) {
        const double a = element_area(mesh, e);
        EXPECT_GT(a, 0.0) << "element " << e;
        total += a;
    }
    return total;
}

// Wall area of the (r, z) section: the integral of (ro - ri) dz, exact for linear radii.
double wall_area(const PileGeometry& g) {
    double area = 0.0;
    for (std::size_t i = 1; i < g.stations.size(); ++i) {
        const PileStation &lo = g.stations[i - 1], &hi = g.stations[i];
        const double t_lo = lo.outer_radius - lo.inner_radius;
        const double t_hi = hi.outer_radius - hi.inner_radius;
        area += 0.5 * (t_lo + t_hi) * (hi.z - lo.z);
    }
    return area;
}

void expect_valid_structure(const PileMesh& mesh) {
    ASSERT_EQ(mesh.dim, 2);
    ASSERT_EQ(mesh.blocks.size(), 1u);
    const ElementBlock& b = mesh.blocks.front();
    EXPECT_EQ(b.kind, ElementKind::AxisymQuad4);
    EXPECT_EQ(b.nodes_per_element, 4);
    EXPECT_TRUE(b.section_area.empty());
    for (int n : b.connectivity) {
        ASSERT_GE(n, 0);
        ASSERT_LT(n, mesh.num_nodes());
    }
}

void expect_end_nodes_sorted(const PileMesh& mesh, const std::vector<int>& nodes, double z) {
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        EXPECT_EQ(mesh.coordinates[2 * nodes[k] + 1], z);
        if (k > 0) {
            EXPECT_LT(mesh.coordinates[2 * nodes[k - 1]], mesh.coordinates[2 * nodes[k]]);
        }
    }
}

TEST(AxisymmetricMesher, UniformTubeCountsAreaAndEnds) {
    const double length = 10.0, thickness = 0.05;
    const int nr = 2;
    const PileMesh mesh =
        mesh_axisymmetric_wall(uniform_tube(length, 1.0, thickness), 0.1, nr, wall_geo());
    expect_valid_structure(mesh);
    EXPECT_EQ(mesh.num_nodes(), 101 * 3);
    EXPECT_EQ(mesh.num_elements(), 200);
    EXPECT_NEAR(total_area_all_positive(mesh), length * thickness, 1e-10 * length * thickness);

    ASSERT_EQ(mesh.head_nodes.size(), static_cast<std::size_t>(nr + 1));
    ASSERT_EQ(mesh.toe_nodes.size(), static_cast<std::size_t>(nr + 1));
    expect_end_nodes_sorted(mesh, mesh.head_nodes, length);
    expect_end_nodes_sorted(mesh, mesh.toe_nodes, 0.0);
    EXPECT_DOUBLE_EQ(mesh.coordinates[2 * mesh.toe_nodes.front()], 0.95);
    EXPECT_DOUBLE_EQ(mesh.coordinates[2 * mesh.head_nodes.back()], 1.0);
}

TEST(AxisymmetricMesher, TwoSegmentsWithTaperAreConformingAndExact) {
    // Thin upper segment on a thicker lower one, joined by the default 1:4 taper.
    const PileGeometry g = make_pile_geometry({{10.0, 2.0, 0.04}, {15.0, 2.0, 0.06}});
    ASSERT_EQ(g.stations.size(), 4u);
    const double element_size = 0.1;
    const int nr = 3;
    const PileMesh mesh = mesh_axisymmetric_wall(g, element_size, nr, wall_geo());
    expect_valid_structure(mesh);

    const double area = wall_area(g);
    EXPECT_NEAR(total_area_all_positive(mesh), area, 1e-10 * area);

    // Shared lines between intervals: one node row per axial division plus one.
    int rows = 1;
    for (std::size_t i = 1; i < g.stations.size(); ++i)
        rows += std::max(1, static_cast<int>(std::lround((g.stations[i].z - g.stations[i - 1].z) /
                                                         element_size)));
    EXPECT_EQ(mesh.num_nodes(), rows * (nr + 1));
    EXPECT_EQ(mesh.num_elements(), (rows - 1) * nr);
    EXPECT_EQ(mesh.head_nodes.size(), static_cast<std::size_t>(nr + 1));
    EXPECT_EQ(mesh.toe_nodes.size(), static_cast<std::size_t>(nr + 1));
}

TEST(AxisymmetricMesher, RepeatedStationIsSkipped) {
    PileGeometry g = uniform_tube(10.0, 1.0, 0.05);
    g.stations.insert(g.stations.begin() + 1, {4.0, 0.95, 1.0});
    g.stations.insert(g.stations.begin() + 1, {4.0, 0.95, 1.0});
    const PileMesh mesh = mesh_axisymmetric_wall(g, 0.1, 2, wall_geo());
    EXPECT_EQ(mesh.num_nodes(), 101 * 3);
    EXPECT_EQ(mesh.num_elements(), 200);
    EXPECT_NEAR(total_area_all_positive(mesh), 0.5, 1e-10 * 0.5);
}

TEST(AxisymmetricMesher, RadiusStepIsRejected) {
    const PileGeometry g = make_pile_geometry({{5.0, 2.0, 0.04}, {5.0, 2.0, 0.06}}, 0.0);
    EXPECT_THROW(mesh_axisymmetric_wall(g, 0.1, 2, wall_geo()), std::invalid_argument);
}

TEST(AxisymmetricMesher, MissingGeoFileThrowsNamingIt) {
    const std::string missing = std::string(PILEMPM_SOURCE_DIR) + "/meshes/no_such_file.geo";
    try {
        mesh_axisymmetric_wall(uniform_tube(10.0, 1.0, 0.05), 0.1, 2, missing);
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
    }
    // A failed call leaves gmsh usable for the next one.
    EXPECT_EQ(
        mesh_axisymmetric_wall(uniform_tube(1.0, 1.0, 0.05), 0.1, 1, wall_geo()).num_elements(),
        10);
}

TEST(AxisymmetricMesher, BrokenGeoThrowsAndGmshRecovers) {
    const auto bad = std::filesystem::temp_directory_path() / "pilempm_test_broken_wall.geo";
    std::ofstream(bad) << "Point(1) = {nr, ;\n";
    EXPECT_THROW(mesh_axisymmetric_wall(uniform_tube(1.0, 1.0, 0.05), 0.1, 1, bad.string()),
                 std::runtime_error);
    std::filesystem::remove(bad);
    // A parse error must not leave gmsh's parser broken for later meshes.
    EXPECT_EQ(
        mesh_axisymmetric_wall(uniform_tube(1.0, 1.0, 0.05), 0.1, 1, wall_geo()).num_elements(),
        10);
}

TEST(AxisymmetricMesher, DefaultGeoFollowsEnvironment) {
    const char* previous = std::getenv("PILEMPM_MESH_DIR");
    const std::string saved = previous ? previous : "";
    ASSERT_EQ(setenv("PILEMPM_MESH_DIR", "/some/dir", 1), 0);
    EXPECT_EQ(default_pile_wall_geo(), "/some/dir/pile_wall_axisymmetric.geo");
    unsetenv("PILEMPM_MESH_DIR");
    EXPECT_NE(default_pile_wall_geo(), "/some/dir/pile_wall_axisymmetric.geo");
    if (previous) setenv("PILEMPM_MESH_DIR", saved.c_str(), 1);  // leave the environment as found
}

}  // namespace
}  // namespace pilempm::fem
