// The pile keys of MPM cases: a pile needs an axisymmetric case and the wall model; one
// starting inside the soil needs wished_in_place, which cuts the soil at its wall; the
// stages' head control is read; a valid case builds the wall mesh, the contact with the
// whole ring's factor and a grid with a field each side of the wall.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "io/cases/mpm_case.hpp"
#include "io/cases/mpm_run_builder.hpp"
#include "io/yaml/case_error.hpp"
#include "tests/unit/io/cases/case_text.hpp"

namespace fs = std::filesystem;
namespace pio = pilempm::io;

namespace {

std::string jacking() { return case_text::shipped("cases/jacking/jacked-open-pile-small.yaml"); }

using case_text::replaced;
using case_text::write;

std::string error_of(const std::string& text, const std::string& name) { return case_text::mpm_error_of(text, name, true); }

}  // namespace

TEST(PileInput, APileNeedsAnAxisymmetricCase) {
    const auto msg = error_of(replaced(jacking(), "geometry: axisymmetric", "geometry: plane_strain"), "plane");
    EXPECT_NE(msg.find("pile"), std::string::npos) << msg;
    EXPECT_NE(msg.find("axisymmetric"), std::string::npos) << msg;
}

TEST(PileInput, ARodHasNoSurfaceToTouch) {
    const auto msg = error_of(replaced(jacking(), "  model: axisymmetric\n", "  model: rod\n"), "rod");
    EXPECT_NE(msg.find("pile.model"), std::string::npos) << msg;
}

TEST(PileInput, APileStartingInTheSoilMustBeWishedInPlace) {
    const std::string embedded = replaced(jacking(), "toe_elevation: 6.0", "toe_elevation: 5.0");
    const auto msg = error_of(embedded, "embedded");
    EXPECT_NE(msg.find("pile.toe_elevation"), std::string::npos) << msg;
    EXPECT_NE(msg.find("wished_in_place"), std::string::npos) << msg;
    EXPECT_NE(msg.find("reaching up to 6.000 m"), std::string::npos) << msg;  // the sand's surface
    // With it the case builds: the points whose centres lie in the steel go (none here:
    // the 20 mm wall lies between the centres 5 cm apart), the overlaps are ignored.
    const fs::path file = write(replaced(embedded, "  friction: 0.4", "  wished_in_place: true\n  friction: 0.4"), "wished");
    const auto run = pio::build_mpm_run<2>(pio::read_mpm_case(file.string()));
    fs::remove(file);
    const auto& p = run.model.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double r = p.x[2 * i], z = p.x[2 * i + 1];
        EXPECT_FALSE(r >= 0.18 && r <= 0.2 && z >= 5.0 && z <= 6.0) << "a point left in the wall at " << r << ", " << z;
    }
    // A wall through the points' centres (r 0.17 to 0.18): the column at r = 0.175 (domains
    // 0.15 to 0.2) is cut into parts 2 cm wide either side, thinner than half a point: each
    // joins the column beyond it (0.10-0.15 and 0.20-0.25), whose domains then end on the
    // wall's faces (0.10-0.17, 0.18-0.25), and the soil's mass is the region's less the
    // steel's volume (per radian, exact for the midpoint rule in r): nothing lost, nothing
    // left in the steel, no sliver.
    const std::string thick = replaced(replaced(embedded, "  friction: 0.4", "  wished_in_place: true\n  friction: 0.4"),
                                       "outer_diameter: 0.4, wall_thickness: 0.02", "outer_diameter: 0.36, wall_thickness: 0.01");
    const fs::path thick_file = write(thick, "thick");
    const auto cut = pio::build_mpm_run<2>(pio::read_mpm_case(thick_file.string()));
    fs::remove(thick_file);
    const auto& q = cut.model.particles;
    EXPECT_EQ(q.size() + 20u, p.size());  // 1 m below the surface, points 5 cm apart
    double mass = 0.0;
    int inside = 0, outside = 0;
    for (std::size_t i = 0; i < q.size(); ++i) {
        mass += q.mass[i];
        const double r = q.x[2 * i], z = q.x[2 * i + 1], half = 0.5 * q.domain0[4 * i];
        if (z < 5.0 || z > 6.0 || r < 0.13 || r > 0.22) continue;
        if (r < 0.17) {
            EXPECT_NEAR(r + half, 0.17, 1e-12) << "inside the wall at z = " << z;
            EXPECT_NEAR(2.0 * half, 0.07, 1e-12) << "inside the wall at z = " << z;
            ++inside;
        } else {
            EXPECT_NEAR(r - half, 0.18, 1e-12) << "outside the wall at z = " << z;
            EXPECT_NEAR(2.0 * half, 0.07, 1e-12) << "outside the wall at z = " << z;
            ++outside;
        }
    }
    EXPECT_EQ(inside, 20);
    EXPECT_EQ(outside, 20);
    const double steel = 1.0 * (0.18 * 0.18 - 0.17 * 0.17) / 2.0, region = 3.0 * 3.0 / 2.0 * 6.0;
    EXPECT_NEAR(mass, 1900.0 * (region - steel), 1e-12 * 1900.0 * region);
    EXPECT_TRUE(run.pile.contact.ignore_initial_overlap);
}

TEST(PileInput, AStageDrivesTheHeadByVelocityOrByForceNotBoth) {
    const auto both = error_of(replaced(jacking(), "pile: {velocity: 0.5,", "pile: {force: 1.0e5, velocity: 0.5,"), "both");
    EXPECT_NE(both.find("stages[0].pile.velocity"), std::string::npos) << both;
    EXPECT_NE(both.find("one of velocity"), std::string::npos) << both;
    const auto neither = error_of(replaced(jacking(), "pile: {velocity: 0.5, rise_time: 0.1}", "pile: {rise_time: 0.1}"), "neither");
    EXPECT_NE(neither.find("neither"), std::string::npos) << neither;
    const fs::path file = write(replaced(jacking(), "pile: {velocity: 0.0, rise_time: 0.05}", "pile: {force: 2.0e5}"), "force");
    const auto c = pio::read_mpm_case(file.string());
    fs::remove(file);
    EXPECT_TRUE(c.stages[1].pile_loaded);
    EXPECT_FALSE(c.stages[1].pile_driven);
    EXPECT_DOUBLE_EQ(c.stages[1].pile_force, 2.0e5);
}

TEST(PileInput, AValidCaseBuildsTheWallTheContactAndAFieldEachSide) {
    const fs::path file = write(jacking(), "valid");
    const auto c = pio::read_mpm_case(file.string());
    fs::remove(file);
    ASSERT_TRUE(c.pile.present);
    EXPECT_DOUBLE_EQ(c.pile.toe_elevation, 6.0);
    EXPECT_DOUBLE_EQ(c.pile.friction, 0.4);
    ASSERT_EQ(c.stages.size(), 2u);
    EXPECT_TRUE(c.stages[0].pile_driven);
    EXPECT_DOUBLE_EQ(c.stages[0].pile_velocity, 0.5);
    const auto run = pio::build_mpm_run<2>(c);
    EXPECT_TRUE(run.pile.present);
    EXPECT_EQ(run.pile.mesh.dim, 2);
    EXPECT_NEAR(run.pile.contact.ring, 2.0 * std::numbers::pi, 1e-15);
    EXPECT_EQ(run.model.grid.fields, 2);
    ASSERT_EQ(run.pile.heads.size(), 2u);
    EXPECT_DOUBLE_EQ(run.pile.heads[1].velocity_down, 0.0);
    EXPECT_TRUE(run.pile.heads[1].driven);
    EXPECT_NEAR(run.pile.gravity, 9.81, 1e-12);
}

// A conical toe: closed-ended piles only, one the pile is long enough for; wished in place,
// the soil in the cone's steel goes and the soil round it stays.
TEST(PileInput, AConicalToeNeedsAClosedPileAndKeepsTheSoilRoundTheCone) {
    const std::string cone = replaced(jacking(), "  friction: 0.4", "  toe_cone_angle: 60.0\n  friction: 0.4");
    const auto open = error_of(cone, "open_cone");
    EXPECT_NE(open.find("pile.toe_cone_angle"), std::string::npos) << open;
    EXPECT_NE(open.find("closed-ended"), std::string::npos) << open;
    const std::string closed = replaced(cone, "outer_diameter: 0.4, wall_thickness: 0.02", "outer_diameter: 0.4, wall_thickness: 0.2");
    const auto sharp = error_of(replaced(closed, "toe_cone_angle: 60.0", "toe_cone_angle: 10.0"), "sharp_cone");  // 2 h = 4.6 m
    EXPECT_NE(sharp.find("pile.toe_cone_angle"), std::string::npos) << sharp;
    EXPECT_NE(sharp.find("too short"), std::string::npos) << sharp;
    const auto flat = error_of(replaced(closed, "toe_cone_angle: 60.0", "toe_cone_angle: 180.0"), "flat_cone");
    EXPECT_NE(flat.find("pile.toe_cone_angle"), std::string::npos) << flat;
    // Wished in place 1 m deep: the cone's apex at z = 5, its shoulder h = R / tan 30 above.
    const std::string embedded = replaced(replaced(closed, "toe_elevation: 6.0", "toe_elevation: 5.0"), "  friction: 0.4",
                                          "  wished_in_place: true\n  friction: 0.4");
    const fs::path file = write(embedded, "cone");
    const auto run = pio::build_mpm_run<2>(pio::read_mpm_case(file.string()));
    fs::remove(file);
    const double R = 0.2, h = R * std::sqrt(3.0);
    int beside_cone = 0;
    const auto& p = run.model.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double r = p.x[2 * i], z = p.x[2 * i + 1] - 5.0;
        const double steel = z < 0.0 || z > 1.0 ? 0.0 : z < h ? R * z / h : R;
        EXPECT_FALSE(r < steel) << "a point left in the steel at " << r << ", " << z;
        if (z > 0.0 && z < h && r < R) ++beside_cone;
    }
    EXPECT_GT(beside_cone, 0);
    double lowest = 1e300;
    for (int node : run.pile.mesh.toe_nodes) lowest = std::min(lowest, run.pile.mesh.z(node));
    EXPECT_EQ(lowest, 0.0);  // the apex is the toe
}

// A toe slip line: its length in cells of the grid and its friction angle's tangent; a grid
// twice the fields (4 with an open wall's cut); a missing angle, or pore-water fields, is
// an input error naming the key.
TEST(PileInput, AToeSlipLineDoublesTheFieldsAndIsMeasuredInCells) {
    const std::string with = replaced(jacking(), "  friction: 0.4",
                                      "  toe_slip_line: {length_in_cells: 2.0, friction_angle: 35.0}\n  friction: 0.4");
    const fs::path file = write(with, "slip");
    const auto run = pio::build_mpm_run<2>(pio::read_mpm_case(file.string()));
    fs::remove(file);
    EXPECT_EQ(run.model.grid.fields, 4);  // open: the wall's cut, then the slip line's
    EXPECT_NEAR(run.pile.toe_slip_line.length, 2.0 * 0.1, 1e-12);  // cells of 0.1 m
    EXPECT_NEAR(run.pile.toe_slip_line.friction, std::tan(35.0 * std::numbers::pi / 180.0), 1e-12);
    const auto missing = error_of(replaced(with, ", friction_angle: 35.0", ""), "slip_no_angle");
    EXPECT_NE(missing.find("friction_angle"), std::string::npos) << missing;
    const auto unknown = error_of(replaced(with, "length_in_cells", "length"), "slip_unknown");
    EXPECT_NE(unknown.find("length"), std::string::npos) << unknown;
    const auto water = error_of(replaced(with, "cohesion: 1.0e3}", "cohesion: 1.0e3,\n     drainage: coupled, porosity: 0.4, hydraulic_conductivity: 1.0e-4}"),
                                "slip_water");
    EXPECT_NE(water.find("pile.toe_slip_line"), std::string::npos) << water;
    EXPECT_NE(water.find("pore-water"), std::string::npos) << water;
}

TEST(PileInput, ACornerContactIsFullUnlessItAsksForTheOverlapsShare) {
    const fs::path plain = write(jacking(), "corner_full");
    const auto full = pio::build_mpm_run<2>(pio::read_mpm_case(plain.string()));
    fs::remove(plain);
    EXPECT_FALSE(full.pile.contact.corner_overlap_share);
    const std::string with = replaced(jacking(), "  friction: 0.4", "  corner_contact: overlap\n  friction: 0.4");
    const fs::path file = write(with, "corner_overlap");
    const auto overlap = pio::build_mpm_run<2>(pio::read_mpm_case(file.string()));
    fs::remove(file);
    EXPECT_TRUE(overlap.pile.contact.corner_overlap_share);
    const auto bad = error_of(replaced(with, "corner_contact: overlap", "corner_contact: area"), "corner_bad");
    EXPECT_NE(bad.find("corner_contact"), std::string::npos) << bad;
    EXPECT_NE(bad.find("overlap"), std::string::npos) << bad;
}

// The case's cfl is the share of the stable step taken by the contact too (omega dt = 2 cfl),
// so halving it halves the coupled run's step wherever the contact sets it.
TEST(PileInput, TheCasesCflScalesTheContactsStepToo) {
    const fs::path plain = write(jacking(), "cfl_default");
    const auto standard = pio::build_mpm_run<2>(pio::read_mpm_case(plain.string()));
    fs::remove(plain);
    EXPECT_DOUBLE_EQ(standard.pile.contact.stability_margin, 1.0);
    const fs::path file = write(replaced(jacking(), "particles_per_cell: 2", "particles_per_cell: 2\ncfl: 0.25"), "cfl_quarter");
    const auto halved = pio::build_mpm_run<2>(pio::read_mpm_case(file.string()));
    fs::remove(file);
    EXPECT_DOUBLE_EQ(halved.pile.contact.stability_margin, 0.5);
    EXPECT_DOUBLE_EQ(halved.model.cfl, 0.25);
}

// A blow needs the hammer that strikes it and a dynamic stage; each mistake names its key,
// and the blow becomes the stage's head control with the hammer: a force on the head, or
// the ram-cushion chain with the pile's element size for an elastic ram's rods.
TEST(PileInput, ABlowNeedsAHammerAndADynamicStage) {
    const std::string blow = replaced(jacking(), "pile: {velocity: 0.0, rise_time: 0.05}", "pile: {blow: true}");
    const auto none = error_of(blow, "blow_no_hammer");
    EXPECT_NE(none.find("stages.hold.pile.blow"), std::string::npos) << none;
    EXPECT_NE(none.find("hammer"), std::string::npos) << none;
    const std::string hammer = "hammer: {type: half_sine, peak_force: 2.0e6, impulse_time: 0.001}\nstages:";
    const std::string with = replaced(blow, "stages:", hammer);
    const fs::path file = write(with, "blow");
    const auto run = pio::build_mpm_run<2>(pio::read_mpm_case(file.string()));
    fs::remove(file);
    ASSERT_EQ(run.pile.heads.size(), 2u);
    EXPECT_FALSE(run.pile.heads[0].struck);
    EXPECT_TRUE(run.pile.heads[1].struck);
    EXPECT_DOUBLE_EQ(run.pile.heads[1].hammer.force.at(0.0005), 2.0e6);  // the half-sine's peak at t_i / 2
    const fs::path chain_file = write(replaced(with, "{type: half_sine, peak_force: 2.0e6, impulse_time: 0.001}",
                                               "{type: ram_cushion, ram: {mass: 1000.0}, impact_velocity: 3.0}"),
                                      "blow_chain");
    const auto chain = pio::build_mpm_run<2>(pio::read_mpm_case(chain_file.string()));
    fs::remove(chain_file);
    EXPECT_EQ(chain.pile.heads[1].hammer.kind, pilempm::fem::HammerKind::RamCushion);
    EXPECT_DOUBLE_EQ(chain.pile.heads[1].hammer.ram_cushion.impact_velocity, 3.0);
    EXPECT_DOUBLE_EQ(chain.pile.heads[1].ram_element_size, 0.05);
    const auto both = error_of(replaced(with, "pile: {blow: true}", "pile: {blow: true, velocity: 0.1}"), "blow_both");
    EXPECT_NE(both.find("more than one"), std::string::npos) << both;
    const auto settled = error_of(replaced(with, "{name: hold, type: dynamic, duration: 0.2, local_damping: 0.7, pile: {blow: true}}",
                                           "{name: hold, type: quasi_static, pile: {blow: true}}"),
                                  "blow_quasi_static");
    EXPECT_NE(settled.find("blow"), std::string::npos) << settled;
    EXPECT_NE(settled.find("dynamic"), std::string::npos) << settled;
}

// A load test names its kind: a static one drives the head, a rapid one is the hammer's pulse.
TEST(PileInput, ALoadTestIsStaticOnADrivenHeadOrRapidOnABlow) {
    const std::string hammer = "hammer: {type: half_sine, peak_force: 2.0e6, impulse_time: 0.001}\nstages:";
    const std::string held = "pile: {velocity: 0.0, rise_time: 0.05}";
    const std::string base = replaced(jacking(), "stages:", hammer);
    const fs::path file = write(replaced(base, held, "pile: {velocity: 0.01, load_test: static}"), "slt");
    EXPECT_EQ(pio::read_mpm_case(file.string()).stages.back().load_test, "static");
    fs::remove(file);
    const auto rapid_on_push = error_of(replaced(base, held, "pile: {velocity: 0.01, load_test: rapid}"), "rlt_push");
    EXPECT_NE(rapid_on_push.find("stages[1].pile.load_test"), std::string::npos) << rapid_on_push;
    EXPECT_NE(rapid_on_push.find("blow: true"), std::string::npos) << rapid_on_push;
    const auto static_on_blow = error_of(replaced(base, held, "pile: {blow: true, load_test: static}"), "slt_blow");
    EXPECT_NE(static_on_blow.find("velocity"), std::string::npos) << static_on_blow;
    const auto unknown = error_of(replaced(base, held, "pile: {blow: true, load_test: quick}"), "lt_unknown");
    EXPECT_NE(unknown.find("rapid"), std::string::npos) << unknown;
}

// A driving stage becomes a blow and a pause per blow, named and numbered, each blow struck
// by the case's hammer and ending once the pile is at rest (after the pulse and four wave
// transits by default), each pause the rest of the interval as a consolidation; without
// water there is nothing to consolidate, without a hammer nothing to strike with.
TEST(PileInput, ADrivingStageIsABlowAndAPausePerBlow) {
    const std::string text = case_text::shipped("cases/verification/coupled-driving-energy.yaml");
    const fs::path file = write(text, "drive");
    const auto c = pio::read_mpm_case(file.string());
    const auto run = pio::build_mpm_run<2>(c);
    fs::remove(file);
    ASSERT_EQ(c.stages.size(), 6u);
    EXPECT_EQ(c.stages[0].name, "drive-blow-1");
    EXPECT_EQ(c.stages[5].name, "drive-pause-3");
    EXPECT_EQ(c.stages[4].blow_number, 3);
    for (int k = 0; k < 6; ++k) {
        const auto& st = run.stages[k];
        EXPECT_EQ(st.drive, 0);
        EXPECT_EQ(st.blow, k % 2 == 0);
        EXPECT_EQ(st.consolidation, k % 2 == 1);
        EXPECT_EQ(run.pile.heads[k].struck, k % 2 == 0);
    }
    // The half-sine's 1 ms and four transits of the 4 m pile at sqrt(E / rho) = 5172 m/s.
    EXPECT_NEAR(run.stages[0].min_duration, 0.001 + 16.0 / std::sqrt(210.0e9 / 7850.0), 1e-12);
    EXPECT_DOUBLE_EQ(run.stages[0].rest_speed, 0.005);
    EXPECT_DOUBLE_EQ(run.stages[1].blow_interval, 0.5);
    EXPECT_EQ(run.stages[1].steps, 8);
    EXPECT_FALSE(run.stages[1].snapshot_at_end);
    const auto dry = error_of(replaced(replaced(text, "water: {level: 2.5}\n", ""),
                                       ",\n     drainage: coupled, porosity: 0.4, hydraulic_conductivity: 1.0e-4}", "}"),
                              "drive_dry");
    EXPECT_NE(dry.find("stages[0].pause"), std::string::npos) << dry;  // the drive's pause: key
    EXPECT_NE(dry.find("coupled"), std::string::npos) << dry;
    const auto hammerless = error_of(replaced(text, "hammer:\n  type: half_sine", "unused:\n  type: half_sine"), "drive_hammerless");
    EXPECT_NE(hammerless.find("hammer"), std::string::npos) << hammerless;
    const auto short_interval = error_of(replaced(text, "interval: 0.5 ", "interval: 0.05 "), "drive_interval");
    EXPECT_NE(short_interval.find("interval"), std::string::npos) << short_interval;
}
