#include "io/writers/vtk_pile_writer.hpp"

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cmath>
#include <stdexcept>
#include <utility>

#include "io/writers/pvd_collection.hpp"

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

}  // namespace

struct PileVtkSeries::Impl {
    explicit Impl(PvdCollection collection) : pvd(std::move(collection)) {}

    PvdCollection pvd;
    int dim = 1;
    vtkIdType num_nodes = 0;
    std::size_t num_dofs = 0;
    std::size_t num_elements = 0;

    vtkNew<vtkUnstructuredGrid> grid;
    vtkNew<vtkDoubleArray> displacement, velocity, stress, time_value, contact;
    bool contact_added = false;
    vtkNew<vtkXMLUnstructuredGridWriter> writer;

    void build_geometry(const fem::PileMesh& mesh);
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

PileVtkSeries::PileVtkSeries(fs::path dir, const fem::PileMesh& mesh, std::string basename)
    : impl_(std::make_unique<Impl>(
          PvdCollection("PileVtkSeries", std::move(dir), std::move(basename)))) {
    impl_->build_geometry(mesh);
    impl_->pvd.create_directory();
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
    // The points never change: drop the range VTK caches on them after a write, so every
    // file reads the same whether it is a series' first (a resumed run's) or not.
    m.grid->GetPoints()->GetData()->GetInformation()->Clear();
    m.grid->GetPoints()->Modified();
    m.grid->Modified();

    const std::string file = m.pvd.next_step_file();
    const fs::path path = m.pvd.dir() / file;
    m.writer->SetFileName(path.c_str());
    if (m.writer->Write() != 1 || m.writer->GetErrorCode() != 0)
        throw std::runtime_error("PileVtkSeries: cannot write " + path.string());
    m.pvd.add(time, file);
}

void PileVtkSeries::write(double time, const std::vector<double>& displacement, const std::vector<double>& velocity,
                          const std::vector<double>& axial_stress, const std::vector<double>& contact_force) {
    if (!impl_) throw std::logic_error("PileVtkSeries::write on a moved-from series");
    Impl& m = *impl_;
    if (m.dim != 2 || contact_force.size() != m.num_dofs)
        throw std::invalid_argument("PileVtkSeries::write: contact forces need an axisymmetric mesh and " +
                                    std::to_string(m.num_dofs) + " values");
    if (!m.contact_added) {
        m.grid->GetPointData()->AddArray(init_array(m.contact, "contact_force_N", 3, m.num_nodes));
        m.contact_added = true;
    }
    for (vtkIdType n = 0; n < m.num_nodes; ++n)
        m.contact->SetTuple3(n, contact_force[2 * n], contact_force[2 * n + 1], 0.0);
    m.contact->Modified();
    write(time, displacement, velocity, axial_stress);
}

void PileVtkSeries::adopt_written_steps(const std::vector<double>& times) { impl_->pvd.adopt_written(times); }

void PileVtkSeries::finish() {
    if (impl_) impl_->pvd.finish();  // nothing to do when moved-from
}

std::size_t PileVtkSeries::steps_written() const { return impl_ ? impl_->pvd.size() : 0; }

fs::path PileVtkSeries::pvd_path() const {
    return impl_ ? impl_->pvd.pvd_path() : fs::path{};
}

}  // namespace pilempm::io
