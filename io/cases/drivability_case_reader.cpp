#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "fem/mesh/rod_mesh.hpp"
#include "io/cases/drivability_case.hpp"
#include "io/yaml/numeric_file.hpp"
#include "io/yaml/yaml_reader.hpp"

namespace pilempm::io {
namespace {

const std::vector<std::string> kAnalyses = {"pile_wave", "drivability", "mpm", "element_test"};
const std::vector<std::string> kChecks = {"static_push", "bearing_graph_monotonic",
                                          "blow_energy_balance", "danish_formula",
                                          "self_weight_penetration"};

coupling::SrdMethod method_from(const std::string& name) {
    if (name == "alm_hamre_2001") return coupling::SrdMethod::AlmHamre2001;
    if (name == "stevens_lower_bound") return coupling::SrdMethod::StevensLowerBound;
    return coupling::SrdMethod::StevensUpperBound;
}

coupling::SoilLayer read_layer(MapReader m, double expected_top) {
    coupling::SoilLayer l;
    l.name = m.text_or("name", "");
    l.top = m.number("top", non_negative("depth below the mudline in m"));
    if (std::abs(l.top - expected_top) > 1e-9) {
        std::ostringstream e, f;
        e << "layers that follow each other without gaps: a top at " << expected_top << " m";
        f << l.top << " m";
        m.fail("top", e.str(), f.str());
    }
    l.bottom = m.number("bottom", {"a depth below the layer's top (" + std::to_string(l.top) + " m)",
                                   [top = l.top](double b) { return b > top; }});
    l.type = m.choice("type", {"sand", "clay"}) == "sand" ? coupling::SoilType::Sand : coupling::SoilType::Clay;
    l.submerged_unit_weight = m.number("submerged_unit_weight", positive("unit weight in N/m^3"));
    if (l.type == coupling::SoilType::Sand) {
        l.relative_density = m.number("relative_density",
                                      in_half_open_range(0.0, 1.5, "a relative density as a fraction"));
        l.friction_angle = m.number_or("friction_angle", 0.0, in_open_range(-1e-12, 60.0, "an angle in degrees"));
        l.interface_friction_angle = m.number("interface_friction_angle",
                                              in_open_range(0.0, 45.0, "an angle in degrees"));
    } else {
        l.undrained_shear_strength = m.number("undrained_shear_strength", positive("strength in Pa"));
        l.undrained_shear_strength_gradient =
            m.number_or("undrained_shear_strength_gradient", 0.0, non_negative("gradient in Pa/m"));
        l.sensitivity = m.number_or("sensitivity", 2.0, {"a sensitivity of at least 1", [](double x) { return x >= 1.0; }});
    }
    m.finish();
    return l;
}

void read_soil(MapReader m, DrivabilityCase& c) {
    c.soil.water_depth = m.number_or("water_depth", 0.0, non_negative("water depth in m"));
    double top = 0.0;
    for (auto l : m.maps("layers")) {
        c.soil.layers.push_back(read_layer(l, top));
        top = c.soil.layers.back().bottom;
    }
    if (m.has("cpt_file")) {
        const NumericFile f = read_numeric_file(m, "cpt_file", {"depth_m", "qt_Pa", "fs_Pa"});
        c.cpt_file = f.path;
        c.soil.cpt = {f.columns[0], f.columns[1], f.columns[2]};
    }
    c.soil.clay_cone_factor = m.number_or("clay_cone_factor", 15.0, positive("cone factor N_kt"));
    m.finish();
}

void read_smith(MapReader m, DrivabilityCase& c) {
    auto& s = c.smith;
    s.shaft_quake = m.number_or("shaft_quake", 2.5e-3, positive("quake in m"));
    s.toe_quake = m.number_or("toe_quake", 2.5e-3, positive("quake in m"));
    const bool smith = m.choice_or("damping_law", "smith_viscous", {"smith_viscous", "case"}) == "smith_viscous";
    s.law = smith ? coupling::DampingLaw::SmithViscous : coupling::DampingLaw::Case;
    if (smith) {
        c.sand_shaft_damping = m.number_or("sand_shaft_damping", 0.16, non_negative("Smith damping in s/m"));
        c.clay_shaft_damping = m.number_or("clay_shaft_damping", 0.65, non_negative("Smith damping in s/m"));
        s.toe_damping = m.number_or("toe_damping", 0.50, non_negative("Smith damping in s/m"));
    } else {
        s.shaft_damping = m.number("shaft_damping", non_negative("Case damping factor J_c"));
        s.toe_damping = m.number("toe_damping", non_negative("Case damping factor J_c"));
    }
    m.finish();
}

void read_cases(MapReader& root, DrivabilityCase& c) {
    const std::vector<std::string> methods = {"alm_hamre_2001", "stevens_lower_bound", "stevens_upper_bound"};
    if (!root.has("soil_cases")) {
        // The industry's usual three: Stevens lower bound, Alm & Hamre best estimate, and
        // Alm & Hamre x 1.25 as upper bound (their own recommendation).
        c.cases = {{"lower_bound", coupling::SrdMethod::StevensLowerBound, 1.0},
                   {"best_estimate", coupling::SrdMethod::AlmHamre2001, 1.0},
                   {"upper_bound", coupling::SrdMethod::AlmHamre2001, 1.25}};
        return;
    }
    for (auto m : root.maps("soil_cases")) {
        coupling::SoilCase sc;
        sc.name = m.text_or("name", "");
        if (sc.name.empty() || sc.name.find_first_of("/\\ ") != std::string::npos)
            m.fail("name", "a name without spaces or slashes (it names the output file)", "'" + sc.name + "'");
        sc.method = method_from(m.choice("method", methods));
        sc.factor = m.number_or("factor", 1.0, positive("factor on the SRD"));
        m.finish();
        c.cases.push_back(sc);
    }
}

void read_driving(MapReader m, DrivabilityCase& c) {
    const double L = c.length();
    c.final_depth = m.number("final_depth", {"a depth within the pile length (" + std::to_string(L) + " m)",
                                             [L](double d) { return d > 0.0 && d < L; }});
    c.start_depth = m.number_or("start_depth", -1.0,
                                {"a depth above the final depth", [fd = c.final_depth](double d) { return d >= 0.0 && d < fd; }});
    c.depth_step = m.number_or("depth_step", 0.25, positive("depth step in m"));
    if (m.has("energy_levels"))
        c.energy_levels = m.numbers("energy_levels", in_half_open_range(0.0, 2.0, "a fraction of the hammer energy"));
    c.refusal_blow_count = m.number_or("refusal_blow_count", 250.0, positive("blows per 0.25 m"));
    c.hard_driving_blow_count = m.number_or("hard_driving_blow_count", 75.0, positive("blows per 0.25 m"));
    c.max_blows = m.integer_or("max_blows", 8, 2);
    c.steady_tolerance = m.number_or("steady_tolerance", 0.05, in_open_range(0.0, 1.0, "a relative change"));
    c.threads = m.integer_or("threads", 0, 0);
    m.finish();
}

}  // namespace

std::string read_analysis_kind(const std::string& file) {
    MapReader root = load_yaml_file(file);
    return root.choice("analysis", kAnalyses);
}

DrivabilityCase read_drivability_case(const std::string& file) {
    MapReader root = load_yaml_file(file);
    DrivabilityCase c;
    read_case_header(root, c, file, "drivability");
    {
        MapReader pile = root.map("pile");
        if (pile.has("model") && pile.choice("model", {"rod", "axisymmetric"}) != "rod")
            pile.fail("model", "rod (the wave-equation drivability uses the rod pile)", "axisymmetric");
        read_pile_section(std::move(pile), c, c, false);
    }
    read_hammer_section(root.map("hammer"), c, c);
    read_soil(root.map("soil"), c);
    if (auto s = root.optional_map("smith")) read_smith(std::move(*s), c);
    else c.smith.shaft_damping = c.sand_shaft_damping;
    if (auto k = root.optional_map("srd")) {
        c.coefficients.stevens_k_lower = k->number_or("stevens_k_lower", 0.5, positive("earth pressure coefficient"));
        c.coefficients.stevens_k_upper = k->number_or("stevens_k_upper", 0.7, positive("earth pressure coefficient"));
        c.coefficients.alm_hamre_sand_inside = k->number_or("alm_hamre_sand_inside_share", 0.5, non_negative("share"));
        c.coefficients.alm_hamre_sand_outside = k->number_or("alm_hamre_sand_outside_share", 0.5, non_negative("share"));
        k->finish();
    }
    read_cases(root, c);
    read_driving(root.map("driving"), c);
    if (auto b = root.optional_map("bearing_graph")) {
        c.bearing_resistances = b->numbers("resistances", positive("ultimate resistance in N"));
        c.bearing_shaft_fraction = b->number_or("shaft_fraction", 0.5,
                                                {"a fraction from 0 to 1", [](double x) { return x >= 0.0 && x <= 1.0; }});
        c.bearing_penetration = b->number_or("penetration", 0.0, non_negative("penetration in m"));
        b->finish();
    }
    if (auto out = root.optional_map("output")) {
        c.plots = out->boolean_or("plots", true);
        out->finish();
    }
    if (auto v = root.optional_map("verification")) {
        c.verification_checks = v->words("checks", kChecks);
        c.verification_depth = v->number_or("depth", 0.0, non_negative("depth in m"));
        c.observed_self_weight_penetration =
            v->number_or("observed_self_weight_penetration", -1.0, non_negative("depth in m"));
        c.observed_tolerance = v->number_or("observed_tolerance", 0.5, positive("depth tolerance in m"));
        if (std::find(c.verification_checks.begin(), c.verification_checks.end(), "self_weight_penetration") !=
                c.verification_checks.end() && c.observed_self_weight_penetration < 0.0)
            v->fail("observed_self_weight_penetration", "the observed depth for the self_weight_penetration check");
        v->finish();
    }
    root.finish();
    return c;
}

coupling::DrivabilitySetup build_drivability_setup(const DrivabilityCase& c) {
    coupling::DrivabilitySetup s;
    const fem::PileGeometry geometry = fem::make_pile_geometry(c.segments, c.taper_ratio);
    s.mesh = fem::mesh_rod(geometry, c.element_size);
    s.steel = c.steel;
    s.outer_diameter = c.segments.back().outer_diameter;
    s.wall_thickness = c.segments.back().wall_thickness;
    double volume = 0.0;
    for (std::size_t i = 1; i < geometry.stations.size(); ++i) {
        const auto &a = geometry.stations[i - 1], &b = geometry.stations[i];
        volume += 0.5 * (geometry.area_at(a.z) + geometry.area_at(b.z)) * (b.z - a.z);
    }
    s.pile_mass = volume * c.steel.density;
    s.soil = c.soil;
    s.coefficients = c.coefficients;
    s.cases = c.cases;
    s.smith = c.smith;
    s.sand_shaft_damping = c.sand_shaft_damping;
    s.clay_shaft_damping = c.clay_shaft_damping;
    s.hammer = c.hammer;
    s.ram_element_size = c.element_size;
    s.hammer_weight = c.hammer_mass * c.gravity * (1.0 - 1025.0 / c.steel.density);
    s.energy_levels = c.energy_levels;
    s.start_depth = c.start_depth;
    s.final_depth = c.final_depth;
    s.depth_step = c.depth_step;
    s.hard_driving_blow_count = c.hard_driving_blow_count;
    s.driving.max_blows = c.max_blows;
    s.driving.steady_tolerance = c.steady_tolerance;
    s.driving.refusal_blow_count = c.refusal_blow_count;
    s.threads = c.threads;
    s.bearing_resistances = c.bearing_resistances;
    s.bearing_shaft_fraction = c.bearing_shaft_fraction;
    s.bearing_penetration = c.bearing_penetration;
    return s;
}

}  // namespace pilempm::io
