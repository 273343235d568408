#include "io/writers/vtk_particle_writer.hpp"

#include <Eigen/Dense>
#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "io/writers/pvd_collection.hpp"
#include "core/voigt.hpp"

namespace pilempm::io {

namespace fs = std::filesystem;

namespace {

// The arrays every step carries; state variables may not take these names.
constexpr const char* kFixedArrays[] = {"velocity", "stress",   "strain", "mean_stress",
                                        "von_mises", "volume",  "mass",   "material",
                                        "TimeValue"};

bool is_fixed_array(const std::string& name) {
    return std::find(std::begin(kFixedArrays), std::end(kFixedArrays), name) !=
           std::end(kFixedArrays);
}

// ParaView recognises a 6-component array with these names as a symmetric tensor; the
// order matches Voigt [xx, yy, zz, xy, yz, zx].
constexpr const char* kTensorComponents[6] = {"XX", "YY", "ZZ", "XY", "YZ", "XZ"};

vtkNew<vtkDoubleArray> make_array(const char* name, int components, vtkIdType tuples) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(components);
    a->SetNumberOfTuples(tuples);
    return a;
}

template <int D>
void check_sizes(const mpm::Particles<D>& p) {
    const std::size_t n = p.size();
    auto need = [&](const char* what, std::size_t have, std::size_t want) {
        if (have != want)
            throw std::invalid_argument(std::string("ParticleVtkSeries::write: Particles::") +
                                        what + " has " + std::to_string(have) + " values, " +
                                        std::to_string(want) + " expected for " +
                                        std::to_string(n) + " points");
    };
    if (p.state_stride < 0)
        throw std::invalid_argument("ParticleVtkSeries::write: negative state_stride");
    need("x", p.x.size(), D * n);
    need("v", p.v.size(), D * n);
    need("volume", p.volume.size(), n);
    need("stress", p.stress.size(), 6 * n);
    need("strain", p.strain.size(), 6 * n);
    need("material", p.material.size(), n);
    need("state", p.state.size(), static_cast<std::size_t>(p.state_stride) * n);
}

}  // namespace

double von_mises_stress(const double* s) {
    const double dxy = s[0] - s[1], dyz = s[1] - s[2], dzx = s[2] - s[0];
    const double j2 = (dxy * dxy + dyz * dyz + dzx * dzx) / 6.0 +
                      s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
    return std::sqrt(3.0 * j2);
}

template <int D>
struct ParticleVtkSeries<D>::Impl {
    explicit Impl(PvdCollection collection) : pvd(std::move(collection)) {}

    PvdCollection pvd;
    std::vector<std::string> state_names;
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    bool pore_water = false;
    mpm::PoreWater water;
    std::vector<double> friction_angle_deg;

    std::vector<std::string> state_array_names(int stride) const;
};

template <int D>
std::vector<std::string> ParticleVtkSeries<D>::Impl::state_array_names(int stride) const {
    std::vector<std::string> names;
    for (int k = 0; k < stride; ++k) {
        const bool given = static_cast<std::size_t>(k) < state_names.size() &&
                           !state_names[static_cast<std::size_t>(k)].empty();
        names.push_back(given ? state_names[static_cast<std::size_t>(k)]
                              : "state_" + std::to_string(k));
        // A generated name may still meet a given one ("state_1" given for k = 0).
        if (std::find(names.begin(), names.end() - 1, names.back()) != names.end() - 1 ||
            is_fixed_array(names.back()))
            throw std::invalid_argument("ParticleVtkSeries::write: state array name \"" +
                                        names.back() + "\" is used twice");
    }
    return names;
}

template <int D>
ParticleVtkSeries<D>::ParticleVtkSeries(fs::path dir, std::string basename,
                                        std::vector<std::string> state_names)
    : impl_(std::make_unique<Impl>(
          PvdCollection("ParticleVtkSeries", std::move(dir), std::move(basename)))) {
    for (std::size_t k = 0; k < state_names.size(); ++k) {
        const std::string& name = state_names[k];
        if (name.empty()) continue;  // falls back to "state_<k>"
        if (is_fixed_array(name) ||
            std::find(state_names.begin(), state_names.begin() + static_cast<long>(k), name) !=
                state_names.begin() + static_cast<long>(k))
            throw std::invalid_argument("ParticleVtkSeries: state name \"" + name +
                                        "\" repeats or collides with a fixed array");
    }
    impl_->state_names = std::move(state_names);

    vtkXMLUnstructuredGridWriter& w = *impl_->writer;
    w.SetDataModeToAppended();
    w.EncodeAppendedDataOff();  // raw binary: no base64 overhead
    w.SetCompressorTypeToZLib();
    w.SetHeaderTypeToUInt64();  // > 4 GiB of appended data is possible with many points

    impl_->pvd.create_directory();
}

template <int D>
ParticleVtkSeries<D>::~ParticleVtkSeries() {
    try {
        finish();
    } catch (...) {
        // Destructors must not throw; a caller who cares calls finish() itself.
    }
}

template <int D>
ParticleVtkSeries<D>::ParticleVtkSeries(ParticleVtkSeries&&) noexcept = default;
template <int D>
ParticleVtkSeries<D>& ParticleVtkSeries<D>::operator=(ParticleVtkSeries&&) noexcept = default;

template <int D>
void ParticleVtkSeries<D>::set_pore_water(const mpm::PoreWater& water, std::vector<double> friction_angle_deg) {
    impl_->pore_water = true;
    impl_->water = water;
    impl_->friction_angle_deg = std::move(friction_angle_deg);
}

namespace {

// sin of the mobilised friction angle, (s1 - s3) / -(s1 + s3), of an effective stress
// (tension positive); 0 when it carries no compression.
double mobilised_sine(const double* s) {
    Eigen::Matrix3d t;
    t << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
    const Eigen::Vector3d e = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(t, Eigen::EigenvaluesOnly).eigenvalues();
    const double s1 = e[2], s3 = e[0];  // least and most compressive
    return s1 + s3 < 0.0 ? std::min(1.0, (s1 - s3) / -(s1 + s3)) : 0.0;
}

}  // namespace

template <int D>
void ParticleVtkSeries<D>::write(double time, const mpm::Particles<D>& p) {
    if (!impl_) throw std::logic_error("ParticleVtkSeries::write on a moved-from series");
    Impl& m = *impl_;
    if (!std::isfinite(time))
        throw std::invalid_argument("ParticleVtkSeries::write: time not finite");
    check_sizes(p);
    const std::vector<std::string> state_names = m.state_array_names(p.state_stride);

    const std::size_t n = p.size();
    const auto nv = static_cast<vtkIdType>(n);

    // A fresh grid per step: the number of points may change between steps.
    vtkNew<vtkUnstructuredGrid> grid;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(nv);
    vtkNew<vtkIdTypeArray> offsets, connectivity;
    offsets->SetNumberOfValues(nv + 1);
    connectivity->SetNumberOfValues(nv);
    auto velocity = make_array("velocity", 3, nv);
    auto stress = make_array("stress", 6, nv);
    auto strain = make_array("strain", 6, nv);
    auto mean = make_array("mean_stress", 1, nv);
    auto mises = make_array("von_mises", 1, nv);
    auto volume = make_array("volume", 1, nv);
    auto mass = make_array("mass", 1, nv);
    vtkNew<vtkIntArray> material;
    material->SetName("material");
    material->SetNumberOfComponents(1);
    material->SetNumberOfTuples(nv);
    for (int c = 0; c < 6; ++c) {
        stress->SetComponentName(c, kTensorComponents[c]);
        strain->SetComponentName(c, kTensorComponents[c]);
    }
    std::vector<vtkSmartPointer<vtkDoubleArray>> state;
    for (const std::string& name : state_names) {
        auto a = vtkSmartPointer<vtkDoubleArray>::New();
        a->SetName(name.c_str());
        a->SetNumberOfComponents(1);
        a->SetNumberOfTuples(nv);
        state.push_back(a);
    }

    const std::size_t stride = static_cast<std::size_t>(p.state_stride);
    for (std::size_t i = 0; i < n; ++i) {
        const auto id = static_cast<vtkIdType>(i);
        const double* xi = &p.x[D * i];
        const double* vi = &p.v[D * i];
        points->SetPoint(id, xi[0], xi[1], D == 3 ? xi[D - 1] : 0.0);
        velocity->SetTuple3(id, vi[0], vi[1], D == 3 ? vi[D - 1] : 0.0);
        offsets->SetValue(id, id);
        connectivity->SetValue(id, id);
        const double* s = &p.stress[6 * i];
        const double* e = &p.strain[6 * i];
        stress->SetTypedTuple(id, s);
        // Engineering shear -> tensor shear, so the array is the strain tensor.
        const double eps[6] = {e[0], e[1], e[2], 0.5 * e[3], 0.5 * e[4], 0.5 * e[5]};
        strain->SetTypedTuple(id, eps);
        mean->SetValue(id, mean_stress(s));
        mises->SetValue(id, von_mises_stress(s));
        volume->SetValue(id, p.volume[i]);
        mass->SetValue(id, p.mass[i]);
        material->SetValue(id, p.material[i]);
        for (std::size_t k = 0; k < stride; ++k) state[k]->SetValue(id, p.state[stride * i + k]);
    }
    offsets->SetValue(nv, nv);
    std::vector<vtkSmartPointer<vtkDoubleArray>> water_arrays;
    if (m.pore_water) {
        auto total = make_array("pore_pressure", 1, nv), excess = make_array("excess_pore_pressure", 1, nv);
        auto w = make_array("water_velocity", 3, nv), n_arr = make_array("porosity", 1, nv);
        auto phi = make_array("mobilised_friction_angle", 1, nv), degree = make_array("degree_of_mobilisation", 1, nv);
        for (std::size_t i = 0; i < n; ++i) {
            const auto id = static_cast<vtkIdType>(i);
            const double pe = p.pore_pressure[i];
            total->SetValue(id, pe + (p.porosity[i] > 0.0 ? m.water.hydrostatic_pressure(p.x[D * i + D - 1]) : 0.0));
            excess->SetValue(id, pe);
            const double* wi = &p.w[D * i];
            w->SetTuple3(id, wi[0], wi[1], D == 3 ? wi[D - 1] : 0.0);
            n_arr->SetValue(id, p.porosity[i]);
            const double sine = mobilised_sine(&p.stress[6 * i]);
            phi->SetValue(id, std::asin(sine) * 180.0 / std::numbers::pi);
            const std::size_t mat = static_cast<std::size_t>(p.material[i]);
            const double phi_mat = mat < m.friction_angle_deg.size() ? m.friction_angle_deg[mat] : 0.0;
            degree->SetValue(id, phi_mat > 0.0 ? sine / std::sin(phi_mat * std::numbers::pi / 180.0) : 0.0);
        }
        water_arrays = {total, excess, w, n_arr, phi, degree};
    }

    grid->SetPoints(points);
    vtkNew<vtkCellArray> cells;
    cells->SetData(offsets, connectivity);
    grid->SetCells(VTK_VERTEX, cells);
    vtkPointData* pd = grid->GetPointData();
    pd->SetVectors(velocity);  // active vectors: ParaView's Glyph picks velocity by default
    pd->AddArray(stress);
    pd->AddArray(strain);
    pd->SetScalars(mean);
    pd->AddArray(mises);
    pd->AddArray(volume);
    pd->AddArray(mass);
    pd->AddArray(material);
    for (const auto& a : state) pd->AddArray(a);
    for (const auto& a : water_arrays) pd->AddArray(a);
    // "TimeValue" field data lets ParaView show the time of a single .vtu opened alone.
    auto time_value = make_array("TimeValue", 1, 1);
    time_value->SetValue(0, time);
    grid->GetFieldData()->AddArray(time_value);

    const std::string file = m.pvd.next_step_file();
    const fs::path path = m.pvd.dir() / file;
    const fs::path tmp = m.pvd.dir() / (file + ".tmp");
    m.writer->SetInputData(grid);
    m.writer->SetFileName(tmp.c_str());
    const bool ok = m.writer->Write() == 1 && m.writer->GetErrorCode() == 0;
    m.writer->SetInputData(nullptr);  // do not keep the step's arrays alive
    std::error_code ec;
    if (ok) fs::rename(tmp, path, ec);
    if (!ok || ec) {
        std::error_code ignored;
        fs::remove(tmp, ignored);
        throw std::runtime_error("ParticleVtkSeries: cannot write " + path.string() +
                                 (ec ? ": " + ec.message() : std::string{}));
    }
    m.pvd.add(time, file);
}

template <int D>
void ParticleVtkSeries<D>::finish() {
    if (impl_) impl_->pvd.finish();  // nothing to do when moved-from
}

template <int D>
std::vector<double> ParticleVtkSeries<D>::step_times() const {
    return impl_ ? impl_->pvd.times() : std::vector<double>{};
}

template <int D>
void ParticleVtkSeries<D>::adopt_written_steps(const std::vector<double>& times) {
    impl_->pvd.adopt_written(times);
}

template <int D>
std::size_t ParticleVtkSeries<D>::steps_written() const {
    return impl_ ? impl_->pvd.size() : 0;
}

template <int D>
fs::path ParticleVtkSeries<D>::pvd_path() const {
    return impl_ ? impl_->pvd.pvd_path() : fs::path{};
}

template class ParticleVtkSeries<2>;
template class ParticleVtkSeries<3>;

}  // namespace pilempm::io
