#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/yaml/numeric_file.hpp"
#include "io/cases/pile_hammer_input.hpp"

namespace pilempm::io {
namespace {

fem::LinearElasticSteel read_steel(MapReader m) {
    fem::LinearElasticSteel s;
    s.youngs_modulus = m.number("youngs_modulus", positive("Young's modulus in Pa"));
    s.poisson_ratio = m.number_or("poisson_ratio", 0.3,
                                  in_open_range(-1.0, 0.5, "a Poisson's ratio"));
    s.density = m.number("density", positive("density in kg/m^3"));
    m.finish();
    return s;
}

void read_pile(MapReader m, PileInput& c, CaseFile& file, bool with_toe) {
    c.model = m.choice_or("model", "rod", {"rod", "axisymmetric"}) == "rod" ? PileModel::Rod
                                                                           : PileModel::Axisymmetric;
    for (auto s : m.maps("segments")) {
        fem::PileSegment seg;
        seg.length = s.number("length", positive("length in m"));
        seg.outer_diameter = s.number("outer_diameter", positive("diameter in m"));
        seg.wall_thickness = s.number("wall_thickness", positive("wall thickness in m"));
        if (seg.wall_thickness > 0.5 * seg.outer_diameter) {
            std::ostringstream f;
            f << seg.wall_thickness << " m with an outer radius of " << 0.5 * seg.outer_diameter << " m";
            s.fail("wall_thickness", "a wall no thicker than the outer radius (equal: a solid, closed-ended pile)", f.str());
        }
        s.finish();
        c.segments.push_back(seg);
    }
    c.taper_ratio = m.number_or("taper_ratio", 4.0, non_negative("taper length per unit change in wall thickness"));
    c.steel = read_steel(m.map("steel"));
    double length = 0.0;
    for (const auto& s : c.segments) length += s.length;
    file.lines["pile.element_size"] = m.line_of("element_size");
    c.element_size = m.number("element_size", positive("element size in m"));
    if (c.element_size > length) {
        std::ostringstream f;
        f << c.element_size << " m for a pile of " << length << " m";
        m.fail("element_size", "an element size no longer than the pile", f.str());
    }
    c.radial_divisions = m.integer_or("radial_divisions", 2, 1);
    if (!with_toe) {
        m.finish();
        return;
    }
    auto toe = m.map("toe");
    const std::string cond = toe.choice("condition", {"free", "fixed", "dashpot"});
    c.toe.condition = cond == "free"    ? fem::ToeCondition::Free
                      : cond == "fixed" ? fem::ToeCondition::Fixed
                                        : fem::ToeCondition::Dashpot;
    if (c.toe.condition == fem::ToeCondition::Dashpot && toe.has("impedance")) {
        c.toe.impedance = toe.number("impedance", positive("impedance in N s/m"));
        c.toe_impedance_given = true;
    }
    toe.finish();
    m.finish();
}

fem::CushionSpec read_cushion(MapReader m) {
    fem::CushionSpec c;
    c.stiffness = m.number("stiffness", positive("stiffness in N/m"));
    c.restitution = m.number("restitution", in_half_open_range(0.0, 1.0, "a coefficient of restitution"));
    m.finish();
    return c;
}

void read_hammer(MapReader m, HammerInput& c, const CaseFile& file) {
    const std::string type = m.choice("type", {"half_sine", "force_table", "ram_cushion"});
    auto& h = c.hammer;
    const double g = file.gravity;
    auto drop_and_efficiency = [&](double& drop, double& eta) {
        drop = m.number("drop_height", positive("drop height in m"));
        eta = m.number_or("efficiency", 1.0, in_half_open_range(0.0, 1.0, "an efficiency"));
    };
    if (type == "half_sine") {
        h.kind = fem::HammerKind::PrescribedForce;
        h.force.duration = m.number("impulse_time", positive("impulse time in s"));
        if (m.has("peak_force")) {
            h.force.peak = m.number("peak_force", positive("force in N"));
            c.hammer_description = "half-sine pulse, given peak force";
        } else {
            const double ram = m.number("ram_mass", positive("ram mass in kg"));
            double drop, eta;
            drop_and_efficiency(drop, eta);
            h.force.peak = fem::half_sine_peak_force(ram, drop, eta, h.force.duration, g);
            c.rated_energy = ram * g * drop;
            c.hammer_mass = ram;
            c.hammer_description = "half-sine pulse, f_max = pi eta m sqrt(2 g h) / (2 t_i)";
        }
    } else if (type == "force_table") {
        h.kind = fem::HammerKind::PrescribedForce;
        std::vector<double> times, forces;
        if (m.has("file")) {
            const NumericFile f = read_numeric_file(m, "file", {"time_s", "force_N"});
            times = f.columns[0];
            forces = f.columns[1];
        } else {
            const YAML::Node t = m.raw("table");
            if (!t.IsSequence()) m.fail("table", "a list of [time_s, force_N] pairs", describe(t));
            for (std::size_t i = 0; i < t.size(); ++i) {
                const std::string where = m.path() + ".table[" + std::to_string(i) + "]";
                if (!t[i].IsSequence() || t[i].size() != 2)
                    throw CaseError(file.file, t[i].Mark().line + 1, where, "a [time_s, force_N] pair", describe(t[i]));
                double time = 0.0, force = 0.0;
                try {
                    time = t[i][0].as<double>();
                    force = t[i][1].as<double>();
                } catch (const YAML::Exception&) {
                    throw CaseError(file.file, t[i].Mark().line + 1, where, "two numbers",
                                    describe(t[i][0]) + ", " + describe(t[i][1]));
                }
                if (!times.empty() && !(time > times.back()))
                    throw CaseError(file.file, t[i].Mark().line + 1, where, "times that increase row by row",
                                    "t = " + std::to_string(time) + " s");
                times.push_back(time);
                forces.push_back(force);
            }
            if (times.size() < 2) m.fail("table", "at least two (time, force) rows", std::to_string(times.size()) + " rows");
        }
        h.force.table_time = times;
        h.force.table_force = forces;
        c.hammer_description = "force table";
    } else {
        h.kind = fem::HammerKind::RamCushion;
        auto& rc = h.ram_cushion;
        rc.gravity = g;
        auto ram = m.map("ram");
        rc.ram.mass = ram.number("mass", positive("ram mass in kg"));
        rc.ram.elastic = ram.choice_or("model", "rigid", {"rigid", "elastic"}) == "elastic";
        if (rc.ram.elastic) {
            rc.ram.length = ram.number("length", positive("ram length in m"));
            rc.ram.youngs_modulus = ram.number("youngs_modulus", positive("Young's modulus in Pa"));
            rc.ram.density = ram.number("density", positive("density in kg/m^3"));
            rc.ram.elements = ram.integer_or("elements", 0, 1);
        }
        ram.finish();
        if (m.has("impact_velocity")) {
            rc.impact_velocity = m.number("impact_velocity", positive("impact velocity in m/s"));
            c.hammer_description = "ram-cushion model, given impact velocity";
        } else {
            double drop, eta;
            drop_and_efficiency(drop, eta);
            rc.impact_velocity = std::sqrt(2.0 * eta * g * drop);
            c.rated_energy = rc.ram.mass * g * drop;
            c.hammer_description = "ram-cushion model, v = sqrt(2 eta g h)";
        }
        if (auto hc = m.optional_map("hammer_cushion")) rc.hammer_cushion = read_cushion(*hc);
        rc.helmet_mass = m.number_or("helmet_mass", 0.0, non_negative("helmet mass in kg"));
        c.hammer_mass = rc.ram.mass + rc.helmet_mass;
        if (auto pc = m.optional_map("pile_cushion")) {
            if (rc.helmet_mass <= 0.0)
                m.fail("pile_cushion", "a helmet_mass above a pile cushion", "no helmet mass");
            rc.pile_cushion = read_cushion(*pc);
        }
    }
    m.finish();
}

}  // namespace

void read_case_header(MapReader& root, CaseFile& c, const std::string& file, const std::string& analysis) {
    c.file = file;
    c.title = root.text_or("title", std::filesystem::path(file).stem().string());
    root.choice("analysis", {analysis});
    c.gravity = root.number_or("gravity", 9.81, non_negative("gravitational acceleration in m/s^2"));
}

const char* pile_model_name(PileModel m) { return m == PileModel::Rod ? "rod" : "axisymmetric"; }

double PileInput::length() const {
    double L = 0.0;
    for (const auto& s : segments) L += s.length;
    return L;
}

void read_pile_section(MapReader m, PileInput& pile, CaseFile& c, bool with_toe) {
    read_pile(std::move(m), pile, c, with_toe);
}

void read_hammer_section(MapReader m, HammerInput& hammer, const CaseFile& c) {
    read_hammer(std::move(m), hammer, c);
}

}  // namespace pilempm::io
