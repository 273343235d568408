#include "io/hdf5/hdf5_handles.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>

namespace pilempm::io::hdf5 {

namespace {

// The deepest entry of HDF5's error stack says why (e.g. errno text of a failed open,
// "truncated file").
herr_t keep_deepest(unsigned n, const H5E_error2_t* err, void* data) {
    auto* deepest = static_cast<std::pair<unsigned, std::string>*>(data);
    if (err->desc && (deepest->second.empty() || n >= deepest->first)) *deepest = {n, err->desc};
    return 0;
}

std::string error_reason() {
    std::pair<unsigned, std::string> deepest{0, {}};
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, keep_deepest, &deepest);
    H5Eclear2(H5E_DEFAULT);
    return deepest.second;
}

}  // namespace

QuietErrors::QuietErrors() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    H5Eclear2(H5E_DEFAULT);
}

QuietErrors::~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

void Context::fail(const std::string& what) const {
    const std::string reason = error_reason();
    throw std::runtime_error(subject_ + ": " + what + (reason.empty() ? "" : " (" + reason + ")"));
}

Hid create_group(const Context& c, hid_t parent, const std::string& name,
                 const std::string& path) {
    return c.make(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                  H5Gclose, "cannot create group " + path);
}

void write_string_attribute(const Context& c, hid_t obj, const std::string& name,
                            const std::vector<std::string>& values, bool scalar,
                            StringStorage storage) {
    const bool fixed = storage == StringStorage::FixedNullPadded;
    std::size_t width = 1;
    for (const auto& v : values) width = std::max(width, v.size());
    Hid type = c.make(H5Tcopy(H5T_C_S1), H5Tclose, "cannot create string type");
    c.check(H5Tset_size(type.get(), fixed ? width : H5T_VARIABLE), "cannot size string type");
    if (fixed)
        c.check(H5Tset_strpad(type.get(), H5T_STR_NULLPAD), "cannot set string padding");
    c.check(H5Tset_cset(type.get(), H5T_CSET_UTF8), "cannot set string charset");
    const hsize_t n = values.size();
    Hid space = c.make(scalar ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &n, nullptr),
                       H5Sclose, "cannot create dataspace for attribute " + name);
    Hid attr = c.make(
        H5Acreate2(obj, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
        H5Aclose, "cannot create attribute " + name);
    if (values.empty()) return;
    if (fixed) {
        std::vector<char> buffer(values.size() * width, '\0');
        for (std::size_t k = 0; k < values.size(); ++k)
            std::copy(values[k].begin(), values[k].end(),
                      buffer.begin() + static_cast<std::ptrdiff_t>(k * width));
        c.check(H5Awrite(attr.get(), type.get(), buffer.data()), "cannot write attribute " + name);
    } else {
        std::vector<const char*> ptrs;
        for (const auto& v : values) ptrs.push_back(v.c_str());
        c.check(H5Awrite(attr.get(), type.get(), ptrs.data()), "cannot write attribute " + name);
    }
}

void flush_and_close(const Context& c, Hid& file) {
    c.check(H5Fflush(file.get(), H5F_SCOPE_LOCAL), "cannot flush");
    c.check(file.reset(), "cannot close");
}

}  // namespace pilempm::io::hdf5
