#include "io/writers/pvd_collection.hpp"

#include <charconv>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace pilempm::io {

namespace fs = std::filesystem;

namespace {

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

PvdCollection::PvdCollection(std::string owner, fs::path dir, std::string basename)
    : owner_(std::move(owner)), dir_(std::move(dir)), basename_(std::move(basename)) {
    if (basename_.empty() || basename_.find_first_of("/\\") != std::string::npos)
        throw std::invalid_argument(owner_ + ": basename must be a plain file name");
}

void PvdCollection::create_directory() const {
    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (ec)
        throw std::runtime_error(owner_ + ": cannot create " + dir_.string() + ": " +
                                 ec.message());
}

std::string PvdCollection::next_step_file() const {
    char name[32];
    std::snprintf(name, sizeof name, "_%06zu.vtu", steps_.size());
    return basename_ + name;
}

void PvdCollection::add(double time, std::string file) {
    steps_.push_back({time, std::move(file)});
}

void PvdCollection::adopt_written(const std::vector<double>& times) {
    if (!steps_.empty()) throw std::logic_error(owner_ + ": adopting written steps after a write");
    for (double t : times) {
        const std::string file = next_step_file();
        if (!std::filesystem::exists(dir_ / file))
            throw std::runtime_error(owner_ + ": cannot resume the VTK series: " + (dir_ / file).string() + " is missing");
        add(t, file);
    }
}

std::vector<double> PvdCollection::times() const {
    std::vector<double> out;
    for (const Step& s : steps_) out.push_back(s.time);
    return out;
}

void PvdCollection::finish() {
    if (pvd_written_ && steps_in_pvd_ == steps_.size()) return;
    write();
    pvd_written_ = true;
    steps_in_pvd_ = steps_.size();
}

void PvdCollection::write() const {
    const fs::path pvd = pvd_path();
    const fs::path tmp = dir_ / (basename_ + ".pvd.tmp");
    {
        std::ofstream out(tmp, std::ios::trunc);
        out << "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
               "  <Collection>\n";
        for (const Step& s : steps_)
            out << "    <DataSet timestep=\"" << format_double(s.time)
                << "\" group=\"\" part=\"0\" file=\"" << xml_escape(s.file) << "\"/>\n";
        out << "  </Collection>\n</VTKFile>\n";
        out.close();
        if (!out) {
            std::error_code ec;
            fs::remove(tmp, ec);
            throw std::runtime_error(owner_ + ": cannot write " + tmp.string());
        }
    }
    // Rename so a reader never sees a half-written collection.
    std::error_code ec;
    fs::rename(tmp, pvd, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(tmp, ignored);
        throw std::runtime_error(owner_ + ": cannot write " + pvd.string() + ": " + ec.message());
    }
}

}  // namespace pilempm::io
