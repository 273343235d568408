// Round trips of the output writers: what PileVtkSeries and write_results_h5 write must
// read back unchanged with the plain VTK reader and the HDF5 C API.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include "io/writers/drive_outlook.hpp"
#include <vtkXMLUnstructuredGridReader.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/table.hpp"
#include "io/hdf5/hdf5_results.hpp"
#include "io/writers/vtk_pile_writer.hpp"

namespace fs = std::filesystem;
using pilempm::Table;
using pilempm::fem::ElementBlock;
using pilempm::fem::ElementKind;
using pilempm::fem::PileMesh;

namespace {

// 3-node rod, z = 0, 1, 2, one Rod2 block of 2 elements.
PileMesh rod_mesh() {
    PileMesh mesh;
    mesh.dim = 1;
    mesh.coordinates = {0.0, 1.0, 2.0};
    ElementBlock block;
    block.kind = ElementKind::Rod2;
    block.nodes_per_element = 2;
    block.connectivity = {0, 1, 1, 2};
    mesh.blocks.push_back(block);
    mesh.head_nodes = {2};
    mesh.toe_nodes = {0};
    return mesh;
}

// Tube wall r in [0.5, 0.52], two quads stacked along z, nodes counter-clockwise.
PileMesh quad_mesh() {
    PileMesh mesh;
    mesh.dim = 2;
    mesh.coordinates = {0.5, 0.0, 0.52, 0.0, 0.5, 1.0, 0.52, 1.0, 0.5, 2.0, 0.52, 2.0};
    ElementBlock block;
    block.kind = ElementKind::AxisymQuad4;
    block.nodes_per_element = 4;
    block.connectivity = {0, 1, 3, 2, 2, 3, 5, 4};
    mesh.blocks.push_back(block);
    mesh.head_nodes = {4, 5};
    mesh.toe_nodes = {0, 1};
    return mesh;
}

// A fresh directory per test, removed again at the end.
class ScratchDir {
public:
    ScratchDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::temp_directory_path() /
                ("pilempm_writers_" + std::string(info->name()) + "_" + std::to_string(getpid()));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~ScratchDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const fs::path& file) {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();
    return reader->GetOutput();
}

std::string slurp(const fs::path& file) {
    std::ifstream in(file);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Value of name="..." inside one XML element's text.
std::string attribute(const std::string& element, const std::string& name) {
    const std::string key = " " + name + "=\"";
    const auto start = element.find(key);
    if (start == std::string::npos) return {};
    const auto begin = start + key.size();
    return element.substr(begin, element.find('"', begin) - begin);
}

}  // namespace

TEST(OutputWriters, VtkRodSeriesReadsBack) {
    ScratchDir dir;
    const PileMesh mesh = rod_mesh();
    {
        pilempm::io::PileVtkSeries series(dir.path(), mesh, "rod");
        series.write(0.0, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0});
        series.write(2.5e-4, {-1e-4, -2e-4, -3.25e-4}, {0.1, 0.2, -0.3}, {-1.5e8, 3.0e7});
        series.finish();
        series.finish();  // idempotent
        EXPECT_EQ(series.steps_written(), 2u);
    }

    auto grid = read_vtu(dir.path() / "rod_000001.vtu");
    ASSERT_NE(grid, nullptr);
    EXPECT_EQ(grid->GetNumberOfPoints(), 3);
    ASSERT_EQ(grid->GetNumberOfCells(), 2);
    EXPECT_EQ(grid->GetCellType(0), VTK_LINE);
    double p[3];
    grid->GetPoint(2, p);
    EXPECT_EQ(p[0], 0.0);
    EXPECT_EQ(p[1], 2.0);  // axial coordinate on y

    vtkDataArray* stress = grid->GetCellData()->GetArray("axial_stress_Pa");
    ASSERT_NE(stress, nullptr);
    EXPECT_EQ(stress->GetComponent(0, 0), -1.5e8);
    EXPECT_EQ(stress->GetComponent(1, 0), 3.0e7);
    vtkDataArray* u = grid->GetPointData()->GetArray("displacement");
    ASSERT_NE(u, nullptr);
    ASSERT_EQ(u->GetNumberOfComponents(), 3);
    EXPECT_EQ(u->GetComponent(2, 1), -3.25e-4);
    EXPECT_EQ(u->GetComponent(2, 0), 0.0);
    vtkDataArray* v = grid->GetPointData()->GetArray("velocity");
    ASSERT_NE(v, nullptr);
    EXPECT_EQ(v->GetComponent(1, 1), 0.2);

    // The first step keeps its own (zero) values: write() must not alias earlier files.
    auto first = read_vtu(dir.path() / "rod_000000.vtu");
    EXPECT_EQ(first->GetCellData()->GetArray("axial_stress_Pa")->GetComponent(0, 0), 0.0);

    const std::string pvd = slurp(dir.path() / "rod.pvd");
    EXPECT_NE(pvd.find("type=\"Collection\""), std::string::npos);
    std::vector<std::pair<double, std::string>> entries;
    for (std::size_t pos = pvd.find("<DataSet"); pos != std::string::npos;
         pos = pvd.find("<DataSet", pos + 1)) {
        const std::string element = pvd.substr(pos, pvd.find('>', pos) - pos);
        entries.emplace_back(std::stod(attribute(element, "timestep")),
                             attribute(element, "file"));
    }
    ASSERT_EQ(entries.size(), 2u);
    EXPECT_EQ(entries[0].first, 0.0);
    EXPECT_EQ(entries[0].second, "rod_000000.vtu");
    EXPECT_EQ(entries[1].first, 2.5e-4);
    EXPECT_EQ(entries[1].second, "rod_000001.vtu");
}

TEST(OutputWriters, VtkAxisymmetricQuadsReadBack) {
    ScratchDir dir;
    const PileMesh mesh = quad_mesh();
    pilempm::io::PileVtkSeries series(dir.path(), mesh);
    std::vector<double> u(12, 0.0), v(12, 0.0);
    u[2 * 5] = 1e-6;      // radial at node 5
    u[2 * 5 + 1] = -4e-4;  // axial at node 5
    v[2 * 4 + 1] = -3.5;
    series.write(1e-3, u, v, {-2.0e8, 5.0e6});
    series.finish();

    auto grid = read_vtu(dir.path() / "pile_000000.vtu");
    ASSERT_NE(grid, nullptr);
    EXPECT_EQ(grid->GetNumberOfPoints(), 6);
    ASSERT_EQ(grid->GetNumberOfCells(), 2);
    EXPECT_EQ(grid->GetCellType(1), VTK_QUAD);
    double p[3];
    grid->GetPoint(3, p);
    EXPECT_EQ(p[0], 0.52);  // r on x
    EXPECT_EQ(p[1], 1.0);   // z on y
    auto* disp = grid->GetPointData()->GetArray("displacement");
    ASSERT_NE(disp, nullptr);
    EXPECT_EQ(disp->GetComponent(5, 0), 1e-6);
    EXPECT_EQ(disp->GetComponent(5, 1), -4e-4);
    EXPECT_EQ(grid->GetPointData()->GetArray("velocity")->GetComponent(4, 1), -3.5);
    EXPECT_EQ(grid->GetCellData()->GetArray("axial_stress_Pa")->GetComponent(1, 0), 5.0e6);
    EXPECT_TRUE(fs::exists(dir.path() / "pile.pvd"));
}

TEST(OutputWriters, VtkRejectsWrongSizes) {
    ScratchDir dir;
    pilempm::io::PileVtkSeries series(dir.path(), rod_mesh());
    EXPECT_THROW(series.write(0.0, {0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0}),
                 std::invalid_argument);
    EXPECT_THROW(series.write(0.0, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0}),
                 std::invalid_argument);
    EXPECT_EQ(series.steps_written(), 0u);
}

TEST(OutputWriters, Hdf5ResultsReadBack) {
    ScratchDir dir;
    const fs::path file = dir.path() / "results.h5";
    Table table("driving", {"depth_m", "blows_per_0.25m"});
    table.add_row({0.25, 3.0});
    table.add_row({0.5, 7.0});
    table.add_row({0.75, 1.0 / 3.0});
    const PileMesh mesh = rod_mesh();
    pilempm::io::write_results_h5(file, {table}, mesh, {0.0, -1e-4, -2e-4}, {0.0, 0.5, 1.0},
                                  {-1e8, 2e7}, {{"hammer_energy_J", 123456.789}},
                                  {{"title", "unit test"}});

    const hid_t h5 = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(h5, 0);

    const hid_t set = H5Dopen2(h5, "/driving/blows_per_0.25m", H5P_DEFAULT);
    ASSERT_GE(set, 0);
    const hid_t space = H5Dget_space(set);
    EXPECT_EQ(H5Sget_simple_extent_ndims(space), 1);
    EXPECT_EQ(H5Sget_simple_extent_npoints(space), 3);
    std::vector<double> values(3, -1.0);
    EXPECT_GE(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
    EXPECT_EQ(values, table.data[1]);
    H5Sclose(space);
    H5Dclose(set);

    double energy = 0.0;
    const hid_t attr = H5Aopen(h5, "hammer_energy_J", H5P_DEFAULT);
    ASSERT_GE(attr, 0);
    EXPECT_GE(H5Aread(attr, H5T_NATIVE_DOUBLE, &energy), 0);
    EXPECT_EQ(energy, 123456.789);
    H5Aclose(attr);

    // Column order attribute, mesh and final state are where the reader expects them.
    const hid_t group = H5Gopen2(h5, "/driving", H5P_DEFAULT);
    ASSERT_GE(group, 0);
    EXPECT_GT(H5Aexists(group, "columns"), 0);
    H5Gclose(group);
    EXPECT_GT(H5Lexists(h5, "/mesh/coordinates", H5P_DEFAULT), 0);
    EXPECT_GT(H5Lexists(h5, "/mesh/block_0", H5P_DEFAULT), 0);
    EXPECT_GT(H5Lexists(h5, "/final_state/axial_stress_Pa", H5P_DEFAULT), 0);
    EXPECT_GT(H5Aexists(h5, "title"), 0);
    H5Fclose(h5);
}

TEST(OutputWriters, Hdf5RejectsWrongFinalStateSize) {
    ScratchDir dir;
    const fs::path file = dir.path() / "bad.h5";
    EXPECT_THROW(pilempm::io::write_results_h5(file, {}, rod_mesh(), {0.0}, {0.0, 0.0, 0.0},
                                               {0.0, 0.0}, {}, {}),
                 std::runtime_error);
    EXPECT_FALSE(fs::exists(file));
}

// A drive's outlook in its log: the depth left over the mean set of the last blows (a window
// of them), the time at their mean pace; none while the pile does not advance.
TEST(DriveOutlook, BlowsAndTimeToGoFollowTheRecentSetsAndPace) {
    pilempm::io::DriveOutlook o(3);
    EXPECT_LT(o.to_go(1.0).blows, 0.0);  // no blow yet
    o.add(0.010, -1.0);                   // the first blow of the invocation: no pace yet
    EXPECT_DOUBLE_EQ(o.to_go(1.0).blows, 100.0);
    EXPECT_LT(o.to_go(1.0).seconds, 0.0);
    o.add(0.020, 20.0);
    o.add(0.030, 10.0);
    o.add(0.010, 30.0);                   // the window keeps 0.020, 0.030, 0.010
    EXPECT_DOUBLE_EQ(o.to_go(0.6).blows, 30.0);
    EXPECT_DOUBLE_EQ(o.to_go(0.6).seconds, 600.0);  // 20 s a blow
    pilempm::io::DriveOutlook stuck(2);
    stuck.add(0.0, 10.0);
    stuck.add(-0.001, 10.0);              // rebounding: no estimate
    EXPECT_LT(stuck.to_go(1.0).blows, 0.0);
}
