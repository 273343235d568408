#pragma once
// The .pvd side of a ParaView time series (internal to io/*.cpp): the steps written so far,
// each a time and a file relative to the series directory, and the collection file listing
// them, written atomically. Shared by the pile and the particle VTK writers.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace pilempm::io {

class PvdCollection {
public:
    // Messages start with `owner` ("<owner>: ..."). Throws std::invalid_argument when
    // basename is not a plain file name.
    PvdCollection(std::string owner, std::filesystem::path dir, std::string basename);

    const std::filesystem::path& dir() const { return dir_; }
    std::filesystem::path pvd_path() const { return dir_ / (basename_ + ".pvd"); }

    // Creates dir (and its parents); throws std::runtime_error when it cannot.
    void create_directory() const;

    // "<basename>_NNNNNN.vtu" for the next step (NNNNNN = steps so far).
    std::string next_step_file() const;
    // Records a written step; `file` is relative to dir, as the .pvd lists it.
    void add(double time, std::string file);
    // A resumed run: the steps an interrupted one wrote, at these times, taken back into
    // an empty series (each file must be there; std::runtime_error names the missing one).
    void adopt_written(const std::vector<double>& times);
    std::size_t size() const { return steps_.size(); }
    std::vector<double> times() const;

    // Writes dir/<basename>.pvd listing all steps with their times (via a .tmp renamed over
    // it, so a reader never sees a half-written collection); idempotent: does nothing when
    // no step was added since the last finish(). Throws std::runtime_error on failure.
    void finish();

private:
    struct Step {
        double time;
        std::string file;
    };

    void write() const;

    std::string owner_;
    std::filesystem::path dir_;
    std::string basename_;
    std::vector<Step> steps_;
    std::size_t steps_in_pvd_ = 0;
    bool pvd_written_ = false;
};

}  // namespace pilempm::io
