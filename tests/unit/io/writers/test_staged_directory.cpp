// What --resume carries on in: a stopped run's DIR.incomplete first; else the
// DIR.partial-PID with a checkpoint that a run killed outright left, if its process is
// gone (its PID may be this process's own after a reboot), never a live run's; the newest
// if several; stray .tmp files dropped. A run without --resume starts a fresh folder.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/writers/staged_directory.hpp"

namespace fs = std::filesystem;
using pilempm::io::StagedDirectory;

namespace {

struct Scratch {
    fs::path dir = fs::temp_directory_path() / ("pilempm-staged-" + std::to_string(::getpid()));
    Scratch() { fs::create_directories(dir); }
    ~Scratch() { fs::remove_all(dir); }
};

// A PID no process has now: a child's, once it has exited and been reaped.
long gone_pid() {
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    ::waitpid(child, nullptr, 0);
    return child;
}

fs::path left_by(const fs::path& out, long pid, const std::string& mark) {
    const fs::path d = out.string() + ".partial-" + std::to_string(pid);
    fs::create_directories(d / "vtk");
    std::ofstream(d / "checkpoint.h5") << mark;
    std::ofstream(d / "vtk" / "particles_000009.vtu.tmp") << "half";
    return d;
}

std::string read(const fs::path& f) {
    std::ifstream in(f);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

TEST(StagedDirectory, ResumeTakesAKilledRunsFolderButNeverALiveOnes) {
    Scratch s;
    const fs::path out = s.dir / "run";
    const fs::path live = left_by(out, ::getppid(), "live");  // the test's parent: alive
    {
        StagedDirectory none(out, true);
        EXPECT_FALSE(none.adopted());  // only a live run's folder: not ours to take
    }
    EXPECT_TRUE(fs::exists(live / "checkpoint.h5"));
    const fs::path old = left_by(out, gone_pid(), "old");
    fs::last_write_time(old / "checkpoint.h5", fs::file_time_type::clock::now() - std::chrono::hours(1));
    const fs::path killed = left_by(out, gone_pid(), "killed");
    {
        StagedDirectory staged(out, true);
        ASSERT_TRUE(staged.adopted());
        EXPECT_EQ(staged.adopted_from(), killed);  // the newer of the two dead runs'
        EXPECT_EQ(read(staged.path() / "checkpoint.h5"), "killed");
        EXPECT_FALSE(fs::exists(staged.path() / "vtk" / "particles_000009.vtu.tmp"));
        EXPECT_FALSE(fs::exists(killed));
    }  // not committed: kept as DIR.incomplete, which a later --resume takes first
    EXPECT_EQ(read(out.string() + ".incomplete/checkpoint.h5"), "killed");
    {
        StagedDirectory again(out, true);
        EXPECT_EQ(again.adopted_from(), fs::path(out.string() + ".incomplete"));
    }
    EXPECT_TRUE(fs::exists(live / "checkpoint.h5"));
    EXPECT_TRUE(fs::exists(old / "checkpoint.h5"));
}

TEST(StagedDirectory, AFolderLeftUnderThisProcesssOwnPidIsResumedNotWiped) {
    Scratch s;
    const fs::path out = s.dir / "run";
    left_by(out, ::getpid(), "before the reboot");
    StagedDirectory staged(out, true);
    ASSERT_TRUE(staged.adopted());
    EXPECT_EQ(read(staged.path() / "checkpoint.h5"), "before the reboot");
}

TEST(StagedDirectory, AFreshRunLeavesAKilledRunsFolderAlone) {
    Scratch s;
    const fs::path out = s.dir / "run";
    const fs::path killed = left_by(out, gone_pid(), "killed");
    StagedDirectory staged(out, false);
    EXPECT_FALSE(staged.adopted());
    EXPECT_TRUE(fs::is_empty(staged.path()));
    EXPECT_TRUE(fs::exists(killed / "checkpoint.h5"));
}
