#include "io/hdf5/hdf5_results.hpp"

#include "io/hdf5/hdf5_handles.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace pilempm::io {

namespace {

using hdf5::Hid;
using hdf5::H5Of;

// The results file is written in native types (h5py reads them as such).
class Writer : public hdf5::Context {
public:
    explicit Writer(const std::string& file) : hdf5::Context("HDF5 results file " + file) {}

    Hid create_group(hid_t parent, const std::string& name, const std::string& path) const {
        // Checked up front: a duplicate name is a caller error worth a clear message.
        if (H5Lexists(parent, name.c_str(), H5P_DEFAULT) > 0) fail("duplicate name " + path);
        return hdf5::create_group(*this, parent, name, path);
    }

    // rows x cols dataset (1-D when cols == 0), row-major values.
    template <typename T>
    void dataset(hid_t parent, const std::string& name, const std::string& path, const T* values,
                 hsize_t rows, hsize_t cols) const {
        if (H5Lexists(parent, name.c_str(), H5P_DEFAULT) > 0) fail("duplicate name " + path);
        hdf5::write_dataset(*this, parent, name, path, values, rows, cols, H5Of<T>::memory());
    }

    template <typename T>
    void scalar_attribute(hid_t obj, const std::string& name, T value) const {
        hdf5::write_scalar_attribute(*this, obj, name, value, H5Of<T>::memory());
    }

    // Variable-length UTF-8 strings: h5py reads them back as str, not bytes.
    void string_attribute(hid_t obj, const std::string& name,
                          const std::vector<std::string>& values, bool scalar) const {
        hdf5::write_string_attribute(*this, obj, name, values, scalar, hdf5::StringStorage::Variable);
    }
};

void write_table(const Writer& w, hid_t root, const Table& table) {
    const std::string group_name = hdf5_object_name(table.name);
    const std::string path = "/" + group_name;
    if (group_name.empty()) w.fail("table without a name");
    Hid group = w.create_group(root, group_name, path);
    std::vector<std::string> names;
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
        names.push_back(hdf5_object_name(table.columns[c]));
        if (names.back().empty()) w.fail("table " + table.name + " has an unnamed column");
        const auto& col = table.data[c];
        w.dataset(group.get(), names.back(), path + "/" + names.back(), col.data(), col.size(), 0);
    }
    w.string_attribute(group.get(), "columns", names, false);
}

void write_mesh(const Writer& w, hid_t root, const fem::PileMesh& mesh) {
    Hid group = w.create_group(root, "mesh", "/mesh");
    const hsize_t dim = static_cast<hsize_t>(mesh.dim);
    w.scalar_attribute(group.get(), "dim", mesh.dim);
    w.dataset(group.get(), "coordinates", "/mesh/coordinates", mesh.coordinates.data(),
              mesh.coordinates.size() / dim, dim);
    for (std::size_t k = 0; k < mesh.blocks.size(); ++k) {
        const auto& block = mesh.blocks[k];
        const std::string name = "block_" + std::to_string(k);
        const hsize_t nen = static_cast<hsize_t>(block.nodes_per_element);
        w.dataset(group.get(), name, "/mesh/" + name, block.connectivity.data(),
                  block.connectivity.size() / nen, nen);
        Hid set = w.make(H5Dopen2(group.get(), name.c_str(), H5P_DEFAULT), H5Dclose,
                         "cannot reopen /mesh/" + name);
        w.string_attribute(set.get(), "kind", {fem::element_kind_name(block.kind)}, true);
    }
    w.dataset(group.get(), "head_nodes", "/mesh/head_nodes", mesh.head_nodes.data(),
              mesh.head_nodes.size(), 0);
    w.dataset(group.get(), "toe_nodes", "/mesh/toe_nodes", mesh.toe_nodes.data(),
              mesh.toe_nodes.size(), 0);
}

void write_final_state(const Writer& w, hid_t root, const fem::PileMesh& mesh,
                       const std::vector<double>& displacement,
                       const std::vector<double>& velocity,
                       const std::vector<double>& axial_stress) {
    const std::size_t dofs = mesh.coordinates.size();
    const std::size_t elements = axial_stress.size();  // checked by validate()
    Hid group = w.create_group(root, "final_state", "/final_state");
    const hsize_t dim = static_cast<hsize_t>(mesh.dim);
    w.dataset(group.get(), "displacement", "/final_state/displacement", displacement.data(),
              dofs / dim, dim);
    w.dataset(group.get(), "velocity", "/final_state/velocity", velocity.data(), dofs / dim, dim);
    w.dataset(group.get(), "axial_stress_Pa", "/final_state/axial_stress_Pa", axial_stress.data(),
              elements, 0);
}

// Input errors are found before the file is touched, so an existing file survives them.
void validate(const Writer& w, const std::vector<Table>& tables, const fem::PileMesh& mesh,
              const std::vector<double>& displacement, const std::vector<double>& velocity,
              const std::vector<double>& axial_stress) {
    if (mesh.dim < 1 || mesh.coordinates.size() % static_cast<std::size_t>(mesh.dim) != 0)
        w.fail("mesh coordinates do not match mesh.dim");
    const std::size_t dofs = mesh.coordinates.size();
    std::size_t elements = 0;
    for (const auto& block : mesh.blocks) elements += block.num_elements();
    const bool no_state = displacement.empty() && velocity.empty() && axial_stress.empty();
    if (!no_state && (displacement.size() != dofs || velocity.size() != dofs))
        w.fail("final displacement/velocity need " + std::to_string(dofs) + " values");
    if (!no_state && axial_stress.size() != elements)
        w.fail("final axial stress needs " + std::to_string(elements) + " values");
    for (const auto& block : mesh.blocks)
        if (block.nodes_per_element < 1 ||
            block.connectivity.size() % static_cast<std::size_t>(block.nodes_per_element) != 0)
            w.fail("mesh block connectivity does not match nodes_per_element");
    for (const Table& table : tables)
        if (table.data.size() != table.columns.size())
            w.fail("table " + table.name + " has " + std::to_string(table.columns.size()) +
                   " column names but " + std::to_string(table.data.size()) + " data columns");
}

void write_file(const Writer& w, const std::filesystem::path& file,
                const std::vector<Table>& tables, const fem::PileMesh& mesh,
                const std::vector<double>& displacement, const std::vector<double>& velocity,
                const std::vector<double>& axial_stress,
                const std::vector<std::pair<std::string, double>>& attributes,
                const std::vector<std::pair<std::string, std::string>>& text_attributes) {
    Hid h5 = w.make(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                    "cannot create file");
    for (const Table& table : tables) write_table(w, h5.get(), table);
    write_mesh(w, h5.get(), mesh);
    // A study of many blows (drivability) has no single final state: then all three are empty.
    if (!displacement.empty()) write_final_state(w, h5.get(), mesh, displacement, velocity, axial_stress);
    // Attributes on the file id land on the root group.
    for (const auto& [name, value] : attributes) w.scalar_attribute(h5.get(), name, value);
    for (const auto& [name, value] : text_attributes)
        w.string_attribute(h5.get(), name, {value}, true);
    hdf5::flush_and_close(w, h5);
}

}  // namespace

std::string hdf5_object_name(const std::string& name) {
    std::string out = name;
    std::replace(out.begin(), out.end(), '/', '_');
    return out;
}

void write_results_h5(const std::filesystem::path& file, const std::vector<Table>& tables,
                      const fem::PileMesh& mesh, const std::vector<double>& displacement,
                      const std::vector<double>& velocity,
                      const std::vector<double>& axial_stress,
                      const std::vector<std::pair<std::string, double>>& attributes,
                      const std::vector<std::pair<std::string, std::string>>& text_attributes) {
    const hdf5::QuietErrors quiet;
    const Writer w(file.string());
    validate(w, tables, mesh, displacement, velocity, axial_stress);
    try {
        write_file(w, file, tables, mesh, displacement, velocity, axial_stress, attributes,
                   text_attributes);
    } catch (...) {
        // A half-written results file would look valid to later tools; remove it. All
        // handles are closed by now (RAII in write_file).
        std::error_code ec;
        std::filesystem::remove(file, ec);
        throw;
    }
}

}  // namespace pilempm::io
