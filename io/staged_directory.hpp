#pragma once
// Results are written into a sibling staging folder and renamed into place only when the
// run is complete, so a failed or interrupted run never leaves a half-written folder.
#include <filesystem>

namespace pilempm::io {

class StagedDirectory {
public:
    explicit StagedDirectory(std::filesystem::path final_dir);
    ~StagedDirectory();  // removes the staging folder unless committed
    StagedDirectory(const StagedDirectory&) = delete;
    StagedDirectory& operator=(const StagedDirectory&) = delete;

    const std::filesystem::path& path() const { return staging_; }
    const std::filesystem::path& final_path() const { return final_; }
    // Replaces final_dir (if it exists) by the staging folder.
    void commit();

private:
    std::filesystem::path final_, staging_;
    bool committed_ = false;
};

}  // namespace pilempm::io
