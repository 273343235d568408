// Strict validation of case files. Every bad case is written at run time into a fresh
// temporary folder, starting from one small valid case (kBase) changed in one place.
//
// Part 1 calls the library (read_pile_wave_case, build_pile_wave_setup) and requires a
// CaseError whose message names the file, the 1-based line, the full key path, what was
// expected and what was found. Part 2 runs the real `pilempm` program and checks the exit
// status, the message on stderr and that a bad case leaves the output folder untouched.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "io/yaml/case_error.hpp"
#include "io/cases/pile_wave_case.hpp"

namespace fs = std::filesystem;
namespace pio = pilempm::io;

namespace {

// A 10 m rod pile struck by a 2 ms half-sine pulse, 4 ms of simulated time. Block style
// throughout, so every key sits on its own line.
const std::string kBase = R"(# base case of the validation tests
title: validation base case
analysis: pile_wave
pile:
  model: rod
  segments:
    - length: 10.0
      outer_diameter: 0.6
      wall_thickness: 0.0125
  steel:
    youngs_modulus: 210.0e9
    poisson_ratio: 0.3
    density: 7850.0
  element_size: 0.1
  toe:
    condition: free
hammer:
  type: half_sine
  peak_force: 1.0e6
  impulse_time: 0.002
simulation:
  duration: 0.004
output:
  gauges: [2.0, 8.0]
  snapshot_interval: 0.0
  plots: false
)";

const std::string kHalfSineHammer = R"(hammer:
  type: half_sine
  peak_force: 1.0e6
  impulse_time: 0.002
)";

// `text` with the one occurrence of `from` replaced by `to`; a test failure if `from` does
// not occur exactly once (the test would not test what it says).
std::string with(const std::string& text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    if (at == std::string::npos || text.find(from, at + 1) != std::string::npos) {
        ADD_FAILURE() << "the base case does not contain '" << from << "' exactly once";
        return text;
    }
    std::string out = text;
    out.replace(at, from.size(), to);
    return out;
}

// 1-based line of the one line of `text` that contains `needle`; 0 (and a failure) if none
// or several do.
int line_of(const std::string& text, const std::string& needle) {
    std::istringstream in(text);
    std::string line;
    int n = 0, found = 0, count = 0;
    while (std::getline(in, line)) {
        ++n;
        if (line.find(needle) != std::string::npos) {
            found = n;
            ++count;
        }
    }
    if (count != 1) {
        ADD_FAILURE() << "'" << needle << "' is on " << count << " lines of the case, not one";
        return 0;
    }
    return found;
}

// Reads the case (and builds the setup when `build`); returns the CaseError's message.
// Accepting the case, or throwing anything else, is a test failure.
std::string case_error(const fs::path& file, bool build = false) {
    try {
        const pio::PileWaveCase c = pio::read_pile_wave_case(file.string());
        if (build) (void)pio::build_pile_wave_setup(c);
    } catch (const pio::CaseError& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "expected a CaseError, got another exception: " << e.what();
        return "";
    } catch (...) {
        ADD_FAILURE() << "expected a CaseError, got a non-standard exception";
        return "";
    }
    ADD_FAILURE() << file << " was accepted, expected a CaseError";
    return "";
}

// The message names everything: "FILE:LINE: KEY: expected EXPECTED..., found FOUND...".
::testing::AssertionResult names_all(const std::string& msg, const fs::path& file, int line,
                                     const std::string& key, const std::string& expected,
                                     const std::string& found) {
    const std::string where = file.string() + ":" + std::to_string(line) + ": ";
    std::vector<std::string> missing;
    if (msg.rfind(where, 0) != 0) missing.push_back("file and line '" + where + "' at the start");
    if (msg.find(": " + key + ": expected ") == std::string::npos)
        missing.push_back("the key path '" + key + "' followed by 'expected'");
    if (msg.find("expected " + expected) == std::string::npos)
        missing.push_back("'expected " + expected + "'");
    if (msg.find(", found " + found) == std::string::npos) missing.push_back("', found " + found + "'");
    if (missing.empty()) return ::testing::AssertionSuccess();
    auto r = ::testing::AssertionFailure();
    r << "message: \"" << msg << "\"\n  lacks:";
    for (const auto& m : missing) r << "\n    " << m;
    return r;
}

std::string read_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string quoted(const std::string& s) {  // for /bin/sh
    std::string q = "'";
    for (char ch : s) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
    return q + "'";
}

struct CliResult {
    int status = -1;  // exit status, -1 if the program did not exit normally
    std::string out, err;
};

class CaseValidation : public ::testing::Test {
protected:
    void SetUp() override {
        static int serial = 0;
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               ("pilempm-case-validation-" + std::to_string(::getpid()) + "-" +
                std::to_string(++serial) + "-" + info->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }

    fs::path write(const std::string& name, const std::string& text) const {
        const fs::path p = dir_ / name;
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }

    // Runs `pilempm ARGS` (ARGS already quoted) with stdout and stderr captured.
    CliResult cli(const std::string& args) const {
        const fs::path out = dir_ / "cli-stdout.txt", err = dir_ / "cli-stderr.txt";
        const std::string cmd = quoted(PILEMPM_EXECUTABLE) + " " + args + " >" + quoted(out.string()) +
                                " 2>" + quoted(err.string()) + " </dev/null";
        const int raw = std::system(cmd.c_str());
        CliResult r;
        if (raw != -1 && WIFEXITED(raw)) r.status = WEXITSTATUS(raw);
        r.out = read_text(out);
        r.err = read_text(err);
        std::error_code ec;
        fs::remove(out, ec);
        fs::remove(err, ec);
        return r;
    }

    // Entries beside `dir` named like its staging or replaced copies.
    static std::vector<std::string> leftovers(const fs::path& dir) {
        std::vector<std::string> found;
        if (!fs::exists(dir.parent_path())) return found;
        const std::string stem = dir.filename().string();
        for (const auto& e : fs::directory_iterator(dir.parent_path())) {
            const std::string name = e.path().filename().string();
            if (name.rfind(stem + ".partial-", 0) == 0 || name.rfind(stem + ".old-", 0) == 0)
                found.push_back(name);
        }
        return found;
    }

    fs::path dir_;
};

// ---------------------------------------------------------------------------------------
// Part 1: the library
// ---------------------------------------------------------------------------------------

TEST_F(CaseValidation, BaseCaseIsValid) {
    const auto f = write("base.yaml", kBase);
    const pio::PileWaveCase c = pio::read_pile_wave_case(f.string());
    ASSERT_EQ(c.segments.size(), 1u);
    EXPECT_DOUBLE_EQ(c.segments[0].length, 10.0);
    EXPECT_EQ(c.gauge_depths.size(), 2u);
    EXPECT_NO_THROW((void)pio::build_pile_wave_setup(c));
}

// (a) unknown keys, at the top level and nested
TEST_F(CaseValidation, UnknownTopLevelKey) {
    const std::string text = with(kBase, "analysis: pile_wave\n", "analysis: pile_wave\nsolver: fast\n");
    const auto f = write("unknown-top.yaml", text);
    EXPECT_TRUE(names_all(case_error(f), f, line_of(text, "solver:"), "solver", "one of the keys",
                          "the unknown key 'solver'"));

    const std::string typo = with(kBase, "title: validation", "titel: validation");
    const auto g = write("typo-top.yaml", typo);
    EXPECT_TRUE(names_all(case_error(g), g, line_of(typo, "titel:"), "titel", "one of the keys",
                          "the unknown key 'titel'"));
}

TEST_F(CaseValidation, UnknownNestedKey) {
    const std::string text = with(kBase, "    density: 7850.0\n", "    density: 7850.0\n    densty: 7850.0\n");
    const auto f = write("unknown-steel.yaml", text);
    const std::string msg = case_error(f);
    EXPECT_TRUE(names_all(msg, f, line_of(text, "densty:"), "pile.steel.densty", "one of the keys",
                          "the unknown key 'densty'"));
    EXPECT_NE(msg.find("density"), std::string::npos) << "the message lists the known keys: " << msg;

    // A misspelt optional key is unknown too (the default is not taken silently).
    const std::string opt = with(kBase, "poisson_ratio: 0.3", "poisson_ration: 0.3");
    const auto g = write("unknown-poisson.yaml", opt);
    EXPECT_TRUE(names_all(case_error(g), g, line_of(opt, "poisson_ration:"), "pile.steel.poisson_ration",
                          "one of the keys", "the unknown key 'poisson_ration'"));

    // In a list element.
    const std::string seg = with(kBase, "      wall_thickness: 0.0125\n",
                                 "      wall_thickness: 0.0125\n      wall: 0.02\n");
    const auto h = write("unknown-segment.yaml", seg);
    EXPECT_TRUE(names_all(case_error(h), h, line_of(seg, "wall: 0.02"), "pile.segments[0].wall",
                          "one of the keys", "the unknown key 'wall'"));
}

// (b) missing required keys. A missing key has no line of its own: the message points at
// the mapping that lacks it, i.e. at the line of its parent key or at the mapping's first
// line (the reader uses the latter); either is accepted here.
TEST_F(CaseValidation, MissingRequiredKey) {
    {
        const std::string text = with(kBase, "  element_size: 0.1\n", "");
        const auto f = write("missing-element-size.yaml", text);
        const std::string msg = case_error(f);
        const int parent = line_of(text, "pile:");
        EXPECT_TRUE(names_all(msg, f, parent, "pile.element_size", "a positive element size",
                              "the key missing") ||
                    names_all(msg, f, parent + 1, "pile.element_size", "a positive element size",
                              "the key missing"))
            << msg;
    }
    {
        const std::string text = with(kBase, "  type: half_sine\n", "");
        const auto f = write("missing-hammer-type.yaml", text);
        const std::string msg = case_error(f);
        const int parent = line_of(text, "hammer:");
        EXPECT_TRUE(names_all(msg, f, parent, "hammer.type", "one of half_sine, force_table, ram_cushion",
                              "the key missing") ||
                    names_all(msg, f, parent + 1, "hammer.type", "one of half_sine, force_table, ram_cushion",
                              "the key missing"))
            << msg;
    }
    {
        // A misspelt required key is reported as the required key missing (it comes first).
        const std::string text = with(kBase, "density: 7850.0", "densty: 7850.0");
        const auto f = write("misspelt-density.yaml", text);
        const std::string msg = case_error(f);
        const int parent = line_of(text, "steel:");
        EXPECT_TRUE(names_all(msg, f, parent, "pile.steel.density", "a positive density", "the key missing") ||
                    names_all(msg, f, parent + 1, "pile.steel.density", "a positive density", "the key missing"))
            << msg;
    }
}

// (c) wrong types
TEST_F(CaseValidation, StringWhereNumberExpected) {
    const std::string text = with(kBase, "length: 10.0", "length: ten");
    const auto f = write("string-length.yaml", text);
    EXPECT_TRUE(names_all(case_error(f), f, line_of(text, "length: ten"), "pile.segments[0].length",
                          "a positive length", "'ten'"));

    // A number with its unit is not a number.
    const std::string unit = with(kBase, "length: 10.0", "length: 10 m");
    const auto g = write("unit-length.yaml", unit);
    EXPECT_TRUE(names_all(case_error(g), g, line_of(unit, "length: 10 m"), "pile.segments[0].length",
                          "a positive length", "'10 m'"));

    const std::string list = with(kBase, "density: 7850.0", "density: [7850.0]");
    const auto h = write("list-density.yaml", list);
    EXPECT_TRUE(names_all(case_error(h), h, line_of(list, "density: [7850.0]"), "pile.steel.density",
                          "a positive density", "a list"));
}

TEST_F(CaseValidation, MappingWhereListExpected) {
    const std::string text = with(kBase,
                                  "    - length: 10.0\n      outer_diameter: 0.6\n      wall_thickness: 0.0125\n",
                                  "    length: 10.0\n    outer_diameter: 0.6\n    wall_thickness: 0.0125\n");
    const auto f = write("segments-mapping.yaml", text);
    EXPECT_TRUE(names_all(case_error(f), f, line_of(text, "segments:"), "pile.segments",
                          "a non-empty list of mappings", "a mapping"));
}

// A key with no value (`density:`) is reported at the key's own line: yaml-cpp gives an
// empty value the position of whatever follows it, here 4 lines further down.
TEST_F(CaseValidation, EmptyValueNamesTheKeysLine) {
    const std::string text = with(kBase, "    density: 7850.0\n", "    density:\n\n\n    # no value above\n");
    const auto f = write("empty-density.yaml", text);
    EXPECT_TRUE(names_all(case_error(f), f, line_of(text, "density:"), "pile.steel.density",
                          "a positive density", "nothing"));
}

// (d) non-physical values, each with a valid value next to the limit as a control
TEST_F(CaseValidation, NegativeLength) {
    const std::string text = with(kBase, "length: 10.0", "length: -10.0");
    const auto f = write("negative-length.yaml", text);
    EXPECT_TRUE(names_all(case_error(f), f, line_of(text, "length: -10.0"), "pile.segments[0].length",
                          "a positive length in m", "-10.0"));
}

TEST_F(CaseValidation, ZeroDensity) {
    const std::string text = with(kBase, "density: 7850.0", "density: 0");
    const auto f = write("zero-density.yaml", text);
    EXPECT_TRUE(names_all(case_error(f), f, line_of(text, "density: 0"), "pile.steel.density",
                          "a positive density", "0"));
}

TEST_F(CaseValidation, PoissonRatioAtOrAboveOneHalf) {
    for (const std::string nu : {"0.5", "0.6"}) {
        SCOPED_TRACE("poisson_ratio " + nu);
        const std::string text = with(kBase, "poisson_ratio: 0.3", "poisson_ratio: " + nu);
        const auto f = write("poisson-" + nu + ".yaml", text);
        EXPECT_TRUE(names_all(case_error(f), f, line_of(text, "poisson_ratio:"), "pile.steel.poisson_ratio",
                              "a Poisson's ratio strictly between -1 and 0.5", nu));
    }
    const auto ok = write("poisson-ok.yaml", with(kBase, "poisson_ratio: 0.3", "poisson_ratio: 0.49"));
    EXPECT_NO_THROW((void)pio::read_pile_wave_case(ok.string()));
}

TEST_F(CaseValidation, WallThickerThanOuterRadius) {
    const std::string text = with(kBase, "wall_thickness: 0.0125", "wall_thickness: 0.4");
    const auto f = write("thick-wall.yaml", text);
    EXPECT_TRUE(names_all(case_error(f), f, line_of(text, "wall_thickness:"), "pile.segments[0].wall_thickness",
                          "a wall no thicker than the outer radius", "0.4 m"));
    // exactly the outer radius: a solid (closed-ended) section, accepted
    const auto g = write("solid-wall.yaml", with(kBase, "wall_thickness: 0.0125", "wall_thickness: 0.3"));
    EXPECT_NO_THROW((void)pio::read_pile_wave_case(g.string()));
}

TEST_F(CaseValidation, EfficiencyAboveOne) {
    const auto hammer = [](const std::string& eta) {
        return with(kBase, "  peak_force: 1.0e6\n",
                    "  ram_mass: 1000.0\n  drop_height: 1.0\n  efficiency: " + eta + "\n");
    };
    const std::string text = hammer("1.2");
    const auto f = write("efficiency.yaml", text);
    EXPECT_TRUE(names_all(case_error(f), f, line_of(text, "efficiency:"), "hammer.efficiency",
                          "an efficiency greater than 0 and at most 1", "1.2"));
    const auto ok = write("efficiency-ok.yaml", hammer("1.0"));
    EXPECT_NO_THROW((void)pio::read_pile_wave_case(ok.string()));
}

TEST_F(CaseValidation, RestitutionOfZero) {
    const auto hammer = [](const std::string& e) {
        return with(kBase, kHalfSineHammer,
                    "hammer:\n  type: ram_cushion\n  ram:\n    mass: 1000.0\n  impact_velocity: 3.0\n"
                    "  hammer_cushion:\n    stiffness: 1.0e9\n    restitution: " + e + "\n");
    };
    const std::string text = hammer("0");
    const auto f = write("restitution.yaml", text);
    EXPECT_TRUE(names_all(case_error(f), f, line_of(text, "restitution:"), "hammer.hammer_cushion.restitution",
                          "a coefficient of restitution greater than 0 and at most 1", "0"));
    const auto ok = write("restitution-ok.yaml", hammer("1.0"));
    EXPECT_NO_THROW((void)pio::read_pile_wave_case(ok.string()));
}

// (e) a time step above the stable one: found when the model is built
TEST_F(CaseValidation, TimeStepAboveStableStep) {
    // rod elements of 0.1 m, c = 5172 m/s: the stable step is 1.93e-5 s
    const std::string text = with(kBase, "  duration: 0.004\n", "  duration: 0.004\n  time_step: 1.0e-4\n");
    const auto f = write("time-step.yaml", text);
    EXPECT_NO_THROW((void)pio::read_pile_wave_case(f.string()));  // reading alone accepts it
    EXPECT_TRUE(names_all(case_error(f, true), f, line_of(text, "time_step:"), "simulation.time_step",
                          "a time step no larger than the stable one", "0.0001 s"));

    const auto ok = write("time-step-ok.yaml",
                          with(kBase, "  duration: 0.004\n", "  duration: 0.004\n  time_step: 1.0e-6\n"));
    EXPECT_NO_THROW((void)pio::build_pile_wave_setup(pio::read_pile_wave_case(ok.string())));
}

// (f) YAML syntax. The parser notices the error at the offending line or the next one.
TEST_F(CaseValidation, InvalidYamlSyntax) {
    struct Bad {
        std::string name, from, to, needle;
    };
    const std::vector<Bad> bads = {
        {"no-colon.yaml", "  element_size: 0.1", "  element_size 0.1", "element_size 0.1"},
        {"open-brace.yaml", "  steel:\n", "  steel: {youngs_modulus: 1\n", "{youngs_modulus"},
    };
    for (const auto& b : bads) {
        SCOPED_TRACE(b.name);
        const std::string text = with(kBase, b.from, b.to);
        const auto f = write(b.name, text);
        const std::string msg = case_error(f);
        const int line = line_of(text, b.needle);
        EXPECT_TRUE(names_all(msg, f, line, "(document)", "valid YAML", "") ||
                    names_all(msg, f, line + 1, "(document)", "valid YAML", ""));
    }
    // An empty file and a top-level list are not cases either.
    const auto empty = write("empty.yaml", "");
    EXPECT_TRUE(names_all(case_error(empty), empty, 1, "(document)", "a mapping at the top level", "nothing"));
    const auto list = write("list.yaml", "- 1\n- 2\n");
    EXPECT_TRUE(names_all(case_error(list), list, 1, "(document)", "a mapping at the top level", "a list"));
}

// (g) no such file: there is no line to name
TEST_F(CaseValidation, MissingCaseFile) {
    const fs::path f = dir_ / "does-not-exist.yaml";
    const std::string msg = case_error(f);
    EXPECT_EQ(msg.rfind(f.string() + ": ", 0), 0u) << msg;
    EXPECT_NE(msg.find("expected a readable case file"), std::string::npos) << msg;
    EXPECT_NE(msg.find("found no such file"), std::string::npos) << msg;
}

// (h) a toe condition that is not one of the three
TEST_F(CaseValidation, UnknownToeCondition) {
    const std::string text = with(kBase, "condition: free", "condition: sliding");
    const auto f = write("sliding.yaml", text);
    EXPECT_TRUE(names_all(case_error(f), f, line_of(text, "condition:"), "pile.toe.condition",
                          "one of free, fixed, dashpot", "'sliding'"));
}

// (i) force tables whose times do not increase
TEST_F(CaseValidation, ForceTableTimesNotIncreasing) {
    const std::string text = with(kBase, kHalfSineHammer,
                                  "hammer:\n  type: force_table\n  table:\n    - [0.0, 0.0]\n"
                                  "    - [0.001, 1.0e6]\n    - [0.001, 0.0]\n");
    const auto f = write("table.yaml", text);
    // The error points at the offending row itself.
    EXPECT_TRUE(names_all(case_error(f), f, line_of(text, "    - [0.001, 0.0]"), "hammer.table[2]",
                          "times that increase row by row", "t = 0.001000 s"));

    // the same from a CSV file next to the case
    write("force.csv", "time_s,force_N\n0.0,0.0\n0.002,1.0e6\n0.001,0.0\n");
    const std::string csv = with(kBase, kHalfSineHammer, "hammer:\n  type: force_table\n  file: force.csv\n");
    const auto g = write("table-file.yaml", csv);
    // ...or, in a CSV file, at that file's row.
    EXPECT_TRUE(names_all(case_error(g), dir_ / "force.csv", 4, "time_s", "values that increase row by row",
                          "0.001000"));

    // control: increasing times are accepted
    const auto ok = write("table-ok.yaml", with(text, "    - [0.001, 0.0]\n", "    - [0.002, 0.0]\n"));
    EXPECT_NO_THROW((void)pio::read_pile_wave_case(ok.string()));
}

// A force-table file that does not exist is reported at the line of the `file:` key.
TEST_F(CaseValidation, MissingForceFileNamesTheLine) {
    const std::string text = with(kBase, kHalfSineHammer, "hammer:\n  type: force_table\n  file: no-such.csv\n");
    const auto f = write("table-missing-file.yaml", text);
    EXPECT_TRUE(names_all(case_error(f), f, line_of(text, "file:"), "hammer.file",
                          "a readable CSV file", (dir_ / "no-such.csv").string()));
}

// (j) a gauge below the toe
TEST_F(CaseValidation, GaugeDeeperThanPile) {
    const std::string text = with(kBase, "gauges: [2.0, 8.0]", "gauges: [2.0, 12.0]");
    const auto f = write("gauge.yaml", text);
    EXPECT_TRUE(names_all(case_error(f), f, line_of(text, "gauges:"), "output.gauges[1]",
                          "a depth below the pile head within the pile", "12.0"));
}

// A key given twice in one mapping is an error: yaml-cpp accepts duplicates and would keep
// one value silently.
TEST_F(CaseValidation, DuplicateKeyIsAnError) {
    const std::string text = with(kBase, "    - length: 10.0\n", "    - length: 10.0\n      length: 20.0\n");
    const auto f = write("duplicate.yaml", text);
    std::string msg;
    try {
        (void)pio::read_pile_wave_case(f.string());
    } catch (const pio::CaseError& e) {
        msg = e.what();
    }
    ASSERT_FALSE(msg.empty()) << "a key given twice was accepted";
    EXPECT_EQ(msg.rfind(f.string() + ":" + std::to_string(line_of(text, "length: 20.0")) + ": ", 0), 0u) << msg;
    EXPECT_NE(msg.find("pile.segments[0].length"), std::string::npos) << msg;
}

// ---------------------------------------------------------------------------------------
// Part 2: the command line
// ---------------------------------------------------------------------------------------

TEST_F(CaseValidation, CliBadCaseLeavesMissingOutputFolderAbsent) {
    struct Bad {
        std::string name, text, key;
    };
    const std::vector<Bad> bads = {
        {"bad-key.yaml", with(kBase, "    density: 7850.0\n", "    density: 7850.0\n    densty: 1.0\n"),
         "pile.steel.densty"},
        {"bad-step.yaml", with(kBase, "  duration: 0.004\n", "  duration: 0.004\n  time_step: 1.0e-4\n"),
         "simulation.time_step"},
        {"bad-syntax.yaml", with(kBase, "  element_size: 0.1", "  element_size 0.1"), "(document)"},
    };
    for (const auto& b : bads) {
        SCOPED_TRACE(b.name);
        const auto f = write(b.name, b.text);
        const fs::path parent = dir_ / "not-there-yet";  // neither the folder nor its parent exist
        const fs::path out = parent / "results";
        const CliResult r = cli("run " + quoted(f.string()) + " --out " + quoted(out.string()) + " --quiet");
        EXPECT_EQ(r.status, 2) << r.err;
        EXPECT_NE(r.err.find(f.string() + ":"), std::string::npos) << "stderr: " << r.err;
        EXPECT_NE(r.err.find(b.key), std::string::npos) << "stderr: " << r.err;
        EXPECT_FALSE(fs::exists(out));
        EXPECT_FALSE(fs::exists(parent)) << "the parent of --out was created for a bad case";
        EXPECT_TRUE(leftovers(out).empty());

        // and directly in an existing folder: nothing at all is added beside the case
        const fs::path flat = dir_ / "flat-out";
        const CliResult s = cli("run " + quoted(f.string()) + " --out " + quoted(flat.string()) + " --quiet");
        EXPECT_EQ(s.status, 2) << s.err;
        EXPECT_FALSE(fs::exists(flat));
        EXPECT_TRUE(leftovers(flat).empty());
        for (const auto& e : fs::directory_iterator(dir_))
            EXPECT_EQ(e.path().extension(), ".yaml") << "left behind: " << e.path();
    }
}

TEST_F(CaseValidation, CliBadCaseLeavesExistingOutputFolderUnchanged) {
    const auto f = write("bad.yaml", with(kBase, "condition: free", "condition: sliding"));
    const fs::path out = dir_ / "results";
    fs::create_directories(out);
    const std::string keep = "results of an earlier run\n";
    std::ofstream(out / "keep.txt", std::ios::binary) << keep;
    const auto before = fs::last_write_time(out / "keep.txt");

    const CliResult r = cli("run " + quoted(f.string()) + " --out " + quoted(out.string()) + " --quiet");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find(f.string() + ":"), std::string::npos) << "stderr: " << r.err;
    EXPECT_NE(r.err.find("pile.toe.condition"), std::string::npos) << "stderr: " << r.err;

    ASSERT_TRUE(fs::is_directory(out));
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(out)) names.push_back(e.path().filename().string());
    EXPECT_EQ(names, std::vector<std::string>{"keep.txt"});
    EXPECT_EQ(read_text(out / "keep.txt"), keep);
    EXPECT_EQ(fs::last_write_time(out / "keep.txt"), before);
    EXPECT_TRUE(leftovers(out).empty());
}

TEST_F(CaseValidation, CliCheck) {
    const auto bad = write("bad.yaml", with(kBase, "length: 10.0", "length: -10.0"));
    const CliResult r = cli("check " + quoted(bad.string()));
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find(bad.string() + ":"), std::string::npos) << "stderr: " << r.err;
    EXPECT_NE(r.err.find("pile.segments[0].length"), std::string::npos) << "stderr: " << r.err;

    const auto good = write("good.yaml", kBase);
    const CliResult g = cli("check " + quoted(good.string()));
    EXPECT_EQ(g.status, 0) << g.err;
    EXPECT_NE(g.out.find("valid"), std::string::npos) << g.out;

    const CliResult m = cli("check " + quoted((dir_ / "none.yaml").string()));
    EXPECT_EQ(m.status, 2) << m.err;
    EXPECT_NE(m.err.find("none.yaml"), std::string::npos) << "stderr: " << m.err;
}

TEST_F(CaseValidation, CliArguments) {
    const auto good = write("good.yaml", kBase);
    const fs::path out = dir_ / "out";
    EXPECT_EQ(cli("frobnicate " + quoted(good.string())).status, 2);
    const CliResult opt = cli("run " + quoted(good.string()) + " --out " + quoted(out.string()) + " --frobnicate");
    EXPECT_EQ(opt.status, 2);
    EXPECT_NE(opt.err.find("--frobnicate"), std::string::npos) << opt.err;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_EQ(cli("").status, 2);                                   // no command
    EXPECT_EQ(cli("run").status, 2);                                // no case file
    EXPECT_EQ(cli("run " + quoted(good.string()) + " --out").status, 2);  // --out without a folder
    EXPECT_EQ(cli("check " + quoted(good.string()) + " --out " + quoted(out.string())).status, 2);
    EXPECT_FALSE(fs::exists(out));

    const CliResult help = cli("--help");
    EXPECT_EQ(help.status, 0);
    EXPECT_NE(help.out.find("Usage"), std::string::npos) << help.out;
    const CliResult version = cli("--version");
    EXPECT_EQ(version.status, 0);
    EXPECT_EQ(version.out.rfind("pilempm ", 0), 0u) << version.out;
}

TEST_F(CaseValidation, CliGoodRunWritesEverything) {
    const auto good = write("good.yaml", kBase);
    const fs::path out = dir_ / "results";
    const CliResult r = cli("run " + quoted(good.string()) + " --out " + quoted(out.string()) + " --quiet");
    ASSERT_EQ(r.status, 0) << r.err;
    ASSERT_TRUE(fs::is_directory(out));
    for (const char* name : {"summary.json", "pile_head.csv", "toe.csv", "stress_envelope.csv", "results.h5"}) {
        EXPECT_TRUE(fs::is_regular_file(out / name)) << name;
        if (fs::is_regular_file(out / name)) {
            EXPECT_GT(fs::file_size(out / name), 0u) << name;
        }
    }
    EXPECT_NE(read_text(out / "summary.json").find("peak_head_force_N"), std::string::npos);
    EXPECT_TRUE(leftovers(out).empty());
}

// Every case shipped in cases/ (examples, verification, studies) passes `pilempm check`:
// a key renamed in the reader cannot leave a stale case behind.
TEST_F(CaseValidation, EveryShippedCaseIsValid) {
    int checked = 0;
    for (const auto& e : fs::recursive_directory_iterator(fs::path(PILEMPM_SOURCE_DIR) / "cases")) {
        if (e.path().extension() != ".yaml") continue;
        const CliResult r = cli("check " + quoted(e.path().string()));
        EXPECT_EQ(r.status, 0) << e.path() << ": " << r.err;
        ++checked;
    }
    EXPECT_GT(checked, 30);
}

}  // namespace
