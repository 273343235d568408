// An MPM run interrupted mid-stage and resumed from its checkpoint ends in exactly the
// state of the same run left alone.
#include <gtest/gtest.h>

#include <csignal>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/hdf5/mpm_checkpoint.hpp"

namespace fs = std::filesystem;

namespace {
int run(const std::string& command) {
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
}  // namespace

// Runs the 1D wave case (FLIP, or APIC whose affine field must be checkpointed too)
// whole, and interrupted by `signal` (Ctrl-C's SIGINT, a batch system's SIGTERM) then
// resumed, and compares the final states bit for bit.
void check_resume(bool apic, int signal) {
    const fs::path dir = fs::temp_directory_path() /
                         ("pilempm-resume-" + std::string(apic ? "apic-" : "flip-") + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string exe = PILEMPM_EXECUTABLE;
    std::string case_file = std::string(PILEMPM_SOURCE_DIR) + "/cases/verification/mpm-wave-1d.yaml";
    if (apic) {
        std::stringstream text;
        text << std::ifstream(case_file).rdbuf();
        std::string yaml = text.str();
        const auto at = yaml.find("flip: 1.0");
        ASSERT_NE(at, std::string::npos);
        yaml.replace(at, 9, "velocity_transfer: apic");
        case_file = (dir / "wave-apic.yaml").string();
        std::ofstream(case_file) << yaml;
    }

    ASSERT_EQ(run(exe + " run " + case_file + " --out " + (dir / "whole").string() + " --quiet"), 0);
    // Interrupt after 100 of the ~260 steps: exit 130, the folder kept as .incomplete.
    ASSERT_EQ(run("PILEMPM_INTERRUPT_AFTER_STEPS=100 PILEMPM_INTERRUPT_SIGNAL=" + std::to_string(signal) + " " + exe + " run " + case_file + " --out " +
                  (dir / "split").string() + " --quiet 2>/dev/null"),
              130);
    EXPECT_FALSE(fs::exists(dir / "split"));
    ASSERT_TRUE(fs::exists(dir / "split.incomplete" / "checkpoint.h5"));
    ASSERT_EQ(run(exe + " run " + case_file + " --out " + (dir / "split").string() + " --quiet --resume"), 0);
    EXPECT_FALSE(fs::exists(dir / "split.incomplete"));

    pilempm::mpm::Particles<2> whole, split;
    const auto a = pilempm::io::read_checkpoint<2>(dir / "whole" / "checkpoint.h5", whole);
    const auto b = pilempm::io::read_checkpoint<2>(dir / "split" / "checkpoint.h5", split);
    EXPECT_EQ(a.step, b.step);
    EXPECT_DOUBLE_EQ(a.time, b.time);
    ASSERT_EQ(whole.size(), split.size());
    for (std::size_t i = 0; i < whole.x.size(); ++i) ASSERT_DOUBLE_EQ(whole.x[i], split.x[i]) << i;
    for (std::size_t i = 0; i < whole.stress.size(); ++i) ASSERT_DOUBLE_EQ(whole.stress[i], split.stress[i]) << i;
    for (std::size_t i = 0; i < whole.v.size(); ++i) ASSERT_DOUBLE_EQ(whole.v[i], split.v[i]) << i;
    for (std::size_t i = 0; i < whole.C.size(); ++i) ASSERT_DOUBLE_EQ(whole.C[i], split.C[i]) << i;

    // Nothing to resume: a clear error, not a fresh run.
    EXPECT_EQ(run(exe + " run " + case_file + " --out " + (dir / "none").string() + " --quiet --resume 2>/dev/null"), 1);
    fs::remove_all(dir);
}

TEST(MpmResume, InterruptedAndResumedRunMatchesAnUninterruptedOne) { check_resume(false, SIGINT); }
TEST(MpmResume, TerminatedAndResumedApicRunMatchesAnUninterruptedOne) { check_resume(true, SIGTERM); }
