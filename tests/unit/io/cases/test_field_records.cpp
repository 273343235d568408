// Field records (ISFOG 2020 layout): the shipped file's locations against counts read off
// the CSV, units converted, and errors that name the file, line and column.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "io/cases/field_records.hpp"
#include "io/yaml/case_error.hpp"

using namespace pilempm::io;
namespace fs = std::filesystem;

namespace {

const std::string kRecords = std::string(PILEMPM_SOURCE_DIR) + "/cases/drivability/data/isfog2020/records.csv";

fs::path write_temp(const std::string& name, const std::string& text) {
    const fs::path p = fs::temp_directory_path() / ("pilempm-records-" + std::to_string(::getpid()) + "-" + name);
    std::ofstream(p) << text;
    return p;
}

}  // namespace

TEST(FieldRecords, ShippedIsfogFile) {
    const auto all = read_field_records(kRecords);
    ASSERT_EQ(all.size(), 38u);
    const auto bg = read_field_records(kRecords, {"BG"}).front();
    // BG: 79 CPT rows 0.5..39.5 m, driven 4.0..26.0 m (45 depths), D 2.48 m, wall 55 mm, 27 m.
    EXPECT_EQ(bg.cpt.depth.size(), 79u);
    EXPECT_EQ(bg.driven_depth.size(), 45u);
    EXPECT_DOUBLE_EQ(bg.driven_depth.front(), 4.0);
    EXPECT_DOUBLE_EQ(bg.driven_depth.back(), 26.0);
    EXPECT_DOUBLE_EQ(bg.diameter, 2.48);
    EXPECT_DOUBLE_EQ(bg.toe_wall, 0.055);
    EXPECT_DOUBLE_EQ(bg.final_penetration, 27.0);
    EXPECT_DOUBLE_EQ(bg.cpt.qc[1], 9.389e6);   // row "BG,1.0,9.389,..." in MPa -> Pa
    EXPECT_DOUBLE_EQ(bg.blows_per_m.front(), 8.0);
    EXPECT_DOUBLE_EQ(bg.cumulative_blows.back(), 1397.0);
}

TEST(FieldRecords, UnknownLocationAndBadCellsNameTheirPlace) {
    EXPECT_THROW(read_field_records(kRecords, {"ZZ"}), CaseError);
    const fs::path bad = write_temp("bad.csv",
        "location,depth_m,qc_MPa,fs_MPa,u2_MPa,blows_per_m,normalised_enthru,normalised_hammer_energy,"
        "cumulative_blows,diameter_m,bottom_wall_thickness_mm,final_penetration_m\n"
        "AA,0.5,1.0,0.01,0.0,,,,,2.48,55,20\n"
        "AA,1.0,x,0.01,0.0,,,,,2.48,55,20\n");
    try {
        read_field_records(bad.string());
        FAIL() << "a cell that is not a number must be refused";
    } catch (const CaseError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find(bad.string() + ":3"), std::string::npos) << m;
        EXPECT_NE(m.find("qc_MPa"), std::string::npos) << m;
    }
    const fs::path missing = write_temp("missing.csv", "location,depth_m\nAA,1.0\n");
    EXPECT_THROW(read_field_records(missing.string()), CaseError);
    fs::remove(bad);
    fs::remove(missing);
}
