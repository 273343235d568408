#include "io/writers/staged_directory.hpp"

#include <unistd.h>

#include <stdexcept>
#include <string>

namespace pilempm::io {

namespace fs = std::filesystem;

StagedDirectory::StagedDirectory(fs::path final_dir, bool adopt_incomplete) : final_(std::move(final_dir)) {
    if (final_.has_filename() == false) final_ = final_.parent_path();
    const fs::path parent = final_.has_parent_path() ? final_.parent_path() : fs::path(".");
    fs::create_directories(parent);
    staging_ = parent / (final_.filename().string() + ".partial-" + std::to_string(::getpid()));
    fs::remove_all(staging_);
    if (adopt_incomplete && fs::is_directory(incomplete_path())) {
        fs::rename(incomplete_path(), staging_);
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
