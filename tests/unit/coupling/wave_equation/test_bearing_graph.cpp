// The bearing graph's Smith soil: each layer's shaft damping follows its soil type.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sand_pipe_pile.hpp"

using namespace pilempm;
using namespace pilempm::coupling;
using namespace pilempm::fem;

namespace {

constexpr double kBoundary = 6.0;     // m below the mudline: sand above, clay below
constexpr double kPenetration = 15.25;  // no pile node on the boundary (nodes 1 m apart)

SoilLayer layer(SoilType type, double top, double bottom) {
    SoilLayer l;
    l.type = type;
    l.top = top;
    l.bottom = bottom;
    l.submerged_unit_weight = 9e3;
    l.relative_density = 0.7;
    l.interface_friction_angle = 28.0;
    l.undrained_shear_strength = 80e3;
    return l;
}

// A 30 m, 1.5 m pipe pile (1 m rod elements), 6 m of sand over clay, a bearing graph of one
// point (3 MN, 60 % on the shaft) at 15.25 m and a depth study of two points.
DrivabilitySetup sand_over_clay(SoilType lower = SoilType::Clay) {
    DrivabilitySetup s = sand_pipe_pile();
    s.soil.layers = {layer(SoilType::Sand, 0.0, kBoundary), layer(lower, kBoundary, 40.0)};
    s.hammer.kind = HammerKind::RamCushion;
    s.hammer.ram_cushion.ram.mass = 5000.0;
    s.hammer.ram_cushion.impact_velocity = 4.0;
    s.hammer.ram_cushion.hammer_cushion = CushionSpec{3e9, 0.8};
    s.start_depth = 14.0;
    s.final_depth = 15.0;
    s.depth_step = 1.0;
    s.bearing_resistances = {3e6};
    s.bearing_shaft_fraction = 0.6;
    s.bearing_penetration = kPenetration;
    s.threads = 1;
    return s;
}

double bearing_blow_count(const DrivabilitySetup& s) {
    return run_drivability(s).bearing_graph.data[3].at(0);
}

}  // namespace

TEST(BearingGraph, ShaftDashpotIsTheLayersJTimesTheNodesResistance) {
    auto s = sand_over_clay();
    s.sand_shaft_damping = 0.2;
    s.clay_shaft_damping = 0.9;
    fem::ExplicitPile pile(s.mesh, s.steel, {});
    const SmithSoil soil = make_smith_soil(pile, bearing_graph_resistance(s, 3e6), s.smith, 1.0);
    // By hand: 0.6 x 3 MN spread evenly over 15.25 m; a node carries the shaft within half
    // an element (0.5 m) of it, cut at the mudline and the tip; its dashpot is the sum of
    // J R_u over that shaft, J = 0.2 s/m above 6 m and 0.9 s/m below.
    const double per_metre = 0.6 * 3e6 / kPenetration;
    auto overlap = [](double a, double b, double lo, double hi) { return std::max(0.0, std::min(b, hi) - std::max(a, lo)); };
    int shaft_points = 0;
    for (std::size_t i = 0; i < soil.size(); ++i) {
        const double depth = kPenetration - pile.mesh().z(soil.node[i]);
        if (soil.toe[i]) {
            EXPECT_NEAR(soil.dashpot[i], 0.50 * 0.4 * 3e6, 1e-6);  // toe: J_toe R_toe
            continue;
        }
        ++shaft_points;
        const double sand = overlap(depth - 0.5, depth + 0.5, 0.0, kBoundary);
        const double clay = overlap(depth - 0.5, depth + 0.5, kBoundary, kPenetration);
        const double r_u = per_metre * (sand + clay);
        EXPECT_NEAR(soil.ultimate[i], r_u, 1e-9 * r_u) << "node at " << depth << " m";
        EXPECT_NEAR(soil.dashpot[i], per_metre * (0.2 * sand + 0.9 * clay), 1e-9 * r_u) << "node at " << depth << " m";
    }
    EXPECT_EQ(shaft_points, 16);  // nodes at 0.25, 1.25, ..., 15.25 m
}

TEST(BearingGraph, BlowCountFollowsTheClayShaftDamping) {
    // 9.25 of the 15.25 m of shaft are in clay: doubling its J must slow the pile.
    auto s = sand_over_clay();
    const double soft = bearing_blow_count(s);
    s.clay_shaft_damping = 1.3;
    const double stiff = bearing_blow_count(s);
    EXPECT_GT(stiff, 1.05 * soft) << "blows per 0.25 m " << soft << " -> " << stiff;

    // With no clay in the ground, the clay J is not used.
    auto sand = sand_over_clay(SoilType::Sand);
    const double before = bearing_blow_count(sand);
    sand.clay_shaft_damping = 1.3;
    EXPECT_EQ(bearing_blow_count(sand), before);
}

TEST(SrdForDriving, ANodeOnALayerBoundarySumsTheDashpotsOfBothLayers) {
    // 0.5 m elements: the tip at 15.45 m puts a node at 5.95 m, 0.05 m above the boundary
    // (inside one SRD sample spacing, 0.1 m); at 15.5 m one sits on it. Each carries
    // shaft from both layers: c = J_sand R_u,sand + J_clay R_u,clay.
    auto s = sand_over_clay();
    s.mesh = fem::mesh_rod(fem::make_pile_geometry({{30.0, 1.5, 0.025}}), 0.5);
    s.sand_shaft_damping = 0.2;
    s.clay_shaft_damping = 0.9;
    for (double pen : {15.45, 15.5}) {
        const ResistanceDistribution r = srd_for_driving(s, s.cases[0], pen);
        fem::ExplicitPile pile(s.mesh, s.steel, {});
        const SmithSoil soil = make_smith_soil(pile, r, s.smith, 1.0);
        int straddling = 0;
        for (std::size_t i = 0; i < soil.size(); ++i) {
            if (soil.toe[i]) continue;
            const double depth = pen - pile.mesh().z(soil.node[i]);
            const double lo = std::max(0.0, depth - 0.25), hi = std::min(pen, depth + 0.25);
            const double sand = r.shaft_between(lo, std::min(hi, kBoundary));
            const double clay = r.shaft_between(std::max(lo, kBoundary), hi);
            straddling += sand > 0.0 && clay > 0.0;
            EXPECT_NEAR(soil.dashpot[i], 0.2 * sand + 0.9 * clay, 1e-9 * soil.ultimate[i])
                << "node at " << depth << " m, tip at " << pen << " m";
        }
        EXPECT_EQ(straddling, 1) << "tip at " << pen << " m";
    }
}
