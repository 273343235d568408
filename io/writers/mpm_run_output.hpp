#pragma once
// What a staged MPM run writes while it runs: the VTK series of the material points, the
// checkpoint (the whole run state, see run_checkpoint.hpp), progress on a terminal and a
// line per finished stage. The stage driver calls it; it decides nothing about the run.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "coupling/driver/stage_driver.hpp"
#include "io/hdf5/history_segments.hpp"
#include "io/writers/drive_outlook.hpp"
#include "io/writers/staged_directory.hpp"
#include "io/writers/stage_progress.hpp"
#include "io/writers/vtk_particle_writer.hpp"

namespace pilempm::io {

template <int D>
class MpmRunOutput final : public coupling::StageObserver<D> {
public:
    // Writes into staged.path(): vtk/particles_NNNNNN.vtu + particles.pvd, checkpoint.h5 and
    // the history's older rows in checkpoint-history-NNNN.h5, history_segment_rows a file.
    MpmRunOutput(StagedDirectory& staged, std::vector<std::string> state_names, std::string case_fingerprint,
                 bool quiet, std::size_t history_segment_rows = 100000);

    // A resumed run: the snapshots the interrupted run wrote stay in the series.
    void adopt_snapshots(const std::vector<double>& times) { vtk_.adopt_written_steps(times); }
    // A resumed run: the history segments its checkpoint names.
    void adopt_history_segments(std::vector<double> rows) { history_segments_.adopt(std::move(rows)); }
    std::filesystem::path checkpoint_path() const { return staged_.path() / "checkpoint.h5"; }
    // Writes the .pvd.
    void finish() { vtk_.finish(); }
    void set_pore_water(const mpm::PoreWater& water, std::vector<double> friction_angle_deg) {
        vtk_.set_pore_water(water, std::move(friction_angle_deg));
    }

    // The coupled body whose state each checkpoint carries (none: nullptr); ground: the
    // elevation a blow's line reports the toe's depth from (the seabed), m.
    void set_body(const coupling::CoupledBody<D>* body, double ground = 0.0) {
        body_ = body;
        ground_ = ground;
    }
    // Called at each snapshot after the particles' (the pile's own VTK series).
    void also_at_snapshots(std::function<void(double)> write) { also_ = std::move(write); }
    // Called after each checkpoint with the driver's state and the history so far (a drive's
    // tables, to follow it).
    void also_at_checkpoints(std::function<void(const coupling::DriverState&, const Table&)> write) {
        also_at_checkpoint_ = std::move(write);
    }

    void snapshot(double time, const mpm::MpmModel<D>& model) override;
    void checkpoint(const coupling::DriverState& state, const mpm::MpmModel<D>& model,
                    const mpm::MpmSolver<D>& solver, const Table& history) override;
    void stage_begin(int stage, const coupling::StageSpec& spec) override;
    void stage_progress(const coupling::StageSpec& spec, const coupling::DriverState& state,
                        const mpm::MpmSolver<D>& solver) override;
    void stage_end(int stage, const coupling::StageSpec& spec, const coupling::StageReport& report) override;
    void drive_ended(const coupling::StageSpec& blow, const std::string& why) override;

    // Each stage finished in this invocation: its index and wall time (s; a stage resumed
    // counts from the resume).
    struct StageWallTime {
        int stage = 0;
        double wall = 0.0;
    };
    const std::vector<StageWallTime>& stage_wall_times() const { return walls_; }

private:
    StagedDirectory& staged_;
    ParticleVtkSeries<D> vtk_;
    std::string fingerprint_;
    bool quiet_;
    StageProgress<D> progress_;
    HistorySegments history_segments_;
    const coupling::CoupledBody<D>* body_ = nullptr;
    std::function<void(double)> also_;
    std::function<void(const coupling::DriverState&, const Table&)> also_at_checkpoint_;
    std::vector<StageWallTime> walls_;
    double stage_began_ = 0.0;  // s on the steady clock
    double ground_ = 0.0;
    DriveOutlook outlook_;            // a drive's blows and time to its target, for the log
    double last_blow_end_ = -1.0;     // s on the steady clock (< 0: none yet in this invocation)
};

extern template class MpmRunOutput<2>;
extern template class MpmRunOutput<3>;

}  // namespace pilempm::io
