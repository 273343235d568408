// Output of the MPM material points: the ParaView series read back with the plain VTK
// reader, and the HDF5 checkpoint round trip (bit-exact) with its failure modes.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/hdf5/mpm_checkpoint.hpp"
#include "io/writers/vtk_particle_writer.hpp"
#include "mpm/points/particles.hpp"

namespace fs = std::filesystem;
using pilempm::io::CheckpointInfo;
using pilempm::io::ParticleVtkSeries;
using pilempm::io::read_checkpoint;
using pilempm::io::write_checkpoint;
using pilempm::mpm::Particles;

namespace {

// A fresh directory per test, removed again at the end.
class ScratchDir {
public:
    ScratchDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::temp_directory_path() /
                ("pilempm_mpm_output_" + std::string(info->name()) + "_" +
                 std::to_string(getpid()));
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
    std::ifstream in(file, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// n points on a line with every array holding distinct, inexact values (1/3, pi, ...), so
// an exact comparison after the round trip means bit-for-bit.
template <int D>
Particles<D> sample_particles(int n, int state_stride) {
    Particles<D> p;
    p.resize_state(state_stride);  // before add(): add() appends state_stride zeros
    for (int i = 0; i < n; ++i) {
        double pos[3] = {0.1 * i + 1.0 / 3.0, -0.25 * i, 2.0 + std::sqrt(2.0) * i};
        const double lengths[3] = {0.05, 0.1, 0.2};
        p.add(pos, 7.0 / 3.0 + i, 1.0 / 7.0 + 0.01 * i, lengths, i % 2);
    }
    double k = 0.0;
    auto fill = [&](std::vector<double>& a) {
        for (double& v : a) {
            k += 1.0;
            v = std::sin(1.0 + k) * std::pow(10.0, std::fmod(k, 7.0));
        }
    };
    fill(p.v);
    fill(p.C);
    fill(p.F);
    fill(p.domain0);
    fill(p.stress);
    fill(p.strain);
    fill(p.state);
    fill(p.external_force);
    for (double& v : p.volume) v *= 0.999999;
    return p;
}

template <int D>
void expect_same_particles(const Particles<D>& a, const Particles<D>& b) {
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.v, b.v);
    EXPECT_EQ(a.C, b.C);
    EXPECT_EQ(a.mass, b.mass);
    EXPECT_EQ(a.volume, b.volume);
    EXPECT_EQ(a.volume0, b.volume0);
    EXPECT_EQ(a.F, b.F);
    EXPECT_EQ(a.domain0, b.domain0);
    EXPECT_EQ(a.stress, b.stress);
    EXPECT_EQ(a.strain, b.strain);
    EXPECT_EQ(a.material, b.material);
    EXPECT_EQ(a.state_stride, b.state_stride);
    EXPECT_EQ(a.state, b.state);
    EXPECT_EQ(a.external_force, b.external_force);
}

// Runs f, expecting std::runtime_error whose message contains every one of `parts`.
template <typename F>
void expect_runtime_error(F&& f, const std::vector<std::string>& parts) {
    try {
        f();
        ADD_FAILURE() << "no exception thrown";
    } catch (const std::runtime_error& e) {
        const std::string msg = e.what();
        for (const auto& part : parts)
            EXPECT_NE(msg.find(part), std::string::npos) << "\"" << part << "\" not in: " << msg;
    }
}

double von_mises(const double* s) {
    const double p = (s[0] + s[1] + s[2]) / 3.0;
    double dev2 = 0.0;
    for (int i = 0; i < 3; ++i) dev2 += (s[i] - p) * (s[i] - p);
    dev2 += 2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
    return std::sqrt(1.5 * dev2);  // sqrt(3/2 s:s)
}

}  // namespace

// ---- ParaView series -------------------------------------------------------------------

TEST(MpmOutput, VtkSeries2DReadsBack) {
    ScratchDir dir;
    Particles<2> p;
    p.resize_state(2);
    const double lengths[2] = {0.1, 0.1};
    for (int i = 0; i < 4; ++i) {
        const double pos[2] = {0.5 + i, -1.0 - 0.5 * i};
        p.add(pos, 10.0 + i, 0.01, lengths, i == 3 ? 2 : 0);
    }
    {
        ParticleVtkSeries<2> series(dir.path(), "soil", {"void_ratio", "p_c"});
        series.write(0.0, p);
        // Second step: a stressed, moving, hardened soil.
        const double s2[6] = {-1.0e5, -2.5e5, -1.2e5, 3.0e4, 0.0, 0.0};
        std::copy(s2, s2 + 6, p.stress.begin() + 6 * 2);
        const double e2[6] = {1e-3, -2e-3, 0.0, 4e-4, 0.0, 0.0};
        std::copy(e2, e2 + 6, p.strain.begin() + 6 * 2);
        p.v[2 * 1 + 0] = 0.75;
        p.v[2 * 1 + 1] = -1.5;
        p.state[2 * 2 + 0] = 0.65;
        p.state[2 * 2 + 1] = 3.5e5;
        series.write(1.25e-3, p);
        series.finish();
        series.finish();  // idempotent
        EXPECT_EQ(series.steps_written(), 2u);
        EXPECT_EQ(series.pvd_path(), dir.path() / "soil.pvd");
    }
    EXPECT_FALSE(fs::exists(dir.path() / "soil_000001.vtu.tmp"));

    auto grid = read_vtu(dir.path() / "soil_000001.vtu");
    ASSERT_NE(grid, nullptr);
    ASSERT_EQ(grid->GetNumberOfPoints(), 4);
    ASSERT_EQ(grid->GetNumberOfCells(), 4);
    EXPECT_EQ(grid->GetCellType(3), VTK_VERTEX);
    double pt[3];
    grid->GetPoint(1, pt);
    EXPECT_EQ(pt[0], 1.5);
    EXPECT_EQ(pt[1], -1.5);
    EXPECT_EQ(pt[2], 0.0);  // padded

    vtkPointData* pd = grid->GetPointData();
    vtkDataArray* stress = pd->GetArray("stress");
    ASSERT_NE(stress, nullptr);
    ASSERT_EQ(stress->GetNumberOfComponents(), 6);
    EXPECT_EQ(stress->GetComponent(2, 1), -2.5e5);
    EXPECT_EQ(stress->GetComponent(2, 3), 3.0e4);
    EXPECT_EQ(stress->GetComponent(0, 1), 0.0);
    ASSERT_NE(stress->GetComponentName(5), nullptr);
    EXPECT_STREQ(stress->GetComponentName(0), "XX");
    EXPECT_STREQ(stress->GetComponentName(3), "XY");
    EXPECT_STREQ(stress->GetComponentName(5), "XZ");

    const double* s2 = &p.stress[6 * 2];
    vtkDataArray* vm = pd->GetArray("von_mises");
    ASSERT_NE(vm, nullptr);
    EXPECT_NEAR(vm->GetComponent(2, 0), von_mises(s2), 1e-9 * von_mises(s2));
    EXPECT_EQ(vm->GetComponent(0, 0), 0.0);
    vtkDataArray* mean = pd->GetArray("mean_stress");
    ASSERT_NE(mean, nullptr);
    EXPECT_DOUBLE_EQ(mean->GetComponent(2, 0), (-1.0e5 - 2.5e5 - 1.2e5) / 3.0);

    vtkDataArray* strain = pd->GetArray("strain");
    ASSERT_NE(strain, nullptr);
    EXPECT_EQ(strain->GetComponent(2, 1), -2e-3);
    EXPECT_EQ(strain->GetComponent(2, 3), 2e-4);  // tensor shear = engineering / 2

    vtkDataArray* velocity = pd->GetArray("velocity");
    ASSERT_NE(velocity, nullptr);
    ASSERT_EQ(velocity->GetNumberOfComponents(), 3);
    EXPECT_EQ(velocity->GetComponent(1, 0), 0.75);
    EXPECT_EQ(velocity->GetComponent(1, 1), -1.5);
    EXPECT_EQ(velocity->GetComponent(1, 2), 0.0);

    vtkDataArray* void_ratio = pd->GetArray("void_ratio");
    vtkDataArray* pc = pd->GetArray("p_c");
    ASSERT_NE(void_ratio, nullptr);
    ASSERT_NE(pc, nullptr);
    EXPECT_EQ(void_ratio->GetComponent(2, 0), 0.65);
    EXPECT_EQ(pc->GetComponent(2, 0), 3.5e5);
    EXPECT_EQ(pc->GetComponent(1, 0), 0.0);

    ASSERT_NE(pd->GetArray("mass"), nullptr);
    EXPECT_EQ(pd->GetArray("mass")->GetComponent(3, 0), 13.0);
    ASSERT_NE(pd->GetArray("volume"), nullptr);
    EXPECT_EQ(pd->GetArray("volume")->GetComponent(0, 0), 0.01);
    ASSERT_NE(pd->GetArray("material"), nullptr);
    EXPECT_EQ(pd->GetArray("material")->GetComponent(3, 0), 2.0);
    ASSERT_NE(grid->GetFieldData()->GetArray("TimeValue"), nullptr);
    EXPECT_EQ(grid->GetFieldData()->GetArray("TimeValue")->GetComponent(0, 0), 1.25e-3);

    // The first step keeps its own (zero) stress.
    auto first = read_vtu(dir.path() / "soil_000000.vtu");
    ASSERT_NE(first->GetPointData()->GetArray("stress"), nullptr);
    EXPECT_EQ(first->GetPointData()->GetArray("stress")->GetComponent(2, 1), 0.0);

    const std::string pvd = slurp(dir.path() / "soil.pvd");
    EXPECT_NE(pvd.find("timestep=\"0\""), std::string::npos);
    EXPECT_NE(pvd.find("timestep=\"0.00125\""), std::string::npos);
    EXPECT_NE(pvd.find("file=\"soil_000001.vtu\""), std::string::npos);
}

TEST(MpmOutput, VtkSeries3DReadsBack) {
    ScratchDir dir;
    Particles<3> p = sample_particles<3>(5, 1);  // state unnamed -> "state_0"
    const double s[6] = {-3.0e5, -3.0e5, -6.0e5, 0.0, 1.0e4, -2.0e4};
    std::copy(s, s + 6, p.stress.begin() + 6 * 4);
    ParticleVtkSeries<3> series(dir.path());
    series.write(0.5, p);
    p.x[3 * 4 + 2] -= 0.125;  // the point moves down; the count changes too
    const double pos[3] = {9.0, 9.0, 9.0}, lengths[3] = {1.0, 1.0, 1.0};
    p.add(pos, 1.0, 1.0, lengths, 0);
    series.write(1.0, p);
    series.finish();

    auto grid = read_vtu(dir.path() / "particles_000001.vtu");
    ASSERT_NE(grid, nullptr);
    ASSERT_EQ(grid->GetNumberOfPoints(), 6);
    EXPECT_EQ(read_vtu(dir.path() / "particles_000000.vtu")->GetNumberOfPoints(), 5);
    double pt[3];
    grid->GetPoint(4, pt);
    EXPECT_EQ(pt[0], p.x[3 * 4]);
    EXPECT_EQ(pt[1], p.x[3 * 4 + 1]);
    EXPECT_EQ(pt[2], p.x[3 * 4 + 2]);
    vtkPointData* pd = grid->GetPointData();
    ASSERT_NE(pd->GetArray("stress"), nullptr);
    EXPECT_EQ(pd->GetArray("stress")->GetComponent(4, 5), -2.0e4);
    ASSERT_NE(pd->GetArray("von_mises"), nullptr);
    EXPECT_NEAR(pd->GetArray("von_mises")->GetComponent(4, 0), von_mises(s), 1e-9 * von_mises(s));
    EXPECT_DOUBLE_EQ(pd->GetArray("mean_stress")->GetComponent(4, 0), -4.0e5);
    vtkDataArray* state = pd->GetArray("state_0");
    ASSERT_NE(state, nullptr);
    EXPECT_EQ(state->GetComponent(3, 0), p.state[3]);
    EXPECT_EQ(pd->GetArray("velocity")->GetComponent(2, 2), p.v[3 * 2 + 2]);
    EXPECT_TRUE(fs::exists(dir.path() / "particles.pvd"));
}

TEST(MpmOutput, VtkSeriesRejectsBadInput) {
    ScratchDir dir;
    EXPECT_THROW(ParticleVtkSeries<2>(dir.path(), "a/b"), std::invalid_argument);
    EXPECT_THROW(ParticleVtkSeries<2>(dir.path(), "p", {"mass"}), std::invalid_argument);
    EXPECT_THROW(ParticleVtkSeries<2>(dir.path(), "p", {"e", "e"}), std::invalid_argument);

    ParticleVtkSeries<2> series(dir.path(), "p", {"state_1"});
    Particles<2> p = sample_particles<2>(3, 2);
    // A generated name ("state_1" for k = 1) meeting a given one is refused.
    EXPECT_THROW(series.write(0.0, p), std::invalid_argument);
    Particles<2> q = sample_particles<2>(3, 1);
    q.stress.pop_back();
    EXPECT_THROW(series.write(0.0, q), std::invalid_argument);
    q = sample_particles<2>(3, 1);
    EXPECT_THROW(series.write(std::nan(""), q), std::invalid_argument);
    EXPECT_EQ(series.steps_written(), 0u);
    series.write(0.0, q);
    EXPECT_EQ(series.steps_written(), 1u);
}

TEST(MpmOutput, VtkSeriesWritesPvdFromDestructor) {
    ScratchDir dir;
    {
        ParticleVtkSeries<3> series(dir.path() / "sub");
        series.write(0.0, sample_particles<3>(2, 0));
    }
    EXPECT_TRUE(fs::exists(dir.path() / "sub" / "particles.pvd"));
    EXPECT_TRUE(fs::exists(dir.path() / "sub" / "particles_000000.vtu"));
}

// ---- checkpoint ------------------------------------------------------------------------

template <int D>
void checkpoint_round_trip(const fs::path& dir, int n, int stride) {
    const fs::path file = dir / ("restart_" + std::to_string(D) + "d_" + std::to_string(n) + ".h5");
    const Particles<D> p = sample_particles<D>(n, stride);
    const std::vector<std::pair<std::string, double>> scalars = {
        {"pile_tip_depth_m", 1.0 / 3.0}, {"blows", 17.0}, {"energy/J", -2.5e-300}};
    const std::string fingerprint = "sha256:0123456789abcdef 2D/3D \xc3\xa9";
    write_checkpoint<D>(file, p, 0.1 + 0.2, 123456789012L, scalars, fingerprint);
    EXPECT_TRUE(fs::exists(file));
    EXPECT_FALSE(fs::exists(fs::path(file.string() + ".tmp")));

    Particles<D> q;
    const CheckpointInfo info = read_checkpoint<D>(file, q);
    EXPECT_EQ(info.dimension, D);
    EXPECT_EQ(info.time, 0.1 + 0.2);
    EXPECT_EQ(info.step, 123456789012L);
    EXPECT_EQ(info.case_fingerprint, fingerprint);
    EXPECT_EQ(info.scalars, scalars);
    ASSERT_EQ(q.size(), static_cast<std::size_t>(n));
    expect_same_particles(p, q);
    EXPECT_EQ(q.dstrain, std::vector<double>(6 * static_cast<std::size_t>(n), 0.0));
}

TEST(MpmOutput, CheckpointRoundTrip2D) {
    ScratchDir dir;
    checkpoint_round_trip<2>(dir.path(), 7, 3);
}

TEST(MpmOutput, CheckpointRoundTrip3D) {
    ScratchDir dir;
    checkpoint_round_trip<3>(dir.path(), 5, 1);
}

TEST(MpmOutput, CheckpointRoundTripEmpty) {
    ScratchDir dir;
    checkpoint_round_trip<2>(dir.path(), 0, 0);
    checkpoint_round_trip<3>(dir.path(), 0, 4);
    // No scalars, empty fingerprint.
    const fs::path file = dir.path() / "bare.h5";
    write_checkpoint<3>(file, sample_particles<3>(2, 0), 0.0, 0, {}, "");
    Particles<3> q;
    const CheckpointInfo info = read_checkpoint<3>(file, q);
    EXPECT_TRUE(info.scalars.empty());
    EXPECT_EQ(info.case_fingerprint, "");
    EXPECT_EQ(q.size(), 2u);
}

TEST(MpmOutput, CheckpointOverwritesPrevious) {
    ScratchDir dir;
    const fs::path file = dir.path() / "restart.h5";
    write_checkpoint<2>(file, sample_particles<2>(3, 0), 1.0, 10, {}, "case");
    write_checkpoint<2>(file, sample_particles<2>(4, 1), 2.0, 20, {}, "case");
    Particles<2> q;
    const CheckpointInfo info = read_checkpoint<2>(file, q);
    EXPECT_EQ(info.step, 20);
    EXPECT_EQ(q.size(), 4u);
    EXPECT_EQ(q.state_stride, 1);
}

TEST(MpmOutput, CheckpointDimensionMismatchThrows) {
    ScratchDir dir;
    const fs::path file = dir.path() / "two_d.h5";
    write_checkpoint<2>(file, sample_particles<2>(3, 1), 1.0, 1, {}, "fp");
    Particles<3> q = sample_particles<3>(2, 0);
    const Particles<3> before = q;
    expect_runtime_error([&] { read_checkpoint<3>(file, q); },
                         {file.string(), "2-D", "Particles<3>"});
    expect_same_particles(before, q);  // untouched on failure
}

TEST(MpmOutput, CheckpointCorruptOrTruncatedThrows) {
    ScratchDir dir;
    const fs::path good = dir.path() / "good.h5";
    Particles<3> p = sample_particles<3>(50, 2);
    const double marker = 1234.5678901234567;  // a bit pattern found once in the file
    p.mass[25] = marker;
    write_checkpoint<3>(good, p, 3.0, 3, {{"a", 1.0}}, "fp");
    const std::string bytes = slurp(good);
    Particles<3> q;

    const fs::path missing = dir.path() / "missing.h5";
    expect_runtime_error([&] { read_checkpoint<3>(missing, q); }, {missing.string()});

    const fs::path empty = dir.path() / "empty.h5";
    std::ofstream(empty).close();
    expect_runtime_error([&] { read_checkpoint<3>(empty, q); }, {empty.string()});

    const fs::path garbage = dir.path() / "garbage.h5";
    std::ofstream(garbage) << "this is not an HDF5 file\n" << std::string(4096, 'x');
    expect_runtime_error([&] { read_checkpoint<3>(garbage, q); }, {garbage.string()});

    for (const double fraction : {0.5, 0.9, 0.999}) {
        const fs::path truncated = dir.path() / "truncated.h5";
        fs::copy_file(good, truncated, fs::copy_options::overwrite_existing);
        fs::resize_file(truncated,
                        static_cast<std::uintmax_t>(fraction * static_cast<double>(bytes.size())));
        expect_runtime_error([&] { read_checkpoint<3>(truncated, q); }, {truncated.string()});
    }

    // One flipped byte in the raw data: caught by the dataset checksum.
    const fs::path flipped = dir.path() / "flipped.h5";
    char pattern[sizeof marker];
    std::memcpy(pattern, &marker, sizeof marker);
    const auto at = bytes.find(std::string(pattern, sizeof pattern));
    ASSERT_NE(at, std::string::npos);
    EXPECT_EQ(bytes.find(std::string(pattern, sizeof pattern), at + 1), std::string::npos);
    std::string corrupt = bytes;
    corrupt[at + 3] = static_cast<char>(corrupt[at + 3] ^ 0x10);
    std::ofstream(flipped, std::ios::binary) << corrupt;
    expect_runtime_error([&] { read_checkpoint<3>(flipped, q); }, {flipped.string(), "mass"});

    EXPECT_EQ(q.size(), 0u);  // never half-filled
    read_checkpoint<3>(good, q);  // the intact file still reads
    expect_same_particles(p, q);
}

// A flipped byte in the root object header fails its metadata checksum. HDF5 1.10 leaks a
// little of its own memory after such a failure and reports it when the library closes at
// exit ("infinite loop closing library"), so this read runs in a child process that leaves
// with _Exit, keeping the test binary's own exit clean.
TEST(MpmOutputDeathTest, CheckpointCorruptMetadataThrows) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    ScratchDir dir;
    const fs::path good = dir.path() / "good.h5";
    write_checkpoint<2>(good, sample_particles<2>(10, 1), 1.0, 1, {}, "fp");
    std::string bytes = slurp(good);
    const auto at = bytes.find("fingerprint");
    ASSERT_NE(at, std::string::npos);
    bytes[at + 2] = 'X';
    const fs::path flipped = dir.path() / "flipped.h5";
    std::ofstream(flipped, std::ios::binary) << bytes;
    EXPECT_EXIT(
        {
            int code = 1;
            try {
                Particles<2> q;
                read_checkpoint<2>(flipped, q);
                std::fprintf(stderr, "no exception thrown\n");
            } catch (const std::runtime_error& e) {
                code = std::string(e.what()).find(flipped.string()) != std::string::npos ? 0 : 2;
                if (code != 0) std::fprintf(stderr, "message without the file: %s\n", e.what());
            }
            std::error_code ec;
            fs::remove_all(dir.path(), ec);  // _Exit skips ScratchDir's destructor
            std::_Exit(code);
        },
        ::testing::ExitedWithCode(0), "");
}

TEST(MpmOutput, CheckpointArraySizeMismatchThrows) {
    ScratchDir dir;
    const fs::path file = dir.path() / "edited.h5";
    write_checkpoint<2>(file, sample_particles<2>(4, 1), 1.0, 1, {}, "fp");
    {
        // Replace /particles/mass by one with a value too many.
        const hid_t h5 = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
        ASSERT_GE(h5, 0);
        ASSERT_GE(H5Ldelete(h5, "/particles/mass", H5P_DEFAULT), 0);
        const hsize_t n = 5;
        const hid_t space = H5Screate_simple(1, &n, nullptr);
        const hid_t set = H5Dcreate2(h5, "/particles/mass", H5T_IEEE_F64LE, space, H5P_DEFAULT,
                                     H5P_DEFAULT, H5P_DEFAULT);
        ASSERT_GE(set, 0);
        const double mass[5] = {1, 2, 3, 4, 5};
        EXPECT_GE(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, mass), 0);
        H5Dclose(set);
        H5Sclose(space);
        H5Fclose(h5);
    }
    Particles<2> q;
    expect_runtime_error([&] { read_checkpoint<2>(file, q); },
                         {file.string(), "/particles/mass", "5 values", "4 expected"});
    EXPECT_EQ(q.size(), 0u);
}

TEST(MpmOutput, CheckpointFailedWriteKeepsPrevious) {
    ScratchDir dir;
    const fs::path file = dir.path() / "restart.h5";
    const Particles<3> good = sample_particles<3>(3, 1);
    write_checkpoint<3>(file, good, 1.0, 1, {}, "first");

    Particles<3> bad = sample_particles<3>(3, 1);
    bad.F.pop_back();
    expect_runtime_error([&] { write_checkpoint<3>(file, bad, 2.0, 2, {}, "second"); },
                         {file.string(), "F"});
    EXPECT_FALSE(fs::exists(fs::path(file.string() + ".tmp")));

    // A stale .tmp from a crashed writer is simply overwritten.
    std::ofstream(file.string() + ".tmp") << "half a checkpoint";
    const fs::path nowhere = dir.path() / "no_such_dir" / "restart.h5";
    expect_runtime_error([&] { write_checkpoint<3>(nowhere, good, 2.0, 2, {}, "x"); },
                         {nowhere.string()});

    Particles<3> q;
    EXPECT_EQ(read_checkpoint<3>(file, q).case_fingerprint, "first");
    expect_same_particles(good, q);
    write_checkpoint<3>(file, good, 3.0, 3, {}, "third");
    EXPECT_FALSE(fs::exists(fs::path(file.string() + ".tmp")));
    EXPECT_EQ(read_checkpoint<3>(file, q).case_fingerprint, "third");
}
