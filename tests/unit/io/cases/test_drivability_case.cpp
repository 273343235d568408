// Drivability case input: the soil from a CPT, the energy plan from a driving log, the
// study section; bad combinations are CaseErrors naming the key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "io/cases/drivability_case.hpp"
#include "io/cases/field_records.hpp"
#include "io/yaml/case_error.hpp"

using namespace pilempm;
namespace fs = std::filesystem;

namespace {

const std::string kData = std::string(PILEMPM_SOURCE_DIR) + "/cases/drivability/data/isfog2020/records.csv";

const char* kHead = R"(title: test
analysis: drivability
pile:
  segments:
    - {length: 37.0, outer_diameter: 2.48, wall_thickness: 0.055}
  steel: {youngs_modulus: 210.0e9, poisson_ratio: 0.3, density: 7850.0}
  element_size: 0.5
hammer:
  type: ram_cushion
  ram: {mass: 60.0e3, model: rigid}
  drop_height: 2.0
  efficiency: 0.95
  helmet_mass: 30.0e3
)";

std::string write_case(const std::string& body, const std::string& head = kHead) {
    static int n = 0;
    const fs::path p = fs::temp_directory_path() /
                       ("pilempm-drivability-case-" + std::to_string(::getpid()) + "-" + std::to_string(++n) + ".yaml");
    std::ofstream(p) << head << body;
    return p.string();
}

std::string error_of(const std::string& file) {
    try {
        io::read_drivability_case(file);
    } catch (const io::CaseError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(DrivabilityCase, SoilAndEnergyPlanFromTheRecords) {
    const std::string f = write_case("soil:\n  water_depth: 30\n  cpt: {file: " + kData + ", location: BG}\n"
                                     "driving:\n  final_depth: 26.0\n  depth_step: 0.5\n"
                                     "  energy_plan: {file: " + kData + ", location: BG, energy_column: "
                                     "normalised_hammer_energy, reference_energy: 1.0e6}\n");
    const io::DrivabilityCase c = io::read_drivability_case(f);
    EXPECT_TRUE(c.cpt_soil);
    EXPECT_EQ(c.soil.layers.size(), 79u);  // one per CPT depth
    EXPECT_EQ(c.soil.cpt.depth.size(), 79u);
    const auto bg = io::read_field_records(kData, {"BG"}).front();
    ASSERT_EQ(c.energy_plan_depth.size(), bg.driven_depth.size());
    const double rated = 60e3 * 9.81 * 2.0;
    EXPECT_NEAR(c.energy_plan_level.front(), bg.normalised_energy.front() * 1e6 / rated, 1e-12);
    EXPECT_NEAR(c.energy_plan_level.back(), bg.normalised_energy.back() * 1e6 / rated, 1e-12);
    const auto s = io::build_drivability_setup(c);
    EXPECT_EQ(s.energy_plan_depth, c.energy_plan_depth);
    fs::remove(f);
}

TEST(DrivabilityCase, CptBesideLayersIsRefused) {
    const std::string f = write_case("soil:\n  cpt: {file: " + kData + ", location: BG}\n  layers:\n"
                                     "    - {top: 0, bottom: 30, type: sand, submerged_unit_weight: 1e4, "
                                     "relative_density: 0.5, interface_friction_angle: 25}\n"
                                     "driving: {final_depth: 26.0}\n");
    EXPECT_NE(error_of(f).find("soil.layers"), std::string::npos) << error_of(f);
    fs::remove(f);
}

TEST(DrivabilityCase, UnknownLocationAndBadPlanNameTheirKeys) {
    const std::string a = write_case("soil:\n  cpt: {file: " + kData + ", location: ZZ}\ndriving: {final_depth: 26.0}\n");
    EXPECT_NE(error_of(a).find("soil.cpt.location"), std::string::npos) << error_of(a);
    const std::string b = write_case("soil:\n  cpt: {file: " + kData + ", location: BG}\n"
                                     "driving:\n  final_depth: 26.0\n  energy_plan: {depth: [1, 0.5], energy: [0.5, 0.6]}\n");
    EXPECT_NE(error_of(b).find("driving.energy_plan.depth"), std::string::npos) << error_of(b);
    const std::string c = write_case("soil:\n  cpt: {file: " + kData + ", location: BG}\n"
                                     "driving:\n  final_depth: 26.0\n  energy_plan: {depth: [1, 2], energy: [0.5]}\n");
    EXPECT_NE(error_of(c).find("driving.energy_plan.energy"), std::string::npos) << error_of(c);
    for (const auto& f : {a, b, c}) fs::remove(f);
}

TEST(DrivabilityCase, StudyNeedsItsBandAndCalibrationCases) {
    std::string head = kHead;
    head.replace(head.find("analysis: drivability"), 21, "analysis: drivability_study");
    const std::string f = write_case("soil:\n  cpt: {net_area_ratio: 0.8}\ndriving: {depth_step: 0.5}\n"
                                     "soil_cases:\n  - {name: best_estimate, method: alm_hamre_2001}\n"
                                     "study:\n  records: " + kData + "\n  reference_energy: 1.0e6\n",
                                     head);
    EXPECT_NE(error_of(f).find("soil_cases"), std::string::npos) << error_of(f);
    const std::string g = write_case("soil:\n  cpt: {net_area_ratio: 0.8}\ndriving: {depth_step: 0.5}\n"
                                     "soil_cases:\n  - {name: lower_bound, method: stevens_lower_bound}\n"
                                     "  - {name: upper_bound, method: unified_2020}\n"
                                     "study:\n  records: " + kData + "\n  locations: [BG, AA]\n  reference_energy: 1.0e6\n",
                                     head);
    const io::DrivabilityCase c = io::read_drivability_case(g);
    EXPECT_TRUE(c.study_mode);
    EXPECT_EQ(c.study.locations, (std::vector<std::string>{"BG", "AA"}));
    EXPECT_EQ(c.cases.back().method, coupling::SrdMethod::Unified2020);
    fs::remove(f);
    fs::remove(g);
}

namespace {

// A coupled run's output folder as `pilempm run` leaves it: three blows (stages 2, 4, 6),
// the head's record in history.csv (its nil step's rows too).
fs::path write_coupled_run() {
    const fs::path dir = fs::temp_directory_path() / ("pilempm-coupled-run-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "blows.csv") << "blow,stage,start_time_s,toe_depth_before_m,set_m,enthru_J\n"
                                        "1,2,0,5.0,0.040,1.5e6\n2,4,1.25,5.04,0.030,1.6e6\n3,6,2.5,5.07,0.020,1.4e6\n";
    std::ofstream h(dir / "history.csv");
    h << "time_s,stage,pile_head_force_N,pile_head_velocity_m_s\n-0.1,1,0,0\n";
    for (int stage : {2, 4, 6})
        for (int i = 1; i <= 3; ++i)
            h << 1.25 * (stage / 2 - 1) + 0.01 * i << "," << stage << "," << 1000 * stage + i << "," << 0.1 * i << "\n";
    return dir;
}

}  // namespace

TEST(DrivabilityCase, CalibrationReadsTheCoupledRunsBlowsAndTheLastHeadRecord) {
    const fs::path run = write_coupled_run();
    const std::string body = "soil:\n  layers:\n    - {top: 0.0, bottom: 40.0, type: sand, submerged_unit_weight: 1.0e4,"
                             " relative_density: 0.8, interface_friction_angle: 28}\n"
                             "driving: {final_depth: 10.0}\n";
    const std::string f = write_case(body + "calibration:\n  runs: [" + run.string() +
                                     "]\n  fit: [srd_factor, toe_quake]\n");
    const io::DrivabilityCase c = io::read_drivability_case(f);
    ASSERT_EQ(c.calibration_targets.size(), 1u);
    const auto& t = c.calibration_targets.front();
    // The first blow left out (skip_blows 1 by default): the mean of the other two.
    EXPECT_EQ(t.blows, 2);
    EXPECT_NEAR(t.set, 0.025, 1e-12);
    EXPECT_NEAR(t.depth, 5.055, 1e-12);
    EXPECT_NEAR(t.enthru, 1.5e6, 1e-6);
    ASSERT_EQ(t.record.time.size(), 3u);  // the last blow's rows, timed from its start
    EXPECT_NEAR(t.record.time.front(), 0.01, 1e-12);
    EXPECT_NEAR(t.record.force.back(), 6003.0, 1e-9);
    EXPECT_NEAR(t.record.velocity.back(), 0.3, 1e-12);
    EXPECT_EQ(c.calibration.fit.size(), 2u);

    const std::string missing = write_case(body + "calibration:\n  runs: [" + run.string() + "-none]\n");
    EXPECT_NE(error_of(missing).find("calibration.runs[0]"), std::string::npos) << error_of(missing);
    EXPECT_NE(error_of(missing).find("without blows.csv"), std::string::npos) << error_of(missing);
    const std::string too_few = write_case(body + "calibration:\n  runs: [" + run.string() + "]\n  skip_blows: 3\n");
    EXPECT_NE(error_of(too_few).find("more blows than skip_blows"), std::string::npos) << error_of(too_few);
    const std::string bad_fit = write_case(body + "calibration:\n  runs: [" + run.string() + "]\n  fit: [srd_factor, quake]\n");
    EXPECT_NE(error_of(bad_fit).find("calibration.fit[1]"), std::string::npos) << error_of(bad_fit);
    const std::string bad_case = write_case(body + "calibration:\n  runs: [" + run.string() + "]\n  soil_case: middle\n");
    EXPECT_NE(error_of(bad_case).find("calibration.soil_case"), std::string::npos) << error_of(bad_case);
    for (const auto& file : {f, missing, too_few, bad_fit, bad_case}) fs::remove(file);

    // A coupled drive's blow count as the reference of the calibrated sheet: each interval's
    // bottom, the last (the drive ended in it) left out; a file of another kind names the key.
    std::ofstream(run / "blow_count.csv") << "depth_top_m,depth_bottom_m,blows,blows_per_m,cumulative_blows\n"
                                             "5,5.25,8,32,8\n5.25,5.5,13,52,21\n5.5,5.75,17,68,38\n5.75,6,5,20,43\n";
    const std::string calibration = "calibration:\n  runs: [" + run.string() + "]\n";
    const std::string counted = write_case(body + calibration + "verification:\n  checks: [calibrated_blow_count]\n"
                                           "  reference_blow_count: " + (run / "blow_count.csv").string() + "\n");
    const io::DrivabilityCase d = io::read_drivability_case(counted);
    EXPECT_EQ(d.reference_drive.depth, (std::vector<double>{5.25, 5.5, 5.75}));
    EXPECT_EQ(d.reference_drive.cumulative_blows, (std::vector<double>{8, 21, 38}));
    EXPECT_DOUBLE_EQ(d.reference_drive.total_blows(), 30.0);
    EXPECT_DOUBLE_EQ(d.blow_count_tolerance, 0.15);
    const std::string wrong = write_case(body + calibration + "verification:\n  checks: [calibrated_blow_count]\n"
                                         "  reference_blow_count: " + (run / "blows.csv").string() + "\n");
    EXPECT_NE(error_of(wrong).find("verification.reference_blow_count"), std::string::npos) << error_of(wrong);
    EXPECT_NE(error_of(wrong).find("no column depth_bottom_m"), std::string::npos) << error_of(wrong);
    for (const auto& file : {counted, wrong}) fs::remove(file);
    fs::remove_all(run);
}
