// Pore-water keys of MPM cases: what a saturated material needs is required, what it
// cannot have is refused, each error naming the key; a valid case builds the water fields,
// the grains' mass and the Darcy resistance its permeability gives.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/cases/mpm_case.hpp"
#include "io/cases/mpm_run_builder.hpp"
#include "io/yaml/case_error.hpp"
#include "tests/unit/io/cases/case_text.hpp"

namespace fs = std::filesystem;
namespace pio = pilempm::io;

namespace {

std::string terzaghi() {
    std::ifstream in(std::string(PILEMPM_SOURCE_DIR) + "/cases/verification/terzaghi-explicit.yaml");
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

using case_text::replaced;
using case_text::write;

std::string error_of(const std::string& text, const std::string& name) { return case_text::mpm_error_of(text, name); }

const char* kPermeability = "drainage: coupled, porosity: 0.4, hydraulic_conductivity: 1.0e-3";

TEST(PoreWaterInput, SaturatedMaterialNeedsAPorosity) {
    const auto msg = error_of(replaced(terzaghi(), kPermeability, "drainage: coupled, hydraulic_conductivity: 1.0e-3"), "n");
    EXPECT_NE(msg.find("materials[0].porosity"), std::string::npos) << msg;
    EXPECT_NE(msg.find("porosity of a saturated material"), std::string::npos) << msg;
}

TEST(PoreWaterInput, CoupledMaterialNeedsExactlyOnePermeability) {
    const auto none = error_of(replaced(terzaghi(), kPermeability, "drainage: coupled, porosity: 0.4"), "k0");
    EXPECT_NE(none.find("hydraulic_conductivity"), std::string::npos) << none;
    EXPECT_NE(none.find("both or neither"), std::string::npos) << none;
    const auto both = error_of(replaced(terzaghi(), kPermeability, std::string(kPermeability) + ", intrinsic_permeability: 1.0e-10"), "k2");
    EXPECT_NE(both.find("both or neither"), std::string::npos) << both;
}

TEST(PoreWaterInput, DryOrUndrainedMaterialRefusesWhatItCannotUse) {
    const auto dry = error_of(replaced(terzaghi(), kPermeability, "porosity: 0.4"), "dry");
    EXPECT_NE(dry.find("materials[0].porosity"), std::string::npos) << dry;
    EXPECT_NE(dry.find("dry material"), std::string::npos) << dry;
    const auto undrained = error_of(replaced(terzaghi(), kPermeability, "drainage: undrained, porosity: 0.4, hydraulic_conductivity: 1.0e-3"), "u");
    EXPECT_NE(undrained.find("unless drainage: coupled"), std::string::npos) << undrained;
    const auto porosity = error_of(replaced(terzaghi(), "porosity: 0.4", "porosity: 1.2"), "n1");
    EXPECT_NE(porosity.find("between 0 and 1"), std::string::npos) << porosity;
    const auto stage = error_of(replaced(terzaghi(), "type: dynamic, duration: 1.0", "type: consolidation, duration: 1.0, step_growth: 3.0"), "g");
    EXPECT_NE(stage.find("step_growth"), std::string::npos) << stage;
}

TEST(PoreWaterInput, ValidCaseBuildsWaterFieldsGrainMassAndDarcyResistance) {
    const fs::path file = write(terzaghi(), "ok");
    const auto c = pio::read_mpm_case(file.string());
    fs::remove(file);
    auto run = pio::build_mpm_run<2>(c);
    const auto& m = run.model;
    EXPECT_TRUE(m.grid.water);
    EXPECT_EQ(m.grid.fields, 2);
    ASSERT_EQ(m.drainage.size(), 1u);
    // k = rho_w g / (mu / kappa) with standard gravity.
    EXPECT_NEAR(1000.0 * 9.80665 / m.drainage[0].darcy_resistance, 1e-3, 1e-15);
    const auto& p = m.particles;
    ASSERT_GT(p.size(), 0u);
    // Grains' mass (rho_sat - n rho_w) V, the porosity on every point.
    EXPECT_NEAR(p.mass[0] / p.volume[0], 2000.0 - 0.4 * 1000.0, 1e-9);
    for (double n : p.porosity) EXPECT_DOUBLE_EQ(n, 0.4);
}

// A stage may hold the coupled water drained (a drained nil step); the key takes drained or
// coupled, and a consolidation, which is about the water's flow, has no such key.
TEST(PoreWaterInput, AStageHoldsTheWaterDrainedOnlyWhenAsked) {
    const std::string stage = "  - {name: consolidation, type: dynamic, duration: 1.0}";
    const fs::path file = write(replaced(terzaghi(), stage, "  - {name: nil, type: quasi_static, drainage: drained}\n" + stage), "drained");
    const auto c = pio::read_mpm_case(file.string());
    fs::remove(file);
    ASSERT_EQ(c.stages.size(), 2u);
    EXPECT_TRUE(c.stages[0].drained);
    EXPECT_FALSE(c.stages[1].drained);
    const auto run = pio::build_mpm_run<2>(c);
    EXPECT_TRUE(run.stages[0].drained);
    const auto bad = error_of(replaced(terzaghi(), "type: dynamic, duration: 1.0", "type: dynamic, drainage: free, duration: 1.0"), "free");
    EXPECT_NE(bad.find("stages[0].drainage"), std::string::npos) << bad;
    EXPECT_NE(bad.find("drained"), std::string::npos) << bad;
    const auto pause = error_of(replaced(terzaghi(), "type: dynamic, duration: 1.0", "type: consolidation, drainage: drained, duration: 1.0"), "pause");
    EXPECT_NE(pause.find("drainage"), std::string::npos) << pause;
}

}  // namespace
