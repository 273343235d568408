#include "io/hdf5_results.hpp"

#include <hdf5.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace pilempm::io {

namespace {

// Owns one HDF5 identifier; closes it on every path out, exceptions included.
class Hid {
public:
    using Closer = herr_t (*)(hid_t);
    Hid(hid_t id, Closer closer) : id_(id), closer_(closer) {}
    ~Hid() { reset(); }
    Hid(const Hid&) = delete;
    Hid& operator=(const Hid&) = delete;
    hid_t get() const { return id_; }
    // Explicit close, so a failing flush of the file is reported, not swallowed.
    herr_t reset() {
        herr_t status = 0;
        if (id_ >= 0) status = closer_(id_);
        id_ = -1;
        return status;
    }

private:
    hid_t id_;
    Closer closer_;
};

template <typename T>
hid_t native_type();
template <>
hid_t native_type<double>() { return H5T_NATIVE_DOUBLE; }
template <>
hid_t native_type<int>() { return H5T_NATIVE_INT; }

// The deepest entry of HDF5's error stack says why (e.g. errno text of a failed open).
herr_t keep_deepest(unsigned n, const H5E_error2_t* err, void* data) {
    auto* deepest = static_cast<std::pair<unsigned, std::string>*>(data);
    if (err->desc && (deepest->second.empty() || n >= deepest->first)) *deepest = {n, err->desc};
    return 0;
}

std::string hdf5_error_reason() {
    std::pair<unsigned, std::string> deepest{0, {}};
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, keep_deepest, &deepest);
    H5Eclear2(H5E_DEFAULT);
    return deepest.second;
}

// HDF5 prints its error stack by default; the exception carries the reason instead, so
// printing is off while we write and restored afterwards.
class QuietHdf5Errors {
public:
    QuietHdf5Errors() {
        H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    }
    ~QuietHdf5Errors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
    QuietHdf5Errors(const QuietHdf5Errors&) = delete;
    QuietHdf5Errors& operator=(const QuietHdf5Errors&) = delete;

private:
    H5E_auto2_t func_ = nullptr;
    void* data_ = nullptr;
};

class Writer {
public:
    explicit Writer(std::string file) : file_(std::move(file)) {}

    [[noreturn]] void fail(const std::string& what) const {
        const std::string reason = hdf5_error_reason();
        throw std::runtime_error("HDF5 results file " + file_ + ": " + what +
                                 (reason.empty() ? "" : " (" + reason + ")"));
    }
    Hid make(hid_t id, Hid::Closer closer, const std::string& what) const {
        if (id < 0) fail(what);
        return Hid(id, closer);
    }
    void check(herr_t status, const std::string& what) const {
        if (status < 0) fail(what);
    }

    Hid create_group(hid_t parent, const std::string& name, const std::string& path) const {
        // Checked up front: a duplicate name is a caller error worth a clear message.
        if (H5Lexists(parent, name.c_str(), H5P_DEFAULT) > 0) fail("duplicate name " + path);
        return make(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                    H5Gclose, "cannot create group " + path);
    }

    // rows x cols dataset (1-D when cols == 0), row-major values.
    template <typename T>
    void dataset(hid_t parent, const std::string& name, const std::string& path, const T* values,
                 hsize_t rows, hsize_t cols) const {
        if (H5Lexists(parent, name.c_str(), H5P_DEFAULT) > 0) fail("duplicate name " + path);
        const hsize_t dims[2] = {rows, cols};
        Hid space = make(H5Screate_simple(cols ? 2 : 1, dims, nullptr), H5Sclose,
                         "cannot create dataspace for " + path);
        Hid set = make(H5Dcreate2(parent, name.c_str(), native_type<T>(), space.get(),
                                  H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                       H5Dclose, "cannot create dataset " + path);
        // HDF5 rejects a null buffer even for zero elements.
        if (rows * (cols ? cols : 1) > 0)
            check(H5Dwrite(set.get(), native_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values),
                  "cannot write dataset " + path);
    }

    template <typename T>
    void scalar_attribute(hid_t obj, const std::string& name, T value) const {
        Hid space = make(H5Screate(H5S_SCALAR), H5Sclose, "cannot create dataspace");
        Hid attr = make(H5Acreate2(obj, name.c_str(), native_type<T>(), space.get(), H5P_DEFAULT,
                                   H5P_DEFAULT),
                        H5Aclose, "cannot create attribute " + name);
        check(H5Awrite(attr.get(), native_type<T>(), &value), "cannot write attribute " + name);
    }

    // Variable-length UTF-8 strings: h5py reads them back as str, not bytes.
    void string_attribute(hid_t obj, const std::string& name,
                          const std::vector<std::string>& values, bool scalar) const {
        Hid type = make(H5Tcopy(H5T_C_S1), H5Tclose, "cannot create string type");
        check(H5Tset_size(type.get(), H5T_VARIABLE), "cannot size string type");
        check(H5Tset_cset(type.get(), H5T_CSET_UTF8), "cannot set string charset");
        const hsize_t n = values.size();
        Hid space = make(scalar ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &n, nullptr),
                         H5Sclose, "cannot create dataspace for attribute " + name);
        Hid attr = make(
            H5Acreate2(obj, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
            H5Aclose, "cannot create attribute " + name);
        std::vector<const char*> ptrs;
        for (const auto& v : values) ptrs.push_back(v.c_str());
        if (!ptrs.empty())
            check(H5Awrite(attr.get(), type.get(), ptrs.data()), "cannot write attribute " + name);
    }

private:
    std::string file_;
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
    w.check(H5Fflush(h5.get(), H5F_SCOPE_LOCAL), "cannot flush");
    w.check(h5.reset(), "cannot close");
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
    const QuietHdf5Errors quiet;
    H5Eclear2(H5E_DEFAULT);  // so a failure reports its own reason, not an older one
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
