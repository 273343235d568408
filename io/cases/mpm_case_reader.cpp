#include <algorithm>
#include <cmath>
#include <sstream>

#include "io/cases/mpm_case.hpp"
#include "io/yaml/yaml_reader.hpp"

namespace pilempm::io {
namespace {

const std::vector<std::string> kChecks = {"self_weight_stress", "lame_cylinder", "wave_arrival",
                                          "absorbed_energy", "footing_collapse", "rigid_punch", "hammer_energy_into_pile", "ram_energy_into_pile", "hammer_energy_every_blow", "conservation", "contact_penetration", "granular_runout",
                                          "stress_noise", "lateral_stress_ratio", "nil_step_displacement",
                                          "shear_wave_arrival", "terzaghi_consolidation", "undrained_wave_speed", "fast_wave_speed",
                                          "poroelastic_wave_history",
                                          "hydrostatic_equilibrium", "skempton_b"};

std::array<double, 3> point(MapReader& m, const std::string& key, int dim) {
    const auto v = m.numbers(key, {"a coordinate in m", [](double) { return true; }});
    if (static_cast<int>(v.size()) != dim)
        m.fail(key, std::to_string(dim) + " coordinates", std::to_string(v.size()) + " numbers");
    std::array<double, 3> out{};
    for (int d = 0; d < dim; ++d) out[d] = v[d];
    return out;
}

MpmBox box(MapReader m, int dim) {
    MpmBox b;
    b.min = point(m, "min", dim);
    b.max = point(m, "max", dim);
    for (int d = 0; d < dim; ++d)
        if (!(b.max[d] > b.min[d])) m.fail("max", "a corner above min in every coordinate", "one that is not");
    m.finish();
    return b;
}

int material_index(const MpmCase& c, MapReader& m, const std::string& key) {
    const std::string name = m.text_or(key, "");
    for (std::size_t i = 0; i < c.materials.size(); ++i)
        if (c.materials[i].name == name) return static_cast<int>(i);
    std::string names;
    for (const auto& mat : c.materials) names += (names.empty() ? "" : ", ") + mat.name;
    m.fail(key, "the name of a material (" + names + ")", "'" + name + "'");
}

std::pair<int, int> plane(MapReader& m, const std::string& key, int dim) {
    std::vector<std::string> names = {"x_min", "x_max", "y_min", "y_max"};
    if (dim == 3) names.insert(names.end(), {"z_min", "z_max"});
    const std::string p = m.choice(key, names);
    return {p[0] - 'x', p.substr(2) == "max" ? 1 : 0};
}

// grid.zones: {x: [{to, cell}, ...], y: [...]}, every axis named; the node coordinates are
// made here once to report a bad zone where it is written.
void read_grid_zones(MapReader& m, MapReader zm, MpmCase& c) {
    const int D = c.dimension;
    if (m.has("size") || m.has("cells")) m.fail("zones", "either zones or size and cells", "both");
    for (int d = 0; d < D; ++d) {
        const std::string axis(1, static_cast<char>('x' + d));
        if (!zm.has(axis)) zm.fail(axis, "the zones along every axis (" + std::string(D == 2 ? "x, y" : "x, y, z") + ")", "none");
        for (auto z : zm.maps(axis)) {
            mpm::GridZone zone;
            zone.to = z.number("to", {"the zone's far end in m", [](double) { return true; }});
            zone.cell = z.number("cell", positive("cell size in m at the zone's end"));
            z.finish();
            c.zones[d].push_back(zone);
        }
        try {
            const auto lines = mpm::graded_axis(c.origin[d], c.zones[d]);
            c.size[d] = lines.back() - lines.front();
            c.cells[d] = static_cast<int>(lines.size()) - 1;
        } catch (const std::invalid_argument& e) {
            zm.fail(axis, "zones that run forward from the origin with cells that fit and grade gently", e.what());
        }
    }
    zm.finish();
}

void read_grid(MapReader m, MpmCase& c) {
    const int D = c.dimension;
    c.origin = point(m, "origin", D);
    if (c.axisymmetric && c.origin[0] < 0.0) m.fail("origin", "r >= 0 in axisymmetry", std::to_string(c.origin[0]));
    if (auto zm = m.optional_map("zones")) {
        read_grid_zones(m, std::move(*zm), c);
        m.finish();
        return;
    }
    c.size = point(m, "size", D);
    const auto cells = m.numbers("cells", positive("number of cells"));
    if (static_cast<int>(cells.size()) != D) m.fail("cells", std::to_string(D) + " counts", std::to_string(cells.size()));
    for (int d = 0; d < D; ++d) {
        c.cells[d] = static_cast<int>(std::lround(cells[d]));
        if (!(c.size[d] > 0.0)) m.fail("size", "positive lengths", std::to_string(c.size[d]));
    }
    m.finish();
}

MpmRegionInput read_region(MapReader m, const MpmCase& c) {
    MpmRegionInput r;
    r.material = material_index(c, m, "material");
    const int D = c.dimension;
    if (auto b = m.optional_map("box")) {
        r.kind = MpmRegionInput::Box;
        r.box = box(std::move(*b), D);
    } else if (auto cy = m.optional_map("cylinder")) {
        if (D != 3) m.fail("cylinder", "a box or layer in 2D (a cylinder needs 3D)", "a cylinder");
        r.kind = MpmRegionInput::Cylinder;
        r.centre = point(*cy, "base_centre", 3);
        r.radius = cy->number("radius", positive("radius in m"));
        r.height = cy->number("height", positive("height in m"));
        cy->finish();
    } else if (auto l = m.optional_map("layer")) {
        r.kind = MpmRegionInput::Layer;
        r.box.min[D - 1] = l->number("bottom", {"an elevation in m", [](double) { return true; }});
        r.box.max[D - 1] = l->number("top", {"an elevation above the bottom", [b = r.box.min[D - 1]](double t) { return t > b; }});
        for (int d = 0; d < D - 1; ++d) {
            r.box.min[d] = -1e300;
            r.box.max[d] = 1e300;
        }
        l->finish();
    } else {
        m.fail("box", "one of box, cylinder or layer", "none");
    }
    m.finish();
    return r;
}

// A consolidation's steps and linear solver (a consolidation stage, a drive's pause).
void read_consolidation_steps(MapReader& m, MpmStageInput& s) {
    s.steps = m.integer_or("steps", 20, 1);
    s.step_growth = m.number_or("step_growth", 1.2, {"a growth factor from 1 to 2 of one step over the last",
                                                      [](double x) { return x >= 1.0 && x <= 2.0; }});
    if (auto ls = m.optional_map("linear_solver")) {
        const std::string method = ls->choice_or("method", "gmres", {"gmres", "bicgstab", "direct"});
        s.linear_solver.method = method == "gmres"      ? core::KrylovMethod::gmres
                                 : method == "bicgstab" ? core::KrylovMethod::bicgstab
                                                        : core::KrylovMethod::direct;
        const std::string pre = ls->choice_or("preconditioner", "ilu", {"none", "jacobi", "ilu", "ilut", "multigrid"});
        s.linear_solver.preconditioner = pre == "none"     ? core::Preconditioner::none
                                         : pre == "jacobi" ? core::Preconditioner::jacobi
                                         : pre == "ilu"    ? core::Preconditioner::ilu
                                         : pre == "ilut"   ? core::Preconditioner::ilut
                                                           : core::Preconditioner::multigrid;
        s.linear_solver.ilu_level = ls->integer_or("ilu_level", 1, 0);
        s.linear_solver.relative_tolerance = ls->number_or("tolerance", 1e-10, in_open_range(0.0, 1.0, "a relative residual"));
        s.linear_solver.multigrid_symmetric = false;
        ls->finish();
    } else {
        s.linear_solver.ilu_level = 1;
        s.linear_solver.relative_tolerance = 1e-10;
    }
}

// `type: driving`: blow after blow of the case's hammer, each a dynamic stage that ends once
// the pile is at rest, then (with `pause:`) the rest of the interval as a consolidation; up
// to `blows` of them, fewer when the toe reaches `target_toe_elevation` or at refusal. Each
// blow and pause becomes a stage of its own (name-blow-k, name-pause-k): a checkpoint and a
// history stage number at every blow's boundary.
void read_drive(MapReader m, const MpmCase& c, int drive, std::vector<MpmStageInput>& out) {
    MpmStageInput blow;
    blow.name = m.text_or("name", "driving");
    blow.drive = drive;
    blow.blow = true;
    blow.pile_struck = true;
    blow.pile_line = m.line_of("type");
    const int blows = m.integer_or("blows", 1, 1);
    blow.duration = m.number("blow_duration", positive("the longest a blow's dynamic phase runs, in s"));
    blow.rest_speed = m.number_or("rest_speed", 0.005, positive("the pile's speed at rest in m/s (the blow then ends)"));
    blow.min_duration = m.number_or("min_blow_duration", -1.0, non_negative("the shortest blow in s"));
    blow.rest_span = m.number_or("rest_span", -1.0, non_negative("how long in s the pile must stay below rest_speed"));
    blow.local_damping = m.number_or("local_damping", 0.0, {"a damping coefficient from 0 to 1",
                                                             [](double x) { return x >= 0.0 && x < 1.0; }});
    blow.settle_damping = m.number_or("settle_damping", 0.0, {"a damping coefficient from 0 to 1",
                                                               [](double x) { return x >= 0.0 && x < 1.0; }});
    blow.gravity_factor = m.number_or("gravity_factor", 1.0, positive("gravity over the case's (n for n g)"));
    // Rows of a long drive's history: every step while the blow's wave travels, then every
    // n-th (the blow's peaks are kept over every step).
    blow.history_every = m.integer_or("history_every", 1, 1);
    if (m.has("target_toe_elevation"))
        blow.end_toe_elevation = m.number("target_toe_elevation", {"an elevation in m", [](double) { return true; }});
    if (auto r = m.optional_map("refusal")) {
        blow.refusal_set = r->number("set", positive("the set per blow in m below which a blow counts to refusal"));
        blow.refusal_blows = r->integer_or("blows", 10, 1);
        r->finish();
    }
    if (!c.pile.present) m.fail("type", "a pile: section for a driving stage", "driving without a pile");
    if (!c.pile.has_hammer) m.fail("type", "a hammer: section (half_sine, force_table or ram_cushion) for the blows", "none");
    MpmStageInput pause;
    const bool paused = m.has("pause");
    if (paused) {
        bool coupled = false;
        for (const auto& mat : c.materials) coupled = coupled || mat.drainage == "coupled";
        MapReader pm = m.map("pause");
        if (!coupled) pm.fail("steps", "soil with pore water (a material with drainage: coupled) to consolidate", "dry soil");
        pause.consolidation = true;
        pause.drive = drive;
        pause.gravity_factor = blow.gravity_factor;
        read_consolidation_steps(pm, pause);
        pm.finish();
        pause.blow_interval = m.number("interval", {"the time from one blow to the next in s, longer than blow_duration",
                                                    [d = blow.duration](double x) { return x > d; }});
        pause.duration = pause.blow_interval;
    }
    m.finish();
    for (int k = 1; k <= blows; ++k) {
        MpmStageInput b = blow;
        b.name = blow.name + "-blow-" + std::to_string(k);
        b.blow_number = k;
        out.push_back(b);
        if (!paused) continue;
        MpmStageInput p = pause;
        p.name = blow.name + "-pause-" + std::to_string(k);
        p.blow_number = k;
        out.push_back(p);
    }
}

MpmStageInput read_stage(MapReader m) {
    MpmStageInput s;
    s.name = m.text_or("name", "stage");
    const std::string type = m.choice("type", {"quasi_static", "dynamic", "consolidation", "driving"});
    s.quasi_static = type == "quasi_static";
    s.consolidation = type == "consolidation";
    if (s.consolidation) {
        s.duration = m.number("duration", positive("duration in s"));
        read_consolidation_steps(m, s);
    } else if (s.quasi_static) {
        s.max_steps = m.integer_or("max_steps", 100000, 1);
        s.tolerance = m.number_or("tolerance", 1e-4, positive("unbalanced force ratio"));
        s.local_damping = m.number_or("local_damping", 0.7, in_open_range(0.0, 1.0, "a damping coefficient"));
    } else {
        s.duration = m.number("duration", positive("duration in s"));
        // A displacement-controlled push can be made quasi-static with local damping.
        s.local_damping = m.number_or("local_damping", 0.0, {"a damping coefficient from 0 to 1",
                                                             [](double x) { return x >= 0.0 && x < 1.0; }});
    }
    s.gravity_factor = m.number_or("gravity_factor", 1.0, positive("gravity over the case's (n for n g)"));
    // drained: the coupled pore water at its hydrostatic pressure through the stage (a
    // drained nil step); a consolidation is about the water's flow, so it has no such key.
    if (!s.consolidation)
        s.drained = m.choice_or("drainage", "coupled", {"coupled", "drained"}) == "drained";
    if (!s.consolidation)
        if (auto pm = m.optional_map("pile")) {
            // The pile's head in this stage: driven down at a velocity (0 holds it), pushed by a
            // force, or struck by the hammer at the stage's start (a blow); else free.
            const int given = pm->has("velocity") + pm->has("force") + pm->has("blow");
            if (given != 1)
                pm->fail(pm->has("velocity") ? "velocity" : pm->has("force") ? "force" : "blow",
                         "one of velocity (m/s, down positive), force (N, compression positive) or blow: true",
                         given ? "more than one" : "none");
            s.pile_line = m.line_of("pile");
            s.pile_driven = pm->has("velocity");
            s.pile_loaded = pm->has("force");
            if (pm->has("blow")) {
                if (!pm->boolean_or("blow", false)) pm->fail("blow", "true (the hammer strikes the head at the stage's start)", "false");
                if (s.quasi_static) pm->fail("blow", "a dynamic stage (a blow is a wave in the pile)", "a quasi-static stage");
                s.pile_struck = true;
            }
            if (s.pile_driven)
                s.pile_velocity = pm->number("velocity", {"a head velocity in m/s, down positive", [](double) { return true; }});
            else if (s.pile_loaded)
                s.pile_force = pm->number("force", {"a head force in N, compression positive", [](double) { return true; }});
            if (!s.pile_struck) s.pile_rise_time = pm->number_or("rise_time", 0.0, non_negative("a rise time in s"));
            if (pm->has("load_test")) {
                s.load_test = pm->choice("load_test", {"static", "rapid"});
                if (s.load_test == "static" && !s.pile_driven)
                    pm->fail("load_test", "static with the head driven (velocity: m/s, down positive)", "static");
                if (s.load_test == "rapid" && !s.pile_struck)
                    pm->fail("load_test", "rapid with blow: true (the hammer's pulse, a force_table)", "rapid");
            }
            pm->finish();
        }
    m.finish();
    return s;
}

}  // namespace

MpmCase read_mpm_case(const std::string& file) {
    MapReader root = load_yaml_file(file);
    MpmCase c;
    read_case_header(root, c, file, "mpm");
    c.dimension = root.integer_or("dimension", 2, 2);
    if (c.dimension > 3) root.fail("dimension", "2 or 3", std::to_string(c.dimension));
    if (c.dimension == 2)
        c.axisymmetric = root.choice_or("geometry", "plane_strain", {"plane_strain", "axisymmetric"}) == "axisymmetric";
    read_grid(root.map("grid"), c);
    const std::string shape = root.choice_or("shape_function", "gimp", {"linear", "gimp", "cpdi"});
    c.shape = shape == "linear" ? mpm::ShapeKind::Linear : shape == "gimp" ? mpm::ShapeKind::GIMP : mpm::ShapeKind::CPDI;
    c.per_cell = root.integer_or("particles_per_cell", 2, 1);
    c.apic = root.choice_or("velocity_transfer", "flip_pic", {"flip_pic", "apic"}) == "apic";
    // C = sum v_i grad N_i jumps across cell faces with linear hats: APIC then blows up.
    if (c.apic && c.shape == mpm::ShapeKind::Linear)
        root.fail("velocity_transfer", "apic with shape_function gimp or cpdi (not linear)", "apic");
    if (c.apic && root.has("flip"))
        root.fail("flip", "no flip with velocity_transfer: apic (APIC has no FLIP/PIC blend)", "a flip fraction");
    c.smooth_dilatation = root.choice_or("volumetric_strain", "point", {"point", "nodal_average"}) == "nodal_average";
    c.flip = root.number_or("flip", 0.98, {"a FLIP fraction from 0 to 1", [](double x) { return x >= 0 && x <= 1; }});
    c.cfl = root.number_or("cfl", 0.5, in_half_open_range(0.0, 1.0, "a Courant number"));
    for (auto m : root.maps("materials")) c.materials.push_back(read_material(std::move(m), true));
    if (auto w = root.optional_map("water")) {
        c.water.density = w->number_or("density", 1000.0, positive("water density in kg/m^3"));
        c.water.bulk_modulus = w->number_or("bulk_modulus", 2.2e9, positive("the water's bulk modulus K_w in Pa"));
        c.water.viscosity = w->number_or("viscosity", 1.0e-3, positive("dynamic viscosity in Pa s"));
        if (w->has("level")) {
            c.water.free_surface = true;
            c.water.level = w->number("level", {"the elevation of the free water surface in m", [](double) { return true; }});
        }
        c.water.cavitation = w->boolean_or("cavitation", false);
        c.water.atmospheric_pressure =
            w->number_or("atmospheric_pressure", 101.325e3, non_negative("the air's pressure on the water surface in Pa"));
        w->finish();
    }
    for (auto m : root.maps("regions")) c.regions.push_back(read_region(std::move(m), c));
    if (root.has("boundaries"))
        for (auto m : root.maps("boundaries")) {
            MpmBoundaryInput b;
            std::tie(b.axis, b.side) = plane(m, "plane", c.dimension);
            const std::string t = m.choice("type", {"fixed", "roller", "absorbing", "frictional"});
            b.kind = t == "fixed"        ? mpm::BoundaryKind::Fixed
                     : t == "roller"     ? mpm::BoundaryKind::Roller
                     : t == "absorbing"  ? mpm::BoundaryKind::Absorbing
                                         : mpm::BoundaryKind::Frictional;
            if (b.kind == mpm::BoundaryKind::Frictional)
                b.friction = m.number("friction", non_negative("Coulomb friction coefficient"));
            if (b.kind == mpm::BoundaryKind::Absorbing)
                b.far_field_distance = m.number_or("far_field_distance", -1.0, non_negative("a distance in m (0: dashpots alone)"));
            // An open (absorbing) boundary lets water through as it lets the waves; a support
            // holds the water unless drained.
            b.drained = m.choice_or("drainage", b.kind == mpm::BoundaryKind::Absorbing ? "drained" : "impermeable",
                                    {"drained", "impermeable"}) == "drained";
            m.finish();
            c.boundaries.push_back(b);
        }
    if (auto pm = root.optional_map("pile")) {
        // The FE pile in the soil: its wall meshed in (r, z), toe at toe_elevation.
        if (c.dimension != 2 || !c.axisymmetric)
            pm->fail("toe_elevation", "a pile in a 2D axisymmetric case (geometry: axisymmetric)", "another geometry");
        auto& p = c.pile;
        p.present = true;
        p.toe_elevation = pm->number("toe_elevation", {"the toe's elevation in m", [](double) { return true; }});
        p.friction = pm->number_or("friction", 0.0, non_negative("the interface's friction coefficient tan(delta)"));
        p.penalty_factor = pm->number_or("penalty_factor", 4.0, in_open_range(0.0, 1000.0, "a penalty factor (k_n h_p^2 / (M A_p))"));
        p.corner_overlap_share = pm->choice_or("corner_contact", "full", {"full", "overlap"}) == "overlap";
        p.self_weight = pm->boolean_or("self_weight", true);
        p.wished_in_place = pm->boolean_or("wished_in_place", false);
        c.lines["pile.toe_elevation"] = pm->line_of("toe_elevation");
        if (pm->has("toe_cone_angle")) {
            p.toe_cone_angle = pm->number("toe_cone_angle", in_open_range(0.0, 180.0, "a cone's apex angle in degrees"));
            c.lines["pile.toe_cone_angle"] = pm->line_of("toe_cone_angle");
        }
        if (auto sl = pm->optional_map("toe_slip_line")) {
            c.lines["pile.toe_slip_line"] = pm->line_of("toe_slip_line");
            p.slip_line_cells = sl->number_or("length_in_cells", 1.5, in_open_range(0.0, 20.0, "a length in grid cells"));
            p.slip_line_friction_angle =
                sl->number("friction_angle", in_open_range(0.0, 90.0, "the soil's friction angle in degrees"));
            sl->finish();
        }
        const int model_line = pm->line_of("model");
        read_pile_section(std::move(*pm), p.pile, c, false);
        if (p.pile.model != PileModel::Axisymmetric)
            throw CaseError(file, model_line, "pile.model", "axisymmetric (the wall's surface is the contact)", "rod");
    }
    if (auto hm = root.optional_map("hammer")) {
        // The hammer of the blows (stages with pile: {blow: true}): a force on the head or a
        // ram-cushion chain, as pile wave analysis reads it.
        if (!c.pile.present) hm->fail("type", "a pile for the hammer to strike (a pile: section)", "no pile");
        read_hammer_section(std::move(*hm), c.pile.hammer, c);
        c.pile.has_hammer = true;
    }
    // Stages first: loads name the stages they act in.
    int drives = 0;
    for (auto m : root.maps("stages")) {
        if (m.has("type") && m.raw("type").IsScalar() && m.raw("type").as<std::string>() == "driving")
            read_drive(std::move(m), c, drives++, c.stages);
        else
            c.stages.push_back(read_stage(std::move(m)));
    }
    for (const auto& st : c.stages)
        if (st.pile_struck && !c.pile.has_hammer)
            throw CaseError(file, st.pile_line, "stages." + st.name + ".pile.blow",
                            "a hammer: section (half_sine, force_table or ram_cushion) for the blow", "none");
    std::vector<std::string> stage_names;
    for (const auto& st : c.stages) stage_names.push_back(st.name);
    if (root.has("pressures"))
        for (auto m : root.maps("pressures")) {
            MpmPressureInput p;
            p.box = box(m.map("box"), c.dimension);
            const auto [axis, side] = plane(m, "face", c.dimension);
            p.normal_axis = axis;
            p.normal_sign = side == 1 ? 1.0 : -1.0;  // outward normal of the loaded face
            const bool traction = m.has("traction");
            if (traction) {
                const auto t = m.numbers("traction", {"a traction in Pa", [](double) { return true; }});
                if (static_cast<int>(t.size()) != c.dimension)
                    m.fail("traction", std::to_string(c.dimension) + " components", std::to_string(t.size()));
                for (int d = 0; d < c.dimension; ++d) p.traction[d] = t[d];
            }
            const Expect pa{"a pressure in Pa", [](double) { return true; }};
            p.pressure = traction ? m.number_or("pressure", 0.0, pa) : m.number("pressure", pa);
            p.duration = m.number_or("duration", 0.0, non_negative("pulse duration in s"));
            if (m.has("pulse")) {
                if (p.duration <= 0.0) m.fail("pulse", "a duration > 0 for a pulse shape", "a held load");
                p.pulse = m.choice("pulse", {"rectangular", "half_sine", "sine_squared"});
            }
            if (m.has("stages"))
                for (const auto& name : m.words("stages", stage_names))
                    for (std::size_t k = 0; k < c.stages.size(); ++k)
                        if (c.stages[k].name == name) p.stages.push_back(static_cast<int>(k));
            m.finish();
            c.pressures.push_back(p);
        }
    if (root.has("velocities"))
        for (auto m : root.maps("velocities")) {
            MpmVelocityInput v;
            v.box = box(m.map("box"), c.dimension);
            const auto vel = m.numbers("velocity", {"a velocity in m/s", [](double) { return true; }});
            if (static_cast<int>(vel.size()) != c.dimension) m.fail("velocity", std::to_string(c.dimension) + " components", std::to_string(vel.size()));
            const auto comps = m.words("components", {"x", "y", "z"});
            for (int d = 0; d < c.dimension; ++d) v.velocity[d] = vel[d];
            for (const auto& s : comps) v.components[s[0] - 'x'] = true;
            m.finish();
            c.velocities.push_back(v);
        }
    if (auto init = root.optional_map("initial_stress")) {
        c.k0_initial_stress = init->choice("type", {"k0", "none"}) == "k0";
        if (c.k0_initial_stress) {
            c.surface = init->number("surface", {"an elevation in m", [](double) { return true; }});
            c.surcharge = init->number_or("surcharge", 0.0, non_negative("a pressure in Pa on the surface"));
        }
        init->finish();
    }
    if (auto out = root.optional_map("output")) {
        c.snapshot_interval = out->number_or("snapshot_interval", 0.0, non_negative("interval in s"));
        c.checkpoint_every = out->integer_or("checkpoint_every", 0, 0);
        c.history_segment_rows = out->integer_or("history_segment_rows", 100000, 1);
        c.plots = out->boolean_or("plots", true);
        if (out->has("probes")) {
            const YAML::Node list = out->raw("probes");
            if (!list.IsSequence()) out->fail("probes", "a list of points", describe(list));
            for (std::size_t i = 0; i < list.size(); ++i) {
                if (!list[i].IsSequence() || static_cast<int>(list[i].size()) != c.dimension)
                    throw CaseError(file, list[i].Mark().line + 1, "output.probes[" + std::to_string(i) + "]",
                                    std::to_string(c.dimension) + " coordinates", describe(list[i]));
                std::array<double, 3> p{};
                for (int d = 0; d < c.dimension; ++d) p[d] = list[i][d].as<double>();
                c.probes.push_back(p);
            }
        }
        out->finish();
    }
    if (auto v = root.optional_map("verification")) {
        c.verification_checks = v->words("checks", kChecks);
        for (const char* key : {"surface", "pressure", "inner_radius", "outer_radius", "depth",
                                "footing_width", "reference", "initial_width", "height", "noise_bound",
                                "min_order", "absorbed_share", "load", "pore_tolerance", "punch_radius",
                                "settlement_tolerance"})
            if (v->has(key)) c.verification[key] = v->number(key, {"a number", [](double) { return true; }});
        // hammer_energy_into_pile: the half-sine's peak (N) and time (s), the pile's Z (N s/m)
        // and the history's number of the blow's stage.
        if (v->has("impulse_peak")) c.verification["impulse_peak"] = v->number("impulse_peak", positive("a peak force in N"));
        if (v->has("impulse_time")) c.verification["impulse_time"] = v->number("impulse_time", positive("a pulse time in s"));
        if (v->has("pile_impedance"))
            c.verification["pile_impedance"] = v->number("pile_impedance", positive("an impedance E A / c in N s/m"));
        // ram_energy_into_pile: the rigid ram's mass (kg), impact velocity (m/s) and the time
        // after impact the energy is read at (s), with pile_impedance and blow_stage.
        if (v->has("ram_mass")) c.verification["ram_mass"] = v->number("ram_mass", positive("a ram mass in kg"));
        if (v->has("impact_velocity"))
            c.verification["impact_velocity"] = v->number("impact_velocity", positive("an impact velocity in m/s"));
        if (v->has("at_time")) c.verification["at_time"] = v->number("at_time", positive("a time after impact in s"));
        if (v->has("blow_stage"))
            c.verification["blow_stage"] = v->integer_or("blow_stage", 1, 1);
        // hammer_energy_every_blow: the blows a drive must have struck.
        if (v->has("blows")) c.verification["blows"] = v->integer_or("blows", 1, 1);
        if (v->has("energy_tolerance"))
            c.verification["energy_tolerance"] = v->number("energy_tolerance", positive("a share of the closed form's energy"));
        if (v->has("front_thickness"))
            c.verification["front_thickness"] = v->number("front_thickness", positive("a deposit thickness in m"));
        if (v->has("pulse_duration"))
            c.verification["pulse_duration"] = v->number("pulse_duration", positive("the load pulse's duration in s"));
        if (v->has("history_tolerance"))
            c.verification["history_tolerance"] = v->number("history_tolerance", positive("a share of the load"));
        // The case rerun on other grids (cells x factor along every axis): each check must
        // hold on every grid, and the errors are reported side by side.
        if (v->has("grid_sequence")) {
            c.grid_sequence = v->numbers("grid_sequence", positive("refinement factors of the cells"));
            // A one-dimensional case need not be refined across: grid_sequence_axes: [y].
            if (v->has("grid_sequence_axes")) {
                const auto axes = v->words("grid_sequence_axes", {"x", "y", "z"});
                c.refined_axes = {false, false, false};
                for (const auto& a : axes) c.refined_axes[a[0] - 'x'] = true;
            }
            // A graded grid refines its zones' cells: any factor will do.
            for (double f : c.grid_sequence)
                for (int d = 0; d < c.dimension; ++d) {
                    if (!c.refined_axes[d] || !c.zones[d].empty()) continue;
                    const double n = f * c.cells[d];
                    if (std::abs(n - std::round(n)) > 1e-9 || std::round(n) < 1)
                        v->fail("grid_sequence", "factors that give whole numbers of cells (" +
                                                     std::to_string(c.cells[d]) + " along axis " + std::to_string(d) +
                                                     ")", std::to_string(f));
                }
        }
        // The errors (names as in verification.json) whose order of convergence is checked.
        for (const char* key : {"converging", "self_converging"}) {
            if (!v->has(key)) continue;
            if (c.grid_sequence.empty()) v->fail(key, "a grid_sequence to converge on", "none");
            const std::string k = key;
            if (k == "self_converging" && c.grid_sequence.size() < 2)
                v->fail(key, "a grid_sequence of three grids or more (with the case's own)", "two");
            const YAML::Node list = v->raw(key);
            if (!list.IsSequence()) v->fail(key, "a list of check names", describe(list));
            auto& names = k == "converging" ? c.converging : c.self_converging;
            for (std::size_t i = 0; i < list.size(); ++i) names.push_back(list[i].as<std::string>());
        }
        if (v->has("tolerance_on")) {
            c.tolerance_on_finest_grid = v->choice_or("tolerance_on", "every_grid", {"every_grid", "finest_grid"}) == "finest_grid";
            if (c.tolerance_on_finest_grid && c.grid_sequence.empty())
                v->fail("tolerance_on", "a grid_sequence whose finest grid the tolerance holds on", "none");
        }
        v->finish();
    }
    root.finish();
    return c;
}

}  // namespace pilempm::io
