#include "io/writers/staged_directory.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <stdexcept>
#include <string>

namespace pilempm::io {

namespace fs = std::filesystem;

namespace {

// The staging folder a run left when it was killed outright (SIGKILL, power loss, a batch
// system's hard limit) and could not rename it to .incomplete: DIR.partial-PID with PID no
// longer alive. The newest of them if several; empty if none.
fs::path orphaned_staging(const fs::path& final_dir) {
    const fs::path parent = final_dir.has_parent_path() ? final_dir.parent_path() : fs::path(".");
    const std::string prefix = final_dir.filename().string() + ".partial-";
    fs::path newest;
    fs::file_time_type newest_time{};
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(parent, ec)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind(prefix, 0) != 0 || !entry.is_directory(ec)) continue;
        const std::string digits = name.substr(prefix.size());
        if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) continue;
        const long pid = std::stol(digits);
        // Ours too (a PID reused since, after a reboot): the folder predates this process.
        if (pid != ::getpid() && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH)) continue;
        const auto when = fs::last_write_time(entry.path() / "checkpoint.h5", ec);
        if (ec) continue;  // nothing to resume from in it
        if (newest.empty() || when > newest_time) newest = entry.path(), newest_time = when;
    }
    return newest;
}

}  // namespace

StagedDirectory::StagedDirectory(fs::path final_dir, bool adopt_incomplete) : final_(std::move(final_dir)) {
    if (final_.has_filename() == false) final_ = final_.parent_path();
    const fs::path parent = final_.has_parent_path() ? final_.parent_path() : fs::path(".");
    fs::create_directories(parent);
    staging_ = parent / (final_.filename().string() + ".partial-" + std::to_string(::getpid()));
    const fs::path left = !adopt_incomplete               ? fs::path()
                          : fs::is_directory(incomplete_path()) ? incomplete_path()
                                                                : orphaned_staging(final_);
    if (left != staging_) fs::remove_all(staging_);
    if (!left.empty()) {
        if (left != staging_) fs::rename(left, staging_);
        // A killed run may have died writing a file: its .tmp never became the file.
        std::error_code ec;
        for (auto it = fs::recursive_directory_iterator(staging_, ec); !ec && it != fs::recursive_directory_iterator();
             it.increment(ec))
            if (it->path().extension() == ".tmp" && it->is_regular_file()) fs::remove(it->path(), ec);
        adopted_from_ = left;
        adopted_ = true;
        keep_ = true;
    } else {
        fs::create_directory(staging_);
    }
}

fs::path StagedDirectory::incomplete_path() const { return final_.string() + ".incomplete"; }

StagedDirectory::~StagedDirectory() {
    if (committed_) return;
    std::error_code ec;
    if (keep_) {
        fs::remove_all(incomplete_path(), ec);
        fs::rename(staging_, incomplete_path(), ec);
        if (!ec) return;
    }
    fs::remove_all(staging_, ec);
}

void StagedDirectory::commit() {
    const fs::path old = final_.string() + ".old-" + std::to_string(::getpid());
    const bool had = fs::exists(final_);
    if (had) fs::rename(final_, old);
    fs::rename(staging_, final_);
    committed_ = true;
    if (had) fs::remove_all(old);
}

}  // namespace pilempm::io
