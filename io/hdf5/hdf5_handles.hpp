#pragma once
// HDF5 plumbing shared by the io/ writers and readers (internal to io/*.cpp: public headers
// keep HDF5 out): an owning id, error checks whose messages name the file, and the few
// dataset/attribute writers the results file and the MPM checkpoint have in common.
#include <hdf5.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace pilempm::io::hdf5 {

// Owns one HDF5 identifier; closes it on every path out, exceptions included.
class Hid {
public:
    using Closer = herr_t (*)(hid_t);
    Hid(hid_t id, Closer closer) : id_(id), closer_(closer) {}
    ~Hid() { reset(); }
    Hid(const Hid&) = delete;
    Hid& operator=(const Hid&) = delete;
    Hid(Hid&& o) noexcept : id_(std::exchange(o.id_, -1)), closer_(o.closer_) {}
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

// HDF5 prints its error stack by default; the exception carries the reason instead, so
// printing is off while the guard lives (and the stack starts empty, so a failure reports
// its own reason, not an older one).
class QuietErrors {
public:
    QuietErrors();
    ~QuietErrors();
    QuietErrors(const QuietErrors&) = delete;
    QuietErrors& operator=(const QuietErrors&) = delete;

private:
    H5E_auto2_t func_ = nullptr;
    void* data_ = nullptr;
};

// Names the file in every message: "<subject>: <what> (<deepest HDF5 reason>)".
class Context {
public:
    explicit Context(std::string subject) : subject_(std::move(subject)) {}

    [[noreturn]] void fail(const std::string& what) const;
    Hid make(hid_t id, Hid::Closer closer, const std::string& what) const {
        if (id < 0) fail(what);
        return Hid(id, closer);
    }
    void check(herr_t status, const std::string& what) const {
        if (status < 0) fail(what);
    }

private:
    std::string subject_;
};

// File (little-endian, fixed) and memory types of the values we store.
template <typename T>
struct H5Of;
template <>
struct H5Of<double> {
    static hid_t file() { return H5T_IEEE_F64LE; }
    static hid_t memory() { return H5T_NATIVE_DOUBLE; }
    static constexpr H5T_class_t type_class = H5T_FLOAT;
    static constexpr const char* name = "64-bit float";
};
template <>
struct H5Of<int> {
    static hid_t file() { return H5T_STD_I32LE; }
    static hid_t memory() { return H5T_NATIVE_INT; }
    static constexpr H5T_class_t type_class = H5T_INTEGER;
    static constexpr const char* name = "32-bit integer";
};
template <>
struct H5Of<long long> {
    static hid_t file() { return H5T_STD_I64LE; }
    static hid_t memory() { return H5T_NATIVE_LLONG; }
    static constexpr H5T_class_t type_class = H5T_INTEGER;
    static constexpr const char* name = "64-bit integer";
};

// Group `name` under parent; `path` is its full name for messages.
Hid create_group(const Context& c, hid_t parent, const std::string& name,
                 const std::string& path);

// rows x cols dataset (1-D when cols == 0) of row-major values, stored as file_type.
// checksum_chunk > 0 (1-D datasets only): chunked, at most that many values per chunk, with
// Fletcher32 checksums of the raw data. Returns the open dataset.
template <typename T>
Hid write_dataset(const Context& c, hid_t parent, const std::string& name,
                  const std::string& path, const T* values, hsize_t rows, hsize_t cols,
                  hid_t file_type, hsize_t checksum_chunk = 0) {
    const hsize_t dims[2] = {rows, cols};
    const hsize_t n = rows * (cols ? cols : 1);
    Hid space = c.make(H5Screate_simple(cols ? 2 : 1, dims, nullptr), H5Sclose,
                       "cannot create dataspace for " + path);
    const bool checksummed = checksum_chunk > 0;
    Hid dcpl = checksummed ? c.make(H5Pcreate(H5P_DATASET_CREATE), H5Pclose,
                                    "cannot create property list")
                           : Hid(-1, H5Pclose);
    if (checksummed && n > 0) {
        // Fletcher32 needs chunks; a chunk must stay below 4 GiB.
        const hsize_t chunk = std::min(n, checksum_chunk);
        c.check(H5Pset_chunk(dcpl.get(), 1, &chunk), "cannot set chunking of " + path);
        c.check(H5Pset_fletcher32(dcpl.get()), "cannot set checksum of " + path);
    }
    Hid set = c.make(H5Dcreate2(parent, name.c_str(), file_type, space.get(), H5P_DEFAULT,
                                checksummed ? dcpl.get() : H5P_DEFAULT, H5P_DEFAULT),
                     H5Dclose, "cannot create dataset " + path);
    // HDF5 rejects a null buffer even for zero elements.
    if (n > 0)
        c.check(H5Dwrite(set.get(), H5Of<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values),
                "cannot write dataset " + path);
    return set;
}

// Scalar attribute stored as file_type.
template <typename T>
void write_scalar_attribute(const Context& c, hid_t obj, const std::string& name, T value,
                            hid_t file_type) {
    Hid space = c.make(H5Screate(H5S_SCALAR), H5Sclose, "cannot create dataspace");
    Hid attr = c.make(
        H5Acreate2(obj, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT),
        H5Aclose, "cannot create attribute " + name);
    c.check(H5Awrite(attr.get(), H5Of<T>::memory(), &value), "cannot write attribute " + name);
}

enum class StringStorage {
    Variable,         // variable-length: h5py reads them back as str, not bytes
    FixedNullPadded,  // fixed-length: kept in the (checksummed) object header, not the heap
};

// UTF-8 string attribute: a scalar (values holds one string) or a 1-D array.
void write_string_attribute(const Context& c, hid_t obj, const std::string& name,
                            const std::vector<std::string>& values, bool scalar,
                            StringStorage storage);

// Flushes and closes the file, reporting either failure.
void flush_and_close(const Context& c, Hid& file);

}  // namespace pilempm::io::hdf5
