#include "io/vtk_pile_writer.hpp"

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace pilempm::io {

namespace fs = std::filesystem;

namespace {

struct CellShape {
    int vtk_type;
    int nodes;
};

CellShape cell_shape(fem::ElementKind kind) {
    switch (kind) {
        case fem::ElementKind::Rod2: return {VTK_LINE, 2};
        case fem::ElementKind::AxisymQuad4: return {VTK_QUAD, 4};
    }
    throw std::invalid_argument("PileVtkSeries: element kind without a VTK cell type");
}

vtkNew<vtkDoubleArray>& init_array(vtkNew<vtkDoubleArray>& a, const char* name, int components,
                                   vtkIdType tuples) {
    a->SetName(name);
    a->SetNumberOfComponents(components);
    a->SetNumberOfTuples(tuples);
    a->Fill(0.0);
    return a;
}

// Shortest text that reads back as the same double: the .pvd times must match write().
std::string format_double(double v) {
    char buf[64];
    auto res = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, res.ptr);
}

std::string xml_escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

}  // namespace

struct PileVtkSeries::Impl {
    struct Step {
        double time;
        std::string file;  // relative to dir, as the .pvd lists it
    };

    fs::path dir;
    std::string basename;
    int dim = 1;
    vtkIdType num_nodes = 0;
    std::size_t num_dofs = 0;
    std::size_t num_elements = 0;

    vtkNew<vtkUnstructuredGrid> grid;
    vtkNew<vtkDoubleArray> displacement, velocity, stress, time_value;
    vtkNew<vtkXMLUnstructuredGridWriter> writer;

    std::vector<Step> steps;
    std::size_t steps_in_pvd = 0;
    bool pvd_written = false;

    void build_geometry(const fem::PileMesh& mesh);
    void write_pvd() const;
};

void PileVtkSeries::Impl::build_geometry(const fem::PileMesh& mesh) {
    if (mesh.dim != 1 && mesh.dim != 2)
        throw std::invalid_argument("PileVtkSeries: mesh.dim must be 1 or 2");
    if (mesh.coordinates.size() % static_cast<std::size_t>(mesh.dim) != 0)
        throw std::invalid_argument("PileVtkSeries: coordinates are not a multiple of dim");
    dim = mesh.dim;
    num_nodes = mesh.num_nodes();
    num_dofs = mesh.coordinates.size();

    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(num_nodes);
    for (vtkIdType n = 0; n < num_nodes; ++n) {
        // Axial coordinate on y so rod and axisymmetric meshes share one "up" in ParaView.
        const double r = dim == 2 ? mesh.coordinates[2 * n] : 0.0;
        points->SetPoint(n, r, mesh.z(static_cast<int>(n)), 0.0);
    }
    grid->SetPoints(points);

    num_elements = 0;
    for (const auto& block : mesh.blocks) num_elements += block.num_elements();
    grid->Allocate(static_cast<vtkIdType>(num_elements));
    for (const auto& block : mesh.blocks) {
        const CellShape shape = cell_shape(block.kind);
        if (block.nodes_per_element != shape.nodes ||
            block.connectivity.size() % static_cast<std::size_t>(shape.nodes) != 0)
            throw std::invalid_argument(std::string("PileVtkSeries: malformed block of kind ") +
                                        fem::element_kind_name(block.kind));
        vtkIdType ids[4];
        for (std::size_t e = 0; e < block.connectivity.size(); e += shape.nodes) {
            for (int a = 0; a < shape.nodes; ++a) {
                const int node = block.connectivity[e + a];
                if (node < 0 || node >= num_nodes)
                    throw std::invalid_argument("PileVtkSeries: connectivity node out of range");
                ids[a] = node;
            }
            grid->InsertNextCell(shape.vtk_type, shape.nodes, ids);
        }
    }

    // Active vectors = displacement, so ParaView's "Warp By Vector" picks it by default.
    grid->GetPointData()->SetVectors(init_array(displacement, "displacement", 3, num_nodes));
    grid->GetPointData()->AddArray(init_array(velocity, "velocity", 3, num_nodes));
    grid->GetCellData()->SetScalars(
        init_array(stress, "axial_stress_Pa", 1, static_cast<vtkIdType>(num_elements)));
    // "TimeValue" field data lets ParaView show the time of a single .vtu opened alone.
    grid->GetFieldData()->AddArray(init_array(time_value, "TimeValue", 1, 1));

    writer->SetInputData(grid);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();  // raw binary: no base64 overhead
    writer->SetCompressorTypeToZLib();
    writer->SetHeaderTypeToUInt64();
}

void PileVtkSeries::Impl::write_pvd() const {
    const fs::path pvd = dir / (basename + ".pvd");
    const fs::path tmp = dir / (basename + ".pvd.tmp");
    {
        std::ofstream out(tmp, std::ios::trunc);
        out << "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
               "  <Collection>\n";
        for (const Step& s : steps)
            out << "    <DataSet timestep=\"" << format_double(s.time)
                << "\" group=\"\" part=\"0\" file=\"" << xml_escape(s.file) << "\"/>\n";
        out << "  </Collection>\n</VTKFile>\n";
        out.close();
        if (!out) throw std::runtime_error("PileVtkSeries: cannot write " + tmp.string());
    }
    // Rename so a reader never sees a half-written collection.
    std::error_code ec;
    fs::rename(tmp, pvd, ec);
    if (ec) throw std::runtime_error("PileVtkSeries: cannot write " + pvd.string() + ": " +
                                     ec.message());
}

PileVtkSeries::PileVtkSeries(fs::path dir, const fem::PileMesh& mesh, std::string basename)
    : impl_(std::make_unique<Impl>()) {
    if (basename.empty() || basename.find_first_of("/\\") != std::string::npos)
        throw std::invalid_argument("PileVtkSeries: basename must be a plain file name");
    impl_->dir = std::move(dir);
    impl_->basename = std::move(basename);
    impl_->build_geometry(mesh);
    std::error_code ec;
    fs::create_directories(impl_->dir, ec);
    if (ec) throw std::runtime_error("PileVtkSeries: cannot create " + impl_->dir.string() +
                                     ": " + ec.message());
}

PileVtkSeries::~PileVtkSeries() {
    try {
        finish();
    } catch (...) {
        // Destructors must not throw; a caller who cares calls finish() itself.
    }
}

PileVtkSeries::PileVtkSeries(PileVtkSeries&&) noexcept = default;
PileVtkSeries& PileVtkSeries::operator=(PileVtkSeries&&) noexcept = default;

void PileVtkSeries::write(double time, const std::vector<double>& displacement,
                          const std::vector<double>& velocity,
                          const std::vector<double>& axial_stress) {
    if (!impl_) throw std::logic_error("PileVtkSeries::write on a moved-from series");
    Impl& m = *impl_;
    if (displacement.size() != m.num_dofs || velocity.size() != m.num_dofs)
        throw std::invalid_argument("PileVtkSeries::write: displacement/velocity need " +
                                    std::to_string(m.num_dofs) + " values");
    if (axial_stress.size() != m.num_elements)
        throw std::invalid_argument("PileVtkSeries::write: axial_stress needs " +
                                    std::to_string(m.num_elements) + " values");
    if (!std::isfinite(time)) throw std::invalid_argument("PileVtkSeries::write: time not finite");

    for (vtkIdType n = 0; n < m.num_nodes; ++n) {
        // Axial DOF -> y, radial DOF (axisymmetric only) -> x, matching the point layout.
        const std::size_t i = static_cast<std::size_t>(n) * m.dim;
        const double ur = m.dim == 2 ? displacement[i] : 0.0;
        const double vr = m.dim == 2 ? velocity[i] : 0.0;
        m.displacement->SetTuple3(n, ur, displacement[i + m.dim - 1], 0.0);
        m.velocity->SetTuple3(n, vr, velocity[i + m.dim - 1], 0.0);
    }
    for (std::size_t e = 0; e < m.num_elements; ++e)
        m.stress->SetValue(static_cast<vtkIdType>(e), axial_stress[e]);
    m.time_value->SetValue(0, time);
    m.displacement->Modified();
    m.velocity->Modified();
    m.stress->Modified();
    m.time_value->Modified();
    m.grid->Modified();

    char name[32];
    std::snprintf(name, sizeof name, "_%06zu.vtu", m.steps.size());
    const std::string file = m.basename + name;
    const fs::path path = m.dir / file;
    m.writer->SetFileName(path.c_str());
    if (m.writer->Write() != 1 || m.writer->GetErrorCode() != 0)
        throw std::runtime_error("PileVtkSeries: cannot write " + path.string());
    m.steps.push_back({time, file});
}

void PileVtkSeries::finish() {
    if (!impl_) return;  // moved-from
    if (impl_->pvd_written && impl_->steps_in_pvd == impl_->steps.size()) return;
    impl_->write_pvd();
    impl_->pvd_written = true;
    impl_->steps_in_pvd = impl_->steps.size();
}

std::size_t PileVtkSeries::steps_written() const { return impl_ ? impl_->steps.size() : 0; }

fs::path PileVtkSeries::pvd_path() const {
    return impl_ ? impl_->dir / (impl_->basename + ".pvd") : fs::path{};
}

}  // namespace pilempm::io
