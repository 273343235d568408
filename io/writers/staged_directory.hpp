#pragma once
// Results are written into a sibling staging folder and renamed into place only when the
// run is complete, so a failed or interrupted run never leaves a half-written folder.
#include <filesystem>

namespace pilempm::io {

class StagedDirectory {
public:
    // adopt_incomplete: carry on in the DIR.incomplete an interrupted run left (resume), or,
    // if there is none, in the DIR.partial-PID with a checkpoint that a killed run left.
    explicit StagedDirectory(std::filesystem::path final_dir, bool adopt_incomplete = false);
    // Removes the staging folder unless committed; after keep_if_failed() a failed run's
    // folder is kept as DIR.incomplete (it holds a checkpoint to resume from).
    ~StagedDirectory();
    void keep_if_failed() { keep_ = true; }
    bool adopted() const { return adopted_; }
    // The folder the run carries on in (DIR.incomplete or a killed run's DIR.partial-PID).
    const std::filesystem::path& adopted_from() const { return adopted_from_; }
    std::filesystem::path incomplete_path() const;
    StagedDirectory(const StagedDirectory&) = delete;
    StagedDirectory& operator=(const StagedDirectory&) = delete;

    const std::filesystem::path& path() const { return staging_; }
    const std::filesystem::path& final_path() const { return final_; }
    // Replaces final_dir (if it exists) by the staging folder.
    void commit();

private:
    std::filesystem::path final_, staging_, adopted_from_;
    bool committed_ = false;
    bool keep_ = false;
    bool adopted_ = false;
};

}  // namespace pilempm::io
