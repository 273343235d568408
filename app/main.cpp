// pilempm: pile installation simulator. Command line: run or check a case file.
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "app/jobs/drivability_job.hpp"
#include "app/jobs/drivability_study_job.hpp"
#include "app/jobs/element_test_job.hpp"
#include "app/jobs/mpm_job.hpp"
#include "app/jobs/pile_wave_job.hpp"
#include "io/cases/drivability_case.hpp"
#include "io/yaml/case_error.hpp"

namespace {

constexpr const char* kUsage = R"(pilempm - pile driving simulator (pile wave analysis, drivability, MPM-FEM)

The case file's `analysis:` key selects what runs: pile_wave (one blow travelling down
the pile), drivability (SRD and blow count against depth), drivability_study (the same
at many field locations against their driving records), mpm (the MPM soil) or
element_test (one soil element along laboratory paths).

Usage:
  pilempm run CASE.yaml [--out DIR] [--quiet] [--resume]
                                                run a case; results go to DIR
                                                (default: results/<case name>); --resume
                                                continues an interrupted MPM run from the
                                                checkpoint it left in DIR.incomplete
  pilempm element-test CASE.yaml [--out DIR] [--quiet]
                                                run an element test (same as run)
  pilempm check CASE.yaml                       validate a case and print what would run
  pilempm --help | --version

Exit status: 0 success, 1 failure while running, 2 bad input (case file or arguments).
The case-file format and the outputs are described in README.md.
)";

int usage_error(const std::string& what) {
    std::fprintf(stderr, "pilempm: %s\n\n%s", what.c_str(), kUsage);
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty()) return usage_error("no command given");
    if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        std::printf("%s", kUsage);
        return 0;
    }
    if (args[0] == "--version") {
        std::printf("pilempm %s\n", PILEMPM_VERSION);
        return 0;
    }
    const std::string command = args[0];
    if (command != "run" && command != "check" && command != "element-test")
        return usage_error("unknown command '" + command + "'");
    std::string case_file, out_dir;
    bool quiet = false, resume = false;
    for (std::size_t i = 1; i < args.size(); ++i) {
        if (args[i] == "--quiet" || args[i] == "-q") quiet = true;
        else if (args[i] == "--resume") resume = true;
        else if (args[i] == "--out" || args[i] == "-o") {
            if (i + 1 >= args.size()) return usage_error("--out needs a directory");
            out_dir = args[++i];
        } else if (!args[i].empty() && args[i][0] == '-') return usage_error("unknown option '" + args[i] + "'");
        else if (case_file.empty()) case_file = args[i];
        else return usage_error("more than one case file given");
    }
    if (case_file.empty()) return usage_error(command + " needs a case file");
    if (command == "check" && !out_dir.empty()) return usage_error("check writes nothing; --out is not used");
    if (out_dir.empty()) out_dir = (std::filesystem::path("results") / std::filesystem::path(case_file).stem()).string();
    try {
        const std::string kind = pilempm::io::read_analysis_kind(case_file);
        if (command == "element-test" && kind != "element_test")
            return usage_error("element-test runs analysis: element_test cases; " + case_file + " is analysis: " + kind);
        if (kind == "element_test") {
            if (resume) return usage_error("--resume applies to MPM runs, which write checkpoints");
            return command == "check" ? pilempm::app::check_element_test_case(case_file)
                                      : pilempm::app::run_element_test_case(case_file, out_dir, quiet);
        }
        if (kind == "mpm")
            return command == "check" ? pilempm::app::check_mpm_case(case_file)
                                      : pilempm::app::run_mpm_case(case_file, out_dir, quiet, resume);
        if (resume) return usage_error("--resume applies to MPM runs, which write checkpoints");
        if (kind == "drivability_study")
            return command == "check" ? pilempm::app::check_drivability_study_case(case_file)
                                      : pilempm::app::run_drivability_study_case(case_file, out_dir, quiet);
        const bool drivability = kind == "drivability";
        if (command == "check")
            return drivability ? pilempm::app::check_drivability_case(case_file)
                               : pilempm::app::check_pile_wave_case(case_file);
        return drivability ? pilempm::app::run_drivability_case(case_file, out_dir, quiet)
                           : pilempm::app::run_pile_wave_case(case_file, out_dir, quiet);
    } catch (const pilempm::io::CaseError& e) {
        std::fprintf(stderr, "pilempm: bad input: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pilempm: error: %s\n", e.what());
        return 1;
    }
}
