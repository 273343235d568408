// volumetric_strain: point (default) | nodal_average reaches the model; anything else is an
// input error naming the key and the choices.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/unit/io/cases/case_text.hpp"

using namespace case_text;
namespace pio = pilempm::io;

TEST(VolumetricStrainInput, NodalAverageReachesTheModelAndPointIsTheDefault) {
    const std::string text = shipped("cases/verification/mpm-lame-cylinder-incompressible.yaml");
    for (const bool given : {true, false}) {
        const auto file = write(given ? text : replaced(text, "\nvolumetric_strain: nodal_average\n", "\n"), "volstrain");
        const auto run = pio::build_mpm_run<2>(pio::read_mpm_case(file.string()));
        std::filesystem::remove(file);
        EXPECT_EQ(run.model.smooth_dilatation, given);
    }
    const auto bad = mpm_error_of(replaced(text, "\nvolumetric_strain: nodal_average", "\nvolumetric_strain: cell_average"), "volstrain_bad");
    EXPECT_NE(bad.find("volumetric_strain"), std::string::npos) << bad;
    EXPECT_NE(bad.find("nodal_average"), std::string::npos) << bad;
    EXPECT_NE(bad.find("cell_average"), std::string::npos) << bad;
}
