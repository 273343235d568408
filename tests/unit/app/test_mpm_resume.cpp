// An MPM run interrupted by a real signal and resumed from its checkpoint writes exactly
// what the same run left alone writes: history.csv, verification.json, summary.json (less
// its wall time) and the VTK series (every .vtu and the .pvd), byte for byte. Checked for
// a dynamic stage (the 1D wave, FLIP and APIC), for a run stopped in its quasi-static
// stage that goes on to a dynamic one, for saturated soil stopped in a consolidation
// pause and in the blow after it, for an FE pile jacked into the soil, for a drive after a
// drained nil step on a held absorbing base stopped as a blow settles, on a graded grid,
// and for a stop during a verification's grid-sequence reruns; with the history sealed in
// segment files beside the checkpoint.
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <vector>
#include <string>

namespace fs = std::filesystem;

namespace {

int run(const std::string& command) {
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string read_file(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// summary.json without the lines that time this invocation.
std::string summary_without_wall_time(const fs::path& file) {
    std::istringstream in(read_file(file));
    std::string line, out;
    while (std::getline(in, line))
        if (line.find("wall_time_s") == std::string::npos && line.find("particle_steps_per_s") == std::string::npos)
            out += line + "\n";
    return out;
}

void expect_same_outputs(const fs::path& whole, const fs::path& split) {
    ASSERT_TRUE(fs::exists(whole / "history.csv"));
    // verification.json where the case checks, blows.csv and blow_count.csv where it drives,
    // the traction profiles (their stage means summed across the stop) where a pile is coupled.
    for (const char* name : {"history.csv", "verification.json", "blows.csv", "blow_count.csv", "pile_tractions_outer.csv",
                             "pile_tractions_inner.csv", "pile_tractions_toe.csv"}) {
        EXPECT_EQ(fs::exists(whole / name), fs::exists(split / name)) << name;
        if (fs::exists(whole / name)) {
            EXPECT_EQ(read_file(whole / name), read_file(split / name)) << name << " differs";
        }
    }
    EXPECT_EQ(summary_without_wall_time(whole / "summary.json"), summary_without_wall_time(split / "summary.json"));
    std::set<std::string> a, b;
    for (const auto& e : fs::directory_iterator(whole / "vtk")) a.insert(e.path().filename().string());
    for (const auto& e : fs::directory_iterator(split / "vtk")) b.insert(e.path().filename().string());
    EXPECT_EQ(a, b) << "the VTK series hold other files";
    EXPECT_GT(a.size(), 3u);
    for (const auto& f : a) {
        if (!b.count(f)) continue;
        EXPECT_EQ(read_file(whole / "vtk" / f), read_file(split / "vtk" / f)) << f << " differs";
    }
}

// Runs `case_file` whole, and interrupted by `signal` after `steps` steps (exit 130, the
// folder kept as .incomplete; `stopped` looks into it) then resumed; compares what the two
// wrote.
void check_resume(const fs::path& dir, const std::string& case_file, int signal, long steps,
                  const std::function<void(const fs::path&)>& stopped = {}) {
    const std::string exe = PILEMPM_EXECUTABLE;
    ASSERT_EQ(run(exe + " run " + case_file + " --out " + (dir / "whole").string() + " --quiet"), 0);
    ASSERT_EQ(run("PILEMPM_INTERRUPT_AFTER_STEPS=" + std::to_string(steps) + " PILEMPM_INTERRUPT_SIGNAL=" +
                  std::to_string(signal) + " " + exe + " run " + case_file + " --out " + (dir / "split").string() +
                  " --quiet 2>/dev/null"),
              130);
    EXPECT_FALSE(fs::exists(dir / "split"));
    ASSERT_TRUE(fs::exists(dir / "split.incomplete" / "checkpoint.h5"));
    if (stopped) stopped(dir / "split.incomplete");
    ASSERT_EQ(run(exe + " run " + case_file + " --out " + (dir / "split").string() + " --quiet --resume"), 0);
    EXPECT_FALSE(fs::exists(dir / "split.incomplete"));
    expect_same_outputs(dir / "whole", dir / "split");
}

fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("pilempm-resume-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// The 1D wave case with snapshots every 20 ms (so the interrupted run has written some).
std::string wave_case(const fs::path& dir, bool apic) {
    std::string yaml = read_file(std::string(PILEMPM_SOURCE_DIR) + "/cases/verification/mpm-wave-1d.yaml");
    if (apic) {
        const auto at = yaml.find("flip: 1.0");
        yaml.replace(at, 9, "velocity_transfer: apic");
    }
    const auto at = yaml.find("  plots: false");
    yaml.replace(at, 14, "  plots: false\n  snapshot_interval: 0.02");
    const fs::path file = dir / "wave.yaml";
    std::ofstream(file) << yaml;
    return file.string();
}

// A column settled under gravity (quasi-static), then struck by a pulse switched on in the
// dynamic stage only; one side absorbs.
const char* kSettleThenBlow = R"(title: "settle, then a blow"
analysis: mpm
dimension: 2
grid: {origin: [0.0, 0.0], size: [0.5, 5.0], cells: [2, 20]}
materials:
  - {name: soil, model: linear_elastic, density: 2000.0, youngs_modulus: 10.0e6, poisson_ratio: 0.3}
regions:
  - {material: soil, box: {min: [0.0, 0.0], max: [0.5, 4.0]}}
boundaries:
  - {plane: x_min, type: roller}
  - {plane: x_max, type: absorbing}
  - {plane: y_min, type: roller}
initial_stress: {type: k0, surface: 4.0}
pressures:
  - {box: {min: [0.0, 3.9], max: [0.5, 4.0]}, face: y_max, pressure: 20.0e3, duration: 0.01, stages: [blow]}
stages:
  - {name: settle, type: quasi_static, max_steps: 400, tolerance: 1.0e-12}
  - {name: blow, type: dynamic, duration: 0.08}
output:
  plots: false
  snapshot_interval: 0.01
  probes: [[0.125, 3.0625], [0.125, 1.0625]]
verification:
  checks: [absorbed_energy]
)";

// Saturated soil under 5 m of water (coupled v-w), struck twice with an implicit
// consolidation pause between the blows: the checkpoint carries the pore water.
const char* kBlowPauseBlow = R"(title: "blow, pause, blow in saturated soil"
analysis: mpm
dimension: 2
grid: {origin: [0.0, 0.0], size: [0.25, 5.0], cells: [1, 20]}
water: {level: 9.0}
materials:
  - {name: sand, model: linear_elastic, density: 2000.0, youngs_modulus: 20.0e6, poisson_ratio: 0.3,
     drainage: coupled, porosity: 0.4, hydraulic_conductivity: 1.0e-4}
regions:
  - {material: sand, box: {min: [0.0, 0.0], max: [0.25, 4.0]}}
boundaries:
  - {plane: x_min, type: roller}
  - {plane: x_max, type: roller}
  - {plane: y_min, type: absorbing}
initial_stress: {type: k0, surface: 4.0}
pressures:
  - {box: {min: [0.0, 3.9], max: [0.25, 4.0]}, face: y_max, pressure: 20.0e3, duration: 0.005, stages: [blow 1, blow 2]}
stages:
  - {name: blow 1, type: dynamic, duration: 0.02}
  - {name: pause, type: consolidation, duration: 1.25, steps: 12}
  - {name: blow 2, type: dynamic, duration: 0.02}
output:
  plots: false
  snapshot_interval: 0.01
  probes: [[0.0625, 3.0625], [0.0625, 1.0625]]
verification:
  checks: [absorbed_energy]
  absorbed_share: 0.0
)";


}  // namespace

TEST(MpmResume, JackedPileStoppedMidwayResumedWritesWhatAnUninterruptedOneWrites) {
    const fs::path dir = fresh_dir("pile");
    // The checkpoint carries the pile's displacements and velocities and each point's
    // contact history.
    check_resume(dir, std::string(PILEMPM_SOURCE_DIR) + "/cases/jacking/jacked-open-pile-tiny.yaml", SIGINT, 300);
    fs::remove_all(dir);
}

// A blow verification case with a geostatic stage of exactly 500 steps (a tolerance it does
// not reach), so the blow begins at step 501: stopped 10 steps into it, the checkpoint must
// carry the blow's ENTHRU so far and, for a ram, the hammer chain (the ram's position and
// velocity, the contact's state, its energy ledger).
namespace {

void check_blow_resume(const std::string& name, const std::string& case_file, int signal) {
    const fs::path dir = fresh_dir(name);
    std::string yaml = read_file(std::string(PILEMPM_SOURCE_DIR) + "/cases/verification/" + case_file);
    const std::string settle = "max_steps: 6000, tolerance: 1.0e-4";
    yaml.replace(yaml.find(settle), settle.size(), "max_steps: 500, tolerance: 1.0e-12");
    const fs::path file = dir / case_file;
    std::ofstream(file) << yaml;
    check_resume(dir, file.string(), signal, 510);
    fs::remove_all(dir);
}

}  // namespace

TEST(MpmResume, ABlowOnTheCoupledPileStoppedInItsPulseResumedWritesWhatAnUninterruptedOneWrites) {
    check_blow_resume("coupled-blow", "coupled-blow-energy.yaml", SIGTERM);
}

TEST(MpmResume, ARamOnTheCoupledPileStoppedAsItRidesTheHeadResumedWritesWhatAnUninterruptedOneWrites) {
    check_blow_resume("coupled-ram", "coupled-ram-blow-energy.yaml", SIGINT);
}

// The driving verification cut to two blows of 10 ms (some 375 steps each), with `more`
// edits on top, written into dir as `name`; its path.
fs::path two_blow_drive(const fs::path& dir, const std::string& name,
                        const std::vector<std::pair<std::string, std::string>>& more = {}) {
    std::string yaml = read_file(std::string(PILEMPM_SOURCE_DIR) + "/cases/verification/coupled-driving-energy.yaml");
    std::vector<std::pair<std::string, std::string>> edits = {
        {"blows: 3", "blows: 2"}, {"blow_duration: 0.25 ", "blow_duration: 0.01 "}, {"  blows: 3\n", "  blows: 2\n"}};
    edits.insert(edits.end(), more.begin(), more.end());
    for (const auto& [from, to] : edits) {
        const auto at = yaml.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) yaml.replace(at, from.size(), to);
    }
    const fs::path file = dir / name;
    std::ofstream(file) << yaml;
    return file;
}

// A drive of two blows with a consolidation pause between them (the driving verification
// with 10 ms blows, some 375 steps each), stopped in the second blow: the driver's
// blow bookkeeping (where the blow began, the refusal count) comes back with the rest.
TEST(MpmResume, ADriveStoppedInItsSecondBlowResumedWritesWhatAnUninterruptedOneWrites) {
    const fs::path dir = fresh_dir("drive");
    const fs::path file = two_blow_drive(dir, "drive.yaml");
    // The stopped drive's folder has its blows so far: the first, and its count.
    check_resume(dir, file.string(), SIGTERM, 450, [](const fs::path& incomplete) {
        const std::string blows = read_file(incomplete / "blows.csv");
        EXPECT_EQ(std::count(blows.begin(), blows.end(), '\n'), 2) << blows;  // header and blow 1
        EXPECT_TRUE(fs::exists(incomplete / "blow_count.csv"));
    });
    EXPECT_TRUE(fs::exists(dir / "whole" / "blows.csv"));
    fs::remove_all(dir);
}

// The same drive after a drained nil step on an absorbing base (held as a roller in the nil
// step, its reaction then a constant force), each blow damped to rest once its wave has
// passed (settle_damping), stopped in the second blow as it settles: the held base force,
// the water held hydrostatic then coupled, and the settling switch come back exactly.
TEST(MpmResume, ADriveAfterADrainedNilStepOnAHeldBaseStoppedAsItsBlowSettlesResumesExactly) {
    const fs::path dir = fresh_dir("drained-drive");
    const fs::path file = two_blow_drive(dir, "drained-drive.yaml", {
                            {"{plane: y_min, type: fixed}", "{plane: y_min, type: absorbing}"},
                            {"stages:\n", "stages:\n  - {name: nil, type: quasi_static, drainage: drained, max_steps: 200, "
                                          "tolerance: 1.0e-12, local_damping: 0.7}\n"},
                            {"    interval: 0.5 ", "    settle_damping: 0.7\n    interval: 0.5 "}});
    // 200 nil steps, blows of some 375 steps settling from 4 ms (of 10), a pause of 8.
    check_resume(dir, file.string(), SIGTERM, 200 + 375 + 8 + 250);
    EXPECT_TRUE(fs::exists(dir / "whole" / "blows.csv"));
    fs::remove_all(dir);
}

// The same drive stopped in its first pause: the pile's surface (where the history reads
// the toe) comes back placed, not at 0 m as before, so the tables match.
TEST(MpmResume, ADriveStoppedInAPauseResumedWritesWhatAnUninterruptedOneWrites) {
    const fs::path dir = fresh_dir("drive-pause");
    const fs::path file = two_blow_drive(dir, "drive.yaml");
    check_resume(dir, file.string(), SIGTERM, 379);  // the first blow some 375 steps, its pause 8
    fs::remove_all(dir);
}

// The same drive with its history sealed in segments of 100 rows beside the checkpoint
// (some 760 rows by the stop): the checkpoint carries only the rows after them, and the
// resumed run reads them back into the same history.
TEST(MpmResume, ADriveWhoseHistoryIsSealedInSegmentsResumesExactly) {
    const fs::path dir = fresh_dir("drive-segments");
    const fs::path file = two_blow_drive(dir, "drive.yaml", {{"  plots: false\n", "  plots: false\n  history_segment_rows: 100\n"}});
    check_resume(dir, file.string(), SIGTERM, 450, [](const fs::path& incomplete) {
        EXPECT_TRUE(fs::exists(incomplete / "checkpoint-history-0000.h5"));
        EXPECT_TRUE(fs::exists(incomplete / "checkpoint-history-0003.h5"));
    });
    fs::remove_all(dir);
}

// The same drive storing every 5th step's row of its blows once their pulse has passed
// (history_every): stopped in its second blow and resumed it writes what the uninterrupted
// one writes; and its blows.csv, every blow's peaks included, is the full-rate drive's to the
// byte from a history of far fewer rows.
TEST(MpmResume, ADriveWithADecimatedHistoryResumesExactlyAndKeepsEveryBlowsPeaks) {
    const fs::path dir = fresh_dir("drive-decimated");
    // Its wave's window (every row) 2 ms of the 10 ms blows, in both drives.
    const std::pair<std::string, std::string> window = {"    pause: {steps: 8}", "    pause: {steps: 8}\n    min_blow_duration: 0.002"};
    const fs::path file = two_blow_drive(dir, "drive.yaml", {{window.first, window.second + "\n    history_every: 5"}});
    check_resume(dir, file.string(), SIGTERM, 450);
    const fs::path full = two_blow_drive(dir, "full.yaml", {window});
    ASSERT_EQ(run(std::string(PILEMPM_EXECUTABLE) + " run " + full.string() + " --out " + (dir / "full").string() + " --quiet"), 0);
    EXPECT_EQ(read_file(dir / "full" / "blows.csv"), read_file(dir / "whole" / "blows.csv"));
    const std::string a = read_file(dir / "full" / "history.csv"), b = read_file(dir / "whole" / "history.csv");
    const auto rows = [](const std::string& t) { return std::count(t.begin(), t.end(), '\n'); };
    EXPECT_LT(rows(b), rows(a) / 2) << "the decimated history is not shorter";
    fs::remove_all(dir);
}

TEST(MpmResume, SaturatedRunStoppedInItsConsolidationPauseResumedWritesWhatAnUninterruptedOneWrites) {
    const fs::path dir = fresh_dir("pause");
    const fs::path file = dir / "blow-pause-blow.yaml";
    std::ofstream(file) << kBlowPauseBlow;
    check_resume(dir, file.string(), SIGINT, 303);  // blow 1 takes 297 steps, the pause 12
    fs::remove_all(dir);
}

TEST(MpmResume, SaturatedRunStoppedInItsSecondBlowResumedWritesWhatAnUninterruptedOneWrites) {
    const fs::path dir = fresh_dir("second-blow");
    const fs::path file = dir / "blow-pause-blow.yaml";
    std::ofstream(file) << kBlowPauseBlow;
    check_resume(dir, file.string(), SIGTERM, 450);
    fs::remove_all(dir);
}

// A drive killed outright (SIGKILL: no handler, no checkpoint on the way out, its staging
// folder not renamed) in its second blow: the folder it left holds the VTK series up to its
// last checkpoint (the end of the first pause), and --resume finds that DIR.partial-PID,
// carries on from the checkpoint and writes what the uninterrupted drive writes.
TEST(MpmResume, ADriveKilledOutrightResumesFromTheFolderItLeft) {
    const fs::path dir = fresh_dir("killed");
    const fs::path file = two_blow_drive(dir, "drive.yaml");
    const std::string exe = PILEMPM_EXECUTABLE;
    ASSERT_EQ(run(exe + " run " + file.string() + " --out " + (dir / "whole").string() + " --quiet"), 0);
    EXPECT_NE(run("PILEMPM_INTERRUPT_AFTER_STEPS=450 PILEMPM_INTERRUPT_SIGNAL=" + std::to_string(SIGKILL) + " " + exe +
                  " run " + file.string() + " --out " + (dir / "split").string() + " --quiet 2>/dev/null"),
              0);
    EXPECT_FALSE(fs::exists(dir / "split"));
    EXPECT_FALSE(fs::exists(dir / "split.incomplete"));
    int left = 0;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().filename().string().rfind("split.partial-", 0) == 0) {
            ++left;
            EXPECT_TRUE(fs::exists(entry.path() / "checkpoint.h5"));
            // The series as far as the checkpoint opens in ParaView: its .pvd lists files that are there.
            for (const char* series : {"particles.pvd", "pile.pvd"}) {
                const std::string pvd = read_file(entry.path() / "vtk" / series);
                int listed = 0;
                for (auto at = pvd.find("file=\""); at != std::string::npos; at = pvd.find("file=\"", at + 1), ++listed) {
                    const auto from = at + 6;
                    EXPECT_TRUE(fs::exists(entry.path() / "vtk" / pvd.substr(from, pvd.find('"', from) - from)));
                }
                EXPECT_GE(listed, 2) << series;
            }
        }
    ASSERT_EQ(left, 1);
    ASSERT_EQ(run(exe + " run " + file.string() + " --out " + (dir / "split").string() + " --quiet --resume"), 0);
    for (const auto& entry : fs::directory_iterator(dir))
        EXPECT_EQ(entry.path().filename().string().find("split."), std::string::npos) << entry.path();
    expect_same_outputs(dir / "whole", dir / "split");
    fs::remove_all(dir);
}

TEST(MpmResume, InterruptedDynamicRunResumedWritesWhatAnUninterruptedOneWrites) {
    const fs::path dir = fresh_dir("flip");
    check_resume(dir, wave_case(dir, false), SIGINT, 100);
    fs::remove_all(dir);
}

TEST(MpmResume, TerminatedApicRunResumedWritesWhatAnUninterruptedOneWrites) {
    const fs::path dir = fresh_dir("apic");
    check_resume(dir, wave_case(dir, true), SIGTERM, 150);
    fs::remove_all(dir);
}

TEST(MpmResume, RunStoppedInItsQuasiStaticStageResumedWritesWhatAnUninterruptedOneWrites) {
    const fs::path dir = fresh_dir("quasi-static");
    const fs::path file = dir / "settle-then-blow.yaml";
    std::ofstream(file) << kSettleThenBlow;
    check_resume(dir, file.string(), SIGINT, 150);
    fs::remove_all(dir);
}

// The same on a graded grid (cells of 0.25 m at the base to about 0.125 m at the top): the
// checkpoint restores the grid's lines, not a spacing.
TEST(MpmResume, AGradedGridRunStoppedMidwayResumedWritesWhatAnUninterruptedOneWrites) {
    const fs::path dir = fresh_dir("graded");
    std::string yaml = kSettleThenBlow;
    const std::string uniform = "grid: {origin: [0.0, 0.0], size: [0.5, 5.0], cells: [2, 20]}";
    yaml.replace(yaml.find(uniform), uniform.size(),
                 "grid:\n  origin: [0.0, 0.0]\n  zones: {x: [{to: 0.5, cell: 0.25}],"
                 " y: [{to: 2.0, cell: 0.25}, {to: 5.0, cell: 0.125}]}");
    const fs::path file = dir / "graded-settle-then-blow.yaml";
    std::ofstream(file) << yaml;
    check_resume(dir, file.string(), SIGTERM, 450);
    fs::remove_all(dir);
}

// A run resumes whatever the spelling of its case's path (stopped with it absolute, resumed
// as ./wave.yaml from its folder); the checkpoint refuses another case file, naming both.
TEST(MpmResume, ARunResumesWithItsCasesPathSpeltOtherwiseAndRefusesAnotherCase) {
    const fs::path dir = fresh_dir("spelling");
    const std::string file = wave_case(dir, false);
    const std::string exe = PILEMPM_EXECUTABLE, here = "cd " + dir.string() + " && ";
    ASSERT_EQ(run(here + exe + " run ./wave.yaml --out whole --quiet"), 0);
    ASSERT_EQ(run("PILEMPM_INTERRUPT_AFTER_STEPS=100 " + exe + " run " + file + " --out " + (dir / "split").string() +
                  " --quiet 2>/dev/null"),
              130);
    fs::copy_file(file, dir / "other.yaml");
    EXPECT_EQ(run(here + exe + " run other.yaml --out split --quiet --resume 2>refused.txt"), 1);
    EXPECT_NE(read_file(dir / "refused.txt").find("belongs to another case (wave.yaml), not to other.yaml"),
              std::string::npos)
        << read_file(dir / "refused.txt");
    ASSERT_EQ(run(here + exe + " run ./wave.yaml --out split --quiet --resume"), 0);
    expect_same_outputs(dir / "whole", dir / "split");
    fs::remove_all(dir);
}

TEST(MpmResume, NothingToResumeIsAClearError) {
    const fs::path dir = fresh_dir("none");
    const std::string exe = PILEMPM_EXECUTABLE;
    EXPECT_EQ(run(exe + " run " + wave_case(dir, false) + " --out " + (dir / "none").string() +
                  " --quiet --resume 2>/dev/null"),
              1);
    fs::remove_all(dir);
}

// A stop while a verification reruns the case on its grid sequence (the 1D wave: 263 steps
// on its own grid, about twice that on the first finer one) ends the job at once with 130,
// naming the grid, the case's own run kept as .incomplete with its checkpoint; resumed, it
// reruns the sequence and writes what an uninterrupted run writes.
TEST(MpmResume, AStopInAGridSequenceRerunEndsTheJobAndResumesToTheSameResults) {
    const fs::path dir = fresh_dir("grid-sequence");
    const std::string exe = PILEMPM_EXECUTABLE;
    const std::string wave = std::string(PILEMPM_SOURCE_DIR) + "/cases/verification/mpm-wave-1d.yaml";
    const fs::path log = dir / "stderr.txt";
    ASSERT_EQ(run("PILEMPM_INTERRUPT_AFTER_STEPS=400 PILEMPM_INTERRUPT_SIGNAL=" + std::to_string(SIGTERM) + " " + exe +
                  " run " + wave + " --out " + (dir / "split").string() + " --quiet 2>" + log.string()),
              130);
    const std::string said = read_file(log);
    EXPECT_NE(said.find("interrupted on grid"), std::string::npos) << said;
    EXPECT_FALSE(fs::exists(dir / "split"));
    ASSERT_TRUE(fs::exists(dir / "split.incomplete" / "checkpoint.h5"));
    ASSERT_EQ(run(exe + " run " + wave + " --out " + (dir / "split").string() + " --quiet --resume"), 0);
    ASSERT_EQ(run(exe + " run " + wave + " --out " + (dir / "whole").string() + " --quiet"), 0);
    EXPECT_FALSE(fs::exists(dir / "split.incomplete"));
    for (const char* name : {"history.csv", "verification.json"})
        EXPECT_EQ(read_file(dir / "whole" / name), read_file(dir / "split" / name)) << name << " differs";
    fs::remove_all(dir);
}
