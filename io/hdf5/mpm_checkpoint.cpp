#include "io/hdf5/mpm_checkpoint.hpp"

#include "io/hdf5/hdf5_handles.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace pilempm::io {

namespace fs = std::filesystem;

namespace {

constexpr const char* kFormat = "pilempm-mpm-checkpoint";
constexpr const char* kTableFormat = "pilempm-tables";  // write_table_file
constexpr int kTableFormatVersion = 1;
constexpr int kFormatVersion = 5;  // 2: the affine velocity field C; 3: arrays and tables; 4: field; 5: pore water
// Datasets are chunked (Fletcher32 needs chunks; a chunk must stay below 4 GiB).
constexpr hsize_t kChunkValues = hsize_t{1} << 20;

using hdf5::H5Of;
using hdf5::Hid;

// Names the checkpoint in every message.
class Context : public hdf5::Context {
public:
    explicit Context(const std::string& file) : hdf5::Context("MPM checkpoint " + file) {}
};

// ---- writing ---------------------------------------------------------------------------

template <typename T>
Hid write_array(const Context& c, hid_t group, const std::string& name,
                const std::vector<T>& values) {
    // Fletcher32 checksums the raw data, so a corrupted checkpoint fails to read instead of
    // restarting from wrong values (metadata has its own checksums).
    return hdf5::write_dataset(c, group, name, "/particles/" + name, values.data(), values.size(),
                             0, H5Of<T>::file(), kChunkValues);
}

template <typename T>
void write_attribute(const Context& c, hid_t obj, const std::string& name, T value) {
    hdf5::write_scalar_attribute(c, obj, name, value, H5Of<T>::file());
}

// Fixed-length, null-padded UTF-8 strings: they live in the (checksummed) object header,
// unlike variable-length strings on the global heap.
void write_string_attribute(const Context& c, hid_t obj, const std::string& name,
                            const std::vector<std::string>& values, bool scalar) {
    hdf5::write_string_attribute(c, obj, name, values, scalar, hdf5::StringStorage::FixedNullPadded);
}

template <int D>
void validate(const Context& c, const mpm::Particles<D>& p) {
    const std::size_t n = p.size();
    auto need = [&](const char* what, std::size_t have, std::size_t per_point) {
        if (have != per_point * n)
            c.fail(std::string("Particles::") + what + " has " + std::to_string(have) +
                   " values, " + std::to_string(per_point * n) + " expected for " +
                   std::to_string(n) + " points");
    };
    if (p.state_stride < 0) c.fail("negative Particles::state_stride");
    need("x", p.x.size(), D);
    need("v", p.v.size(), D);
    need("volume", p.volume.size(), 1);
    need("volume0", p.volume0.size(), 1);
    need("C", p.C.size(), D * D);
    need("F", p.F.size(), D * D);
    need("domain0", p.domain0.size(), D * D);
    need("stress", p.stress.size(), 6);
    need("strain", p.strain.size(), 6);
    need("material", p.material.size(), 1);
    need("field", p.field.size(), 1);
    need("state", p.state.size(), static_cast<std::size_t>(p.state_stride));
    need("external_force", p.external_force.size(), D);
    need("porosity", p.porosity.size(), 1);
    need("pore_pressure", p.pore_pressure.size(), 1);
    need("w", p.w.size(), D);
}

void write_extras(const Context& c, hid_t root, const CheckpointExtras& extras) {
    Hid arrays = hdf5::create_group(c, root, "arrays", "/arrays");
    for (const auto& [name, values] : extras.arrays)
        hdf5::write_dataset(c, arrays.get(), name, "/arrays/" + name, values.data(), values.size(), 0,
                            H5Of<double>::file(), kChunkValues);
    Hid tables = hdf5::create_group(c, root, "tables", "/tables");
    for (const Table& t : extras.tables) {
        const std::string path = "/tables/" + t.name;
        Hid group = hdf5::create_group(c, tables.get(), t.name, path);
        for (std::size_t k = 0; k < t.columns.size(); ++k) {
            const std::string name = "column_" + std::to_string(k);
            hdf5::write_dataset(c, group.get(), name, path + "/" + name, t.data[k].data(), t.data[k].size(), 0,
                                H5Of<double>::file(), kChunkValues);
        }
        write_string_attribute(c, group.get(), "columns", t.columns, false);
    }
}

template <int D>
void write_file(const Context& c, const fs::path& file, const mpm::Particles<D>& p, double time,
                long step, const std::vector<std::pair<std::string, double>>& scalars,
                const std::string& fingerprint, const CheckpointExtras& extras) {
    // Format 1.8+ structures: superblock and object headers carry checksums.
    Hid fapl = c.make(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "cannot create property list");
    c.check(H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V18, H5F_LIBVER_LATEST),
            "cannot set file format");
    Hid h5 = c.make(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), H5Fclose,
                    "cannot create " + file.string());

    write_string_attribute(c, h5.get(), "format", {kFormat}, true);
    write_attribute(c, h5.get(), "format_version", kFormatVersion);
    write_attribute(c, h5.get(), "dimension", D);
    write_attribute(c, h5.get(), "num_points", static_cast<long long>(p.size()));
    write_attribute(c, h5.get(), "time", time);
    write_attribute(c, h5.get(), "step", static_cast<long long>(step));
    write_string_attribute(c, h5.get(), "fingerprint", {fingerprint}, true);

    Hid group = hdf5::create_group(c, h5.get(), "particles", "/particles");
    const hid_t g = group.get();
    write_array(c, g, "x", p.x);
    write_array(c, g, "v", p.v);
    write_array(c, g, "mass", p.mass);
    write_array(c, g, "volume", p.volume);
    write_array(c, g, "volume0", p.volume0);
    write_array(c, g, "C", p.C);
    write_array(c, g, "F", p.F);
    write_array(c, g, "domain0", p.domain0);
    write_array(c, g, "stress", p.stress);
    write_array(c, g, "strain", p.strain);
    write_array(c, g, "material", p.material);
    write_array(c, g, "field", p.field);
    {
        Hid state = write_array(c, g, "state", p.state);
        write_attribute(c, state.get(), "state_stride", p.state_stride);
    }
    write_array(c, g, "external_force", p.external_force);
    write_array(c, g, "porosity", p.porosity);
    write_array(c, g, "pore_pressure", p.pore_pressure);
    write_array(c, g, "w", p.w);
    group.reset();

    std::vector<std::string> names;
    std::vector<double> values;
    for (const auto& [name, value] : scalars) {
        names.push_back(name);
        values.push_back(value);
    }
    {
        Hid set = hdf5::write_dataset(c, h5.get(), "scalars", "/scalars", values.data(),
                                    values.size(), 0, H5Of<double>::file());
        write_string_attribute(c, set.get(), "names", names, false);
    }
    write_extras(c, h5.get(), extras);

    hdf5::flush_and_close(c, h5);
}

// Data must be on disk before the rename makes it the checkpoint; best effort on the
// directory entry afterwards.
void sync_path(const fs::path& path, bool directory, const Context& c) {
    const int fd = ::open(path.c_str(), directory ? (O_RDONLY | O_DIRECTORY) : O_RDONLY);
    if (fd < 0) {
        if (directory) return;
        c.fail("cannot open " + path.string() + " to sync it: " +
               std::error_code(errno, std::generic_category()).message());
    }
    const int status = ::fsync(fd);
    const int err = errno;
    ::close(fd);
    if (status != 0 && !directory)
        c.fail("cannot sync " + path.string() + ": " +
               std::error_code(err, std::generic_category()).message());
}

// ---- reading ---------------------------------------------------------------------------

std::string object_path(const std::string& parent, const std::string& name) {
    return parent == "/" ? "/" + name : parent + "/" + name;
}

Hid open_attribute(const Context& c, hid_t obj, const std::string& owner,
                   const std::string& name) {
    const std::string what = "attribute " + name + " of " + owner;
    if (H5Aexists(obj, name.c_str()) <= 0) c.fail("missing " + what);
    return c.make(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose, "cannot open " + what);
}

template <typename T>
T read_attribute(const Context& c, hid_t obj, const std::string& owner, const std::string& name) {
    const std::string what = "attribute " + name + " of " + owner;
    Hid attr = open_attribute(c, obj, owner, name);
    Hid space = c.make(H5Aget_space(attr.get()), H5Sclose, "cannot read " + what);
    Hid type = c.make(H5Aget_type(attr.get()), H5Tclose, "cannot read " + what);
    if (H5Sget_simple_extent_npoints(space.get()) != 1) c.fail(what + " is not a single value");
    if (H5Tget_class(type.get()) != H5Of<T>::type_class || H5Tget_size(type.get()) > sizeof(T))
        c.fail(what + " is not a " + H5Of<T>::name);
    T value{};
    c.check(H5Aread(attr.get(), H5Of<T>::memory(), &value), "cannot read " + what);
    return value;
}

std::vector<std::string> read_string_attribute(const Context& c, hid_t obj,
                                               const std::string& owner,
                                               const std::string& name) {
    const std::string what = "attribute " + name + " of " + owner;
    Hid attr = open_attribute(c, obj, owner, name);
    Hid space = c.make(H5Aget_space(attr.get()), H5Sclose, "cannot read " + what);
    Hid file_type = c.make(H5Aget_type(attr.get()), H5Tclose, "cannot read " + what);
    if (H5Tget_class(file_type.get()) != H5T_STRING) c.fail(what + " is not a string");
    const hssize_t count = H5Sget_simple_extent_npoints(space.get());
    if (count < 0) c.fail("cannot read " + what);
    const auto n = static_cast<std::size_t>(count);
    std::vector<std::string> out;
    if (n == 0) return out;

    Hid mem_type = c.make(H5Tcopy(H5T_C_S1), H5Tclose, "cannot create string type");
    c.check(H5Tset_cset(mem_type.get(), H5Tget_cset(file_type.get())), "cannot read " + what);
    if (H5Tis_variable_str(file_type.get()) > 0) {
        // Not what write_checkpoint writes, but other tools (h5py) might.
        c.check(H5Tset_size(mem_type.get(), H5T_VARIABLE), "cannot read " + what);
        std::vector<char*> ptrs(n, nullptr);
        c.check(H5Aread(attr.get(), mem_type.get(), ptrs.data()), "cannot read " + what);
        for (char* s : ptrs) out.emplace_back(s ? s : "");
        H5Dvlen_reclaim(mem_type.get(), space.get(), H5P_DEFAULT, ptrs.data());
        return out;
    }
    const std::size_t width = H5Tget_size(file_type.get());
    if (width == 0) c.fail("cannot read " + what);
    c.check(H5Tset_size(mem_type.get(), width), "cannot read " + what);
    c.check(H5Tset_strpad(mem_type.get(), H5T_STR_NULLPAD), "cannot read " + what);
    std::vector<char> buffer(n * width, '\0');
    c.check(H5Aread(attr.get(), mem_type.get(), buffer.data()), "cannot read " + what);
    for (std::size_t k = 0; k < n; ++k) {
        const char* begin = buffer.data() + k * width;
        std::size_t len = width;
        while (len > 0 && begin[len - 1] == '\0') --len;  // padding
        out.emplace_back(begin, len);
    }
    return out;
}

std::string read_single_string(const Context& c, hid_t obj, const std::string& owner,
                               const std::string& name) {
    auto values = read_string_attribute(c, obj, owner, name);
    if (values.size() != 1) c.fail("attribute " + name + " of " + owner + " is not one string");
    return values.front();
}

// A 1-D dataset of exactly `expected` values; `layout` says why that many (for the message).
template <typename T>
std::vector<T> read_array(const Context& c, hid_t parent, const std::string& parent_path,
                          const std::string& name, std::size_t expected,
                          const std::string& layout) {
    const std::string path = object_path(parent_path, name);
    if (H5Lexists(parent, name.c_str(), H5P_DEFAULT) <= 0) c.fail("missing dataset " + path);
    Hid set = c.make(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), H5Dclose,
                     "cannot open dataset " + path);
    Hid space = c.make(H5Dget_space(set.get()), H5Sclose, "cannot read dataset " + path);
    Hid type = c.make(H5Dget_type(set.get()), H5Tclose, "cannot read dataset " + path);
    if (H5Sget_simple_extent_ndims(space.get()) != 1) c.fail(path + " is not a 1-D dataset");
    hsize_t n = 0;
    c.check(H5Sget_simple_extent_dims(space.get(), &n, nullptr), "cannot read dataset " + path);
    if (n != expected)
        c.fail(path + " has " + std::to_string(n) + " values, " + std::to_string(expected) +
               " expected (" + layout + ")");
    if (H5Tget_class(type.get()) != H5Of<T>::type_class || H5Tget_size(type.get()) > sizeof(T) ||
        (H5Of<T>::type_class == H5T_FLOAT && H5Tget_size(type.get()) != sizeof(T)))
        c.fail(path + " is not " + H5Of<T>::name + " data");
    std::vector<T> values(expected);
    if (expected > 0)
        c.check(H5Dread(set.get(), H5Of<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT,
                        values.data()),
                "cannot read dataset " + path + " (corrupt?)");
    return values;
}

// The names of the links in a group (in name order: they are looked up by name).
std::vector<std::string> member_names(const Context& c, hid_t group, const std::string& path) {
    H5G_info_t info;
    c.check(H5Gget_info(group, &info), "cannot read group " + path);
    std::vector<std::string> names;
    for (hsize_t k = 0; k < info.nlinks; ++k) {
        const ssize_t len = H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, k, nullptr, 0, H5P_DEFAULT);
        if (len < 0) c.fail("cannot read group " + path);
        std::string name(static_cast<std::size_t>(len), '\0');
        H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, k, name.data(), name.size() + 1, H5P_DEFAULT);
        names.push_back(name);
    }
    return names;
}

// The length of a 1-D dataset (the arrays and table columns are whatever length they were).
std::size_t dataset_length(const Context& c, hid_t parent, const std::string& name, const std::string& path) {
    Hid set = c.make(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), H5Dclose, "cannot open dataset " + path);
    Hid space = c.make(H5Dget_space(set.get()), H5Sclose, "cannot read dataset " + path);
    if (H5Sget_simple_extent_ndims(space.get()) != 1) c.fail(path + " is not a 1-D dataset");
    hsize_t n = 0;
    c.check(H5Sget_simple_extent_dims(space.get(), &n, nullptr), "cannot read dataset " + path);
    return static_cast<std::size_t>(n);
}

CheckpointExtras read_extras(const Context& c, hid_t root) {
    CheckpointExtras extras;
    if (H5Lexists(root, "arrays", H5P_DEFAULT) <= 0) c.fail("missing group /arrays");
    Hid arrays = c.make(H5Gopen2(root, "arrays", H5P_DEFAULT), H5Gclose, "cannot open group /arrays");
    for (const auto& name : member_names(c, arrays.get(), "/arrays")) {
        const std::string path = "/arrays/" + name;
        const std::size_t n = dataset_length(c, arrays.get(), name, path);
        extras.arrays.emplace_back(name, read_array<double>(c, arrays.get(), "/arrays", name, n, "its own length"));
    }
    if (H5Lexists(root, "tables", H5P_DEFAULT) <= 0) c.fail("missing group /tables");
    Hid tables = c.make(H5Gopen2(root, "tables", H5P_DEFAULT), H5Gclose, "cannot open group /tables");
    for (const auto& name : member_names(c, tables.get(), "/tables")) {
        const std::string path = "/tables/" + name;
        Hid group = c.make(H5Gopen2(tables.get(), name.c_str(), H5P_DEFAULT), H5Gclose, "cannot open group " + path);
        Table t(name, read_string_attribute(c, group.get(), path, "columns"));
        std::size_t rows = 0;
        for (std::size_t k = 0; k < t.columns.size(); ++k) {
            const std::string column = "column_" + std::to_string(k);
            if (H5Lexists(group.get(), column.c_str(), H5P_DEFAULT) <= 0) c.fail("missing dataset " + path + "/" + column);
            if (k == 0) rows = dataset_length(c, group.get(), column, path + "/" + column);
            t.data[k] = read_array<double>(c, group.get(), path, column, rows, "as many rows as column_0");
        }
        extras.tables.push_back(std::move(t));
    }
    return extras;
}

template <int D>
CheckpointInfo read_file(const Context& c, const fs::path& file, mpm::Particles<D>& p) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) c.fail("no such file");
    if (H5Fis_hdf5(file.c_str()) <= 0) c.fail("not an HDF5 file (corrupt or truncated?)");
    Hid h5 = c.make(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                    "cannot open (corrupt or truncated?)");
    const hid_t root = h5.get();

    if (H5Aexists(root, "format") <= 0 || read_single_string(c, root, "/", "format") != kFormat)
        c.fail(std::string("not an MPM checkpoint (root attribute format is not \"") + kFormat +
               "\")");
    const int version = read_attribute<int>(c, root, "/", "format_version");
    if (version < 2 || version > kFormatVersion)
        c.fail("checkpoint format version " + std::to_string(version) + ", this build reads " +
               std::to_string(kFormatVersion));

    CheckpointInfo info;
    info.dimension = read_attribute<int>(c, root, "/", "dimension");
    if (info.dimension != D)
        c.fail("checkpoint of " + std::to_string(info.dimension) +
               "-D particles cannot be read into Particles<" + std::to_string(D) + ">");
    const long long num_points = read_attribute<long long>(c, root, "/", "num_points");
    if (num_points < 0) c.fail("negative num_points " + std::to_string(num_points));
    info.time = read_attribute<double>(c, root, "/", "time");
    info.step = static_cast<long>(read_attribute<long long>(c, root, "/", "step"));
    info.case_fingerprint = read_single_string(c, root, "/", "fingerprint");

    if (H5Lexists(root, "particles", H5P_DEFAULT) <= 0) c.fail("missing group /particles");
    Hid group = c.make(H5Gopen2(root, "particles", H5P_DEFAULT), H5Gclose,
                       "cannot open group /particles");
    const hid_t g = group.get();
    const std::string gp = "/particles";
    const auto n = static_cast<std::size_t>(num_points);
    const std::string points = " for " + std::to_string(n) + " points";
    const std::string vec = std::to_string(D) + " per point" + points;
    const std::string mat = std::to_string(D * D) + " per point" + points;
    const std::string one = "1 per point" + points;
    const std::string six = "6 per point" + points;

    // Everything is read into a fresh container first: p is untouched on failure.
    mpm::Particles<D> q;
    q.x = read_array<double>(c, g, gp, "x", D * n, vec);
    q.v = read_array<double>(c, g, gp, "v", D * n, vec);
    q.mass = read_array<double>(c, g, gp, "mass", n, one);
    q.volume = read_array<double>(c, g, gp, "volume", n, one);
    q.volume0 = read_array<double>(c, g, gp, "volume0", n, one);
    q.C = read_array<double>(c, g, gp, "C", D * D * n, mat);
    q.F = read_array<double>(c, g, gp, "F", D * D * n, mat);
    q.domain0 = read_array<double>(c, g, gp, "domain0", D * D * n, mat);
    q.stress = read_array<double>(c, g, gp, "stress", 6 * n, six);
    q.strain = read_array<double>(c, g, gp, "strain", 6 * n, six);
    q.material = read_array<int>(c, g, gp, "material", n, one);
    // Before format 4 every point moved with the grid's first velocity field.
    q.field = version >= 4 ? read_array<int>(c, g, gp, "field", n, one) : std::vector<int>(n, 0);
    {
        if (H5Lexists(g, "state", H5P_DEFAULT) <= 0) c.fail("missing dataset /particles/state");
        Hid state = c.make(H5Dopen2(g, "state", H5P_DEFAULT), H5Dclose,
                           "cannot open dataset /particles/state");
        q.state_stride = read_attribute<int>(c, state.get(), "/particles/state", "state_stride");
        if (q.state_stride < 0)
            c.fail("negative state_stride " + std::to_string(q.state_stride) +
                   " on /particles/state");
    }
    q.state = read_array<double>(c, g, gp, "state", static_cast<std::size_t>(q.state_stride) * n,
                                 "state_stride " + std::to_string(q.state_stride) +
                                     " per point" + points);
    q.external_force = read_array<double>(c, g, gp, "external_force", D * n, vec);
    // Before format 5 there was no pore water.
    q.porosity = version >= 5 ? read_array<double>(c, g, gp, "porosity", n, one) : std::vector<double>(n, 0.0);
    q.pore_pressure = version >= 5 ? read_array<double>(c, g, gp, "pore_pressure", n, one) : std::vector<double>(n, 0.0);
    q.w = version >= 5 ? read_array<double>(c, g, gp, "w", D * n, vec) : std::vector<double>(D * n, 0.0);
    q.dstrain.assign(6 * n, 0.0);
    group.reset();

    if (H5Lexists(root, "scalars", H5P_DEFAULT) <= 0) c.fail("missing dataset /scalars");
    std::vector<std::string> names;
    {
        Hid set = c.make(H5Dopen2(root, "scalars", H5P_DEFAULT), H5Dclose,
                         "cannot open dataset /scalars");
        names = read_string_attribute(c, set.get(), "/scalars", "names");
    }
    const std::vector<double> values =
        read_array<double>(c, root, "/", "scalars", names.size(), "one per name");
    for (std::size_t k = 0; k < names.size(); ++k) info.scalars.emplace_back(names[k], values[k]);
    if (version >= 3) info.extras = read_extras(c, root);

    c.check(h5.reset(), "cannot close");
    p = std::move(q);
    return info;
}


// Writes `file` + ".tmp" through `write`, syncs it and renames it over `file`: a crash
// mid-write leaves the previous file intact.
template <typename Write>
void write_atomically(const Context& c, const fs::path& file, Write&& write) {
    fs::path tmp = file;
    tmp += ".tmp";
    try {
        write(tmp);
        sync_path(tmp, false, c);
    } catch (...) {
        // All handles are closed by now (RAII in the writer); the old file is untouched.
        std::error_code ec;
        fs::remove(tmp, ec);
        throw;
    }
    std::error_code ec;
    fs::rename(tmp, file, ec);  // atomic replacement on POSIX
    if (ec) {
        std::error_code ignored;
        fs::remove(tmp, ignored);
        c.fail("cannot rename " + tmp.string() + " over it: " + ec.message());
    }
    const fs::path dir = file.parent_path();
    sync_path(dir.empty() ? fs::path(".") : dir, true, c);
}

void write_table_contents(const Context& c, const fs::path& file, const std::vector<Table>& tables) {
    Hid fapl = c.make(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "cannot create property list");
    c.check(H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V18, H5F_LIBVER_LATEST), "cannot set file format");
    Hid h5 = c.make(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), H5Fclose,
                    "cannot create " + file.string());
    write_string_attribute(c, h5.get(), "format", {kTableFormat}, true);
    write_attribute(c, h5.get(), "format_version", kTableFormatVersion);
    CheckpointExtras extras;
    extras.tables = tables;
    write_extras(c, h5.get(), extras);
    hdf5::flush_and_close(c, h5);
}

}  // namespace

template <int D>
void write_checkpoint(const fs::path& file, const mpm::Particles<D>& p, double time, long step,
                      const std::vector<std::pair<std::string, double>>& scalars,
                      const std::string& case_fingerprint, const CheckpointExtras& extras) {
    const hdf5::QuietErrors quiet;
    const Context c(file.string());
    validate(c, p);  // before any file is touched
    write_atomically(c, file, [&](const fs::path& tmp) { write_file(c, tmp, p, time, step, scalars, case_fingerprint, extras); });
}

void write_table_file(const fs::path& file, const std::vector<Table>& tables) {
    const hdf5::QuietErrors quiet;
    const Context c(file.string());
    for (const Table& t : tables)
        for (const auto& column : t.data)
            if (column.size() != t.rows()) c.fail("table " + t.name + " has columns of different lengths");
    write_atomically(c, file, [&](const fs::path& tmp) { write_table_contents(c, tmp, tables); });
}

std::vector<Table> read_table_file(const fs::path& file) {
    const hdf5::QuietErrors quiet;
    const Context c(file.string());
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) c.fail("no such file");
    if (H5Fis_hdf5(file.c_str()) <= 0) c.fail("not an HDF5 file (corrupt or truncated?)");
    Hid h5 = c.make(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "cannot open (corrupt or truncated?)");
    const hid_t root = h5.get();
    if (H5Aexists(root, "format") <= 0 || read_single_string(c, root, "/", "format") != kTableFormat)
        c.fail(std::string("not a pilempm table file (root attribute format is not \"") + kTableFormat + "\")");
    const int version = read_attribute<int>(c, root, "/", "format_version");
    if (version != kTableFormatVersion)
        c.fail("table file format version " + std::to_string(version) + ", this build reads " +
               std::to_string(kTableFormatVersion));
    std::vector<Table> tables = read_extras(c, root).tables;
    c.check(h5.reset(), "cannot close");
    return tables;
}

template <int D>
CheckpointInfo read_checkpoint(const fs::path& file, mpm::Particles<D>& p) {
    const hdf5::QuietErrors quiet;
    const Context c(file.string());
    return read_file(c, file, p);
}

template void write_checkpoint<2>(const fs::path&, const mpm::Particles<2>&, double, long,
                                  const std::vector<std::pair<std::string, double>>&,
                                  const std::string&, const CheckpointExtras&);
template void write_checkpoint<3>(const fs::path&, const mpm::Particles<3>&, double, long,
                                  const std::vector<std::pair<std::string, double>>&,
                                  const std::string&, const CheckpointExtras&);
template CheckpointInfo read_checkpoint<2>(const fs::path&, mpm::Particles<2>&);
template CheckpointInfo read_checkpoint<3>(const fs::path&, mpm::Particles<3>&);

}  // namespace pilempm::io
