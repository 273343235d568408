#include "io/cases/mpm_run_builder.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "core/conventions.hpp"
#include "fem/mesh/axisymmetric_mesher.hpp"
#include "fem/mesh/conical_toe.hpp"
#include "io/yaml/case_error.hpp"

namespace pilempm::io {

namespace {

// A pile wished in place: a point of the shaft whose domain the wall cuts gives way to the
// parts of it either side of the steel, each ending on the wall's face (mass and volume in
// proportion), so the soil starts touching the wall inside and out. Without it the points
// beside a wall thinner than a cell stand up to half a point's width off it and the shaft
// carries nothing until the soil has moved that far. A part thinner than half the point
// joins the point beyond it (that point's domain then reaches the face): a sliver would
// set the contact's stable step (its penalty spring against its own mass, omega = c_p /
// thickness), 6e-6 s instead of 2.2e-5 s for the North Sea monopile on cells of 0.125 m.
// A part with no such neighbour stands alone, or under a tenth of the domain is dropped.
template <int D>
void split_at_the_wall(mpm::Particles<D>& p, std::vector<char>& keep, const fem::PileGeometry& g, double toe,
                       double cone, bool axisymmetric) {
    const std::size_t count = p.size();
    auto half_r = [&](std::size_t i) { return 0.5 * p.domain0[D * D * i]; };
    auto half_z = [&](std::size_t i) { return 0.5 * p.domain0[D * D * i + D * (D - 1) + D - 1]; };
    auto cut = [&](std::size_t i) {
        const double hr = half_r(i), hz = half_z(i), r = p.x[D * i], z = p.x[D * i + D - 1] - toe;
        const double touch = 1e-9 * hz;
        if (z - hz < cone - touch || z + hz > g.length() + touch) return false;  // the shaft's points only (not a cone's)
        return !(r + hr <= g.inner_radius_at(z) || r - hr >= g.outer_radius_at(z));
    };
    // The points by the edges of their domains in r at their height (nm), to find the one
    // beyond a part.
    using Key = std::pair<long long, long long>;
    auto key = [](double r, double z) { return Key{std::llround(r * 1e9), std::llround(z * 1e9)}; };
    std::map<Key, std::size_t> by_left_edge, by_right_edge;
    for (std::size_t i = 0; i < count; ++i) {
        by_left_edge[key(p.x[D * i] - half_r(i), p.x[D * i + D - 1])] = i;
        by_right_edge[key(p.x[D * i] + half_r(i), p.x[D * i + D - 1])] = i;
    }
    std::vector<std::pair<std::size_t, std::array<double, 2>>> joins;  // neighbour, the part's [r0, r1]
    for (std::size_t i = 0; i < count; ++i) {
        if (!cut(i)) continue;
        keep[i] = 0;
        const double hr = half_r(i), r = p.x[D * i], z = p.x[D * i + D - 1] - toe;
        const double ri = g.inner_radius_at(z), ro = g.outer_radius_at(z);
        const double pieces[2][2] = {{r - hr, std::min(ri, r + hr)}, {std::max(ro, r - hr), r + hr}};
        for (int side = 0; side < 2; ++side) {
            const double* piece = pieces[side];
            const double width = piece[1] - piece[0];
            if (width <= 0.0) continue;
            if (width < hr) {
                const auto& edges = side == 0 ? by_right_edge : by_left_edge;
                const auto it = edges.find(key(side == 0 ? r - hr : r + hr, p.x[D * i + D - 1]));
                if (it != edges.end() && !cut(it->second) && half_z(it->second) == half_z(i)) {
                    joins.push_back({it->second, {piece[0], piece[1]}});
                    continue;
                }
                if (width < 0.2 * hr) continue;
            }
            double x[D], len[D];
            for (int d = 0; d < D; ++d) x[d] = p.x[D * i + d], len[d] = p.domain0[D * D * i + D * d + d];
            x[0] = 0.5 * (piece[0] + piece[1]);
            len[0] = width;
            const double share = width / (2.0 * hr) * (axisymmetric ? x[0] / r : 1.0);
            p.add(x, p.mass[i] * share, p.volume[i] * share, len, p.material[i]);
            p.porosity.back() = p.porosity[i];
            keep.push_back(1);
        }
    }
    // Per radian a ring's volume is its mid-radius times its width, so the joined point at
    // its new middle holds both masses exactly.
    for (const auto& [j, piece] : joins) {
        const double hr = half_r(j), r = p.x[D * j];
        const double lo = std::min(r - hr, piece[0]), hi = std::max(r + hr, piece[1]);
        const double mid = 0.5 * (lo + hi), grown = (hi - lo) / (2.0 * hr) * (axisymmetric ? mid / r : 1.0);
        p.mass[j] *= grown;
        p.volume[j] *= grown;
        p.volume0[j] *= grown;
        p.x[D * j] = mid;
        p.domain0[D * D * j] = hi - lo;
    }
}

// A length to the millimetre, as a message shows it.
std::string metres(double x) {
    std::ostringstream out;
    out.precision(3);
    out << std::fixed << x;
    return out.str();
}

// The shortest a blow runs before the pile counts as at rest: the given one, else the
// hammer's pulse (a ram-cushion's: none, its ram rides the head) and four of the wave's
// transits of the pile, so a blow does not end between two of its reflections.
double blow_min_duration(const MpmCase& c, const MpmStageInput& st) {
    if (st.min_duration >= 0.0) return st.min_duration;
    const fem::HammerSpec& h = c.pile.hammer.hammer;
    const double pulse = h.kind == fem::HammerKind::PrescribedForce ? h.force.end_time() : 0.0;
    return pulse + 4.0 * c.pile.pile.length() / c.pile.pile.steel.wave_speed();
}

template <int D>
bool in_region(const MpmRegionInput& r, const double* x) {
    if (r.kind == MpmRegionInput::Cylinder) {
        const double dx = x[0] - r.centre[0], dy = x[1] - r.centre[1];
        return dx * dx + dy * dy <= r.radius * r.radius && x[D - 1] >= r.centre[D - 1] &&
               x[D - 1] <= r.centre[D - 1] + r.height;
    }
    for (int d = 0; d < D; ++d)
        if (x[d] < r.box.min[d] || x[d] > r.box.max[d]) return false;
    return true;
}

template <int D>
bool in_box(const MpmBox& b, const double* x) {
    for (int d = 0; d < D; ++d)
        if (x[d] < b.min[d] - 1e-12 || x[d] > b.max[d] + 1e-12) return false;
    return true;
}

// The points a pressure loads: in its box, of each column of points along the face's normal
// only the outermost (the material's face). A box deeper than a row of points (any box, on a
// fine enough grid) would otherwise apply the full pressure once per row.
template <int D>
std::vector<int> face_points(const mpm::Particles<D>& p, const MpmPressureInput& pr) {
    std::map<std::array<long long, D - 1>, int> outermost;  // lateral position (nm) -> point
    const int a = pr.normal_axis;
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (!in_box<D>(pr.box, &p.x[D * i])) continue;
        std::array<long long, D - 1> lateral{};
        for (int d = 0, k = 0; d < D; ++d)
            if (d != a) lateral[k++] = std::llround(p.x[D * i + d] * 1e9);
        const auto [it, fresh] = outermost.emplace(lateral, static_cast<int>(i));
        if (!fresh && pr.normal_sign * (p.x[D * i + a] - p.x[D * it->second + a]) > 0.0) it->second = static_cast<int>(i);
    }
    std::vector<int> points;
    for (const auto& [lateral, i] : outermost) points.push_back(i);
    std::sort(points.begin(), points.end());
    return points;
}

}  // namespace

template <int D>
MpmRun<D> build_mpm_run(const MpmCase& c) {
    MpmRun<D> run;
    auto& m = run.model;
    for (int d = 0; d < D; ++d) {
        m.grid.origin[d] = c.origin[d];
        m.grid.cells[d] = c.cells[d];
        m.grid.spacing[d] = c.size[d] / c.cells[d];
        if (!c.zones[d].empty()) m.grid.set_lines(d, mpm::graded_axis(c.origin[d], c.zones[d]));
    }
    // Saturated soil: the pore water of each material, and water fields when one is coupled.
    m.water.density = c.water.density;
    m.water.bulk_modulus = c.water.bulk_modulus;
    m.water.free_surface = c.water.free_surface;
    m.water.level = c.water.level;
    m.water.cavitation = c.water.cavitation;
    m.water.atmospheric_pressure = c.water.atmospheric_pressure;
    m.water.gravity = c.gravity > 0.0 ? c.gravity : 9.81;
    bool coupled = false;
    for (const auto& mat : c.materials) {
        mpm::MaterialDrainage dr;
        dr.drainage = mat.drainage == "drained"     ? mpm::Drainage::Drained
                      : mat.drainage == "undrained" ? mpm::Drainage::Undrained
                      : mat.drainage == "coupled"   ? mpm::Drainage::Coupled
                                                    : mpm::Drainage::Dry;
        dr.porosity = mat.porosity;
        // mu / kappa: from k = kappa rho_w g / mu with standard gravity (k is measured at 1 g,
        // whatever the model's g), or from kappa and the water's viscosity.
        constexpr double kStandardGravity = 9.80665;
        if (mat.hydraulic_conductivity > 0.0) dr.darcy_resistance = c.water.density * kStandardGravity / mat.hydraulic_conductivity;
        if (mat.intrinsic_permeability > 0.0) dr.darcy_resistance = c.water.viscosity / mat.intrinsic_permeability;
        coupled = coupled || dr.drainage == mpm::Drainage::Coupled;
        m.drainage.push_back(dr);
    }
    if (coupled) {
        m.grid.water = true;
        m.grid.fields = 2;
    }
    // The soil inside and outside an open pile's wall: a set of fields each (a cut); and
    // either side of a toe slip line.
    if (c.pile.present && c.pile.open_ended()) m.grid.fields *= 2;
    if (c.pile.present && c.pile.slip_line_cells > 0.0) {
        if (coupled)
            throw CaseError(c.file, c.line_of("pile.toe_slip_line"), "pile.toe_slip_line",
                            "dry, drained or undrained soil (a slip line with pore-water fields is not built yet)",
                            "a coupled (v-w) material");
        m.grid.fields *= 2;
    }
    m.grid.allocate();
    m.shape = c.shape;
    m.axisymmetric = c.axisymmetric;
    m.gravity[D - 1] = -c.gravity;
    m.flip = c.flip;
    m.apic = c.apic;
    m.smooth_dilatation = c.smooth_dilatation;
    m.cfl = c.cfl;
    int stride = 0;
    for (const auto& mat : c.materials) {
        m.materials.push_back(mpm::make_constitutive_model(mat));
        stride = std::max(stride, m.materials.back()->num_state());
    }
    m.particles.state_stride = stride;
    for (std::size_t k = 0; k < c.regions.size(); ++k) {
        const auto& r = c.regions[k];
        // The first region that holds a point owns it.
        auto inside = [&](const double* x) {
            if (!in_region<D>(r, x)) return false;
            for (std::size_t j = 0; j < k; ++j)
                if (in_region<D>(c.regions[j], x)) return false;
            return true;
        };
        // A saturated point's own mass is its grains', (rho_sat - n rho_w) V: the water's is n rho_w V.
        const auto& dr = m.drainage[r.material];
        const double solid_density = c.materials[r.material].density - dr.porosity * c.water.density;
        if (!(solid_density > 0.0))
            throw std::runtime_error("material " + c.materials[r.material].name + ": the saturated density " +
                                     std::to_string(c.materials[r.material].density) +
                                     " kg/m^3 is not above the water's share n rho_w");
        const std::size_t first = m.particles.size();
        mpm::fill_region<D>(m.grid, m.particles, inside, c.per_cell, solid_density, r.material, c.axisymmetric);
        for (std::size_t i = first; i < m.particles.size(); ++i) m.particles.porosity[i] = dr.porosity;
    }
    if (m.particles.size() == 0) throw std::runtime_error("the regions hold no material points");
    if (c.pile.present) {
        // The soil where the pile's steel is: removed (wished in place), else an error.
        const fem::PileGeometry g = fem::make_pile_geometry(c.pile.pile.segments, c.pile.pile.taper_ratio);
        // A conical toe's steel reaches r = R z / h below its shoulder (z = h).
        const double cone = c.pile.toe_cone_angle > 0.0 ? fem::cone_height(g.outer_radius_at(0.0), c.pile.toe_cone_angle) : 0.0;
        auto outer_at = [&](double z) {
            const double ro = g.outer_radius_at(z);
            return z < cone ? ro * std::max(z, 0.0) / cone : ro;
        };
        // Overlapping: a point's domain reaches into the steel (its centre in it: removed).
        std::vector<char> keep(m.particles.size(), 1);
        std::size_t overlapping = 0;
        double highest_top = -1e300;  // m: the highest overlapping domain's top
        const auto& p0 = m.particles;
        for (std::size_t i = 0; i < p0.size(); ++i) {
            const double hr = 0.5 * p0.domain0[D * D * i], hz = 0.5 * p0.domain0[D * D * i + D * (D - 1) + D - 1];
            const double r = p0.x[D * i], z = p0.x[D * i + D - 1] - c.pile.toe_elevation;
            const double touch = 1e-9 * hz;  // a domain only touching the steel does not overlap it
            if (z + hz <= touch || z - hz >= g.length() - touch) continue;
            const double zc = std::clamp(z, 0.0, g.length());
            const double widest = outer_at(std::clamp(z + hz, 0.0, g.length()));  // over the domain's height
            if (r + hr <= g.inner_radius_at(zc) + touch || r - hr >= widest - touch) continue;
            ++overlapping;
            highest_top = std::max(highest_top, p0.x[D * i + D - 1] + hz);
            if (z >= 0.0 && z <= g.length() && r >= g.inner_radius_at(z) && r <= outer_at(z)) keep[i] = 0;
        }
        if (overlapping > 0 && !c.pile.wished_in_place)
            throw CaseError(c.file, c.line_of("pile.toe_elevation"), "pile.toe_elevation",
                            "a pile that starts clear of the soil, or wished_in_place: true",
                            std::to_string(overlapping) + " material points overlapping its wall, reaching up to " +
                                metres(highest_top) +
                                " m (points fill whole grid cells: a region's top between two grid lines"
                                " reaches the line above it)");
        if (c.pile.wished_in_place) split_at_the_wall<D>(m.particles, keep, g, c.pile.toe_elevation, cone, c.axisymmetric);
        m.particles.keep_only(keep);
    }
    for (const auto& b : c.boundaries) {
        // Absorbing boundaries take the first material's moduli (a pressure-dependent model
        // states them at its reference pressure).
        const auto& mat = c.materials.front();
        const auto& dr = m.drainage.front();
        const double G = m.materials.front()->shear_modulus(), M = m.materials.front()->p_wave_modulus();
        const double rho = mat.density;  // the whole soil's: saturated when wet
        double cp = std::sqrt(M / rho), water_impedance = 0.0;
        if (dr.drainage == mpm::Drainage::Undrained || dr.drainage == mpm::Drainage::Coupled) {
            // An undrained wave carries sigma' = M eps and p = (K_w / n) eps at c_u: the skeleton's
            // dashpot takes M / c_u, the pore pressure's K_w / (n c_u) (on the water, coupled)
            // or with the skeleton (undrained); together rho_sat c_u.
            const double cu = mpm::saturated_wave_speeds(M, dr.porosity, rho - dr.porosity * c.water.density, m.water).undrained;
            const double pore = c.water.bulk_modulus / (dr.porosity * cu);
            cp = (M / cu + (dr.drainage == mpm::Drainage::Coupled ? 0.0 : pore)) / rho;
            if (dr.drainage == mpm::Drainage::Coupled) water_impedance = pore;
        }
        // The far field's springs: from the source, taken at the boundary's opposite face.
        const double far = b.far_field_distance >= 0.0 ? b.far_field_distance : m.grid.top(b.axis) - m.grid.origin[b.axis];
        mpm::apply_boundary<D>(m.grid, b.axis, b.side, b.kind, rho, cp, std::sqrt(G / rho), c.axisymmetric, b.friction,
                               water_impedance, b.drained, far);
    }
    auto& p = m.particles;
    for (const auto& pr : c.pressures)
        for (const int i : face_points<D>(p, pr)) {
            double area = 1.0;
            for (int d = 0; d < D; ++d)
                if (d != pr.normal_axis) area *= p.domain0[D * D * i + D * d + d];
            // Per radian the face's area scales with its own radius (the particle's face,
            // not its centre, when the face is normal to r).
            if (c.axisymmetric)
                area *= p.x[D * i] + (pr.normal_axis == 0 ? 0.5 * pr.normal_sign * p.domain0[0] : 0.0);
            // The force on each loaded point: (traction - p n) x the point's face area.
            coupling::StageLoad load;
            load.duration = pr.duration;
            load.shape = pr.pulse == "half_sine"      ? coupling::PulseShape::HalfSine
                         : pr.pulse == "sine_squared" ? coupling::PulseShape::SineSquared
                                                      : coupling::PulseShape::Rectangular;
            load.stages = pr.stages;
            load.load.point = i;
            for (int d = 0; d < D; ++d) load.load.force[d] = pr.traction[d] * area;
            load.load.force[pr.normal_axis] -= pr.pressure * pr.normal_sign * area;
            load.load.offset[pr.normal_axis] = 0.5 * pr.normal_sign * p.domain0[D * D * i + D * pr.normal_axis + pr.normal_axis];
            run.loads.push_back(load);
        }
    for (const auto& v : c.velocities)
        for (int n = 0; n < m.grid.num_nodes(); ++n) {
            const auto ijk = m.grid.ijk(n);
            double x[D];
            for (int d = 0; d < D; ++d) x[d] = m.grid.coordinate(d, ijk[d]);
            if (!in_box<D>(v.box, x)) continue;
            auto& cond = m.grid.condition(n);
            for (int d = 0; d < D; ++d)
                if (v.components[d]) {
                    cond.fixed[d] = 1;
                    cond.prescribed[d] = v.velocity[d];
                }
            run.reaction_nodes.push_back(n);
        }
    if (c.k0_initial_stress) {
        auto material_at = [&](double z) -> const MpmMaterialInput& {
            for (const auto& r : c.regions)
                if (r.kind != MpmRegionInput::Cylinder && z >= r.box.min[D - 1] && z <= r.box.max[D - 1])
                    return c.materials[r.material];
            return c.materials.front();
        };
        // Effective stress from the buoyant weight below the water surface.
        auto effective_density = [&](double z) {
            const auto& mat = material_at(z);
            const bool wet = mat.drainage != "dry";
            return mat.density - (wet && m.water.submerged(z) ? c.water.density : 0.0);
        };
        mpm::apply_k0_stress<D>(p, c.surface, c.gravity, effective_density,
                                [&](double z) { return mpm::k0_of(material_at(z)); }, c.surcharge);
    }
    for (std::size_t i = 0; i < p.size(); ++i)
        m.materials[p.material[i]]->initialise_state(&p.stress[6 * i], p.state.data() + p.state_stride * i);
    for (const auto& probe : c.probes) {
        int best = 0;
        double d2best = 1e300;
        for (std::size_t i = 0; i < p.size(); ++i) {
            double d2 = 0.0;
            for (int d = 0; d < D; ++d) d2 += (p.x[D * i + d] - probe[d]) * (p.x[D * i + d] - probe[d]);
            if (d2 < d2best) d2best = d2, best = static_cast<int>(i);
        }
        run.probe_points.push_back(best);
    }
    run.x0 = p.x;
    for (const auto& st : c.stages) {
        coupling::StageSpec s;
        s.name = st.name;
        s.quasi_static = st.quasi_static;
        s.duration = st.duration;
        s.max_steps = st.max_steps;
        s.tolerance = st.tolerance;
        s.local_damping = st.local_damping;
        s.drained = st.drained;
        s.gravity_factor = st.gravity_factor;
        s.consolidation = st.consolidation;
        s.steps = st.steps;
        s.step_growth = st.step_growth;
        s.linear_solver = st.linear_solver;
        s.direct_below = st.direct_below;
        s.drive = st.drive;
        s.blow = st.blow;
        s.rest_speed = st.rest_speed;
        s.min_duration = st.blow ? blow_min_duration(c, st) : 0.0;
        // At rest for as long as that too: longer than a bounce's top, where the speed dwells
        // below rest_speed (2 ms for the 3 m pile rebounding on loose sand, 4 ms for the
        // monopile rocking at 4 Hz).
        s.rest_span = !st.blow ? 0.0 : st.rest_span >= 0.0 ? st.rest_span : s.min_duration;
        s.settle_damping = st.settle_damping;
        s.record_every = st.history_every;
        s.end_toe_elevation = st.end_toe_elevation;
        s.refusal_set = st.refusal_set;
        s.refusal_blows = st.refusal_blows;
        s.blow_interval = st.blow_interval;
        s.snapshot_at_end = !(st.drive >= 0 && st.consolidation);  // a drive's snapshots: after each blow
        run.stages.push_back(s);
    }
    run.settings.snapshot_interval = c.snapshot_interval;
    run.settings.checkpoint_every = c.checkpoint_every;
    if (c.pile.present) {
        if constexpr (D == 2) {
            auto& pile = run.pile;
            pile.present = true;
            const fem::PileGeometry geometry = fem::make_pile_geometry(c.pile.pile.segments, c.pile.pile.taper_ratio);
            pile.mesh = fem::mesh_axisymmetric_wall(geometry, c.pile.pile.element_size, c.pile.pile.radial_divisions,
                                                    fem::default_pile_wall_geo());
            if (c.pile.toe_cone_angle > 0.0) {
                if (c.pile.open_ended())
                    throw CaseError(c.file, c.line_of("pile.toe_cone_angle"), "pile.toe_cone_angle",
                                    "a closed-ended pile (a solid last segment: wall_thickness = outer_diameter / 2)",
                                    "an open-ended pile");
                try {
                    fem::shape_conical_toe(pile.mesh, c.pile.toe_cone_angle);
                } catch (const std::invalid_argument& e) {
                    throw CaseError(c.file, c.line_of("pile.toe_cone_angle"), "pile.toe_cone_angle",
                                    "a cone the pile is long enough for", e.what());
                }
            }
            pile.steel = c.pile.pile.steel;
            pile.contact.friction = c.pile.friction;
            pile.contact.penalty_factor = c.pile.penalty_factor;
            // The case's cfl is the share of the stable step taken, the contact's too: halving
            // it halves the step wherever the contact sets it (a time-step convergence study).
            pile.contact.stability_margin = 2.0 * c.cfl;
            pile.contact.corner_overlap_share = c.pile.corner_overlap_share;
            pile.contact.ring = full_ring(1.0);
            pile.contact.axisymmetric = true;
            pile.contact.ignore_initial_overlap = c.pile.wished_in_place;
            pile.frame.toe_elevation = c.pile.toe_elevation;
            // A solid (closed-ended) pile has no soil inside: no cut through the grid's fields.
            pile.cut_fields = c.pile.open_ended();
            if (c.pile.slip_line_cells > 0.0) {
                const double cell = std::min(m.grid.spacing[0], m.grid.spacing[1]);  // the finest (a graded grid's, at the pile)
                pile.toe_slip_line = {c.pile.slip_line_cells * cell,
                                      std::tan(c.pile.slip_line_friction_angle * std::numbers::pi / 180.0)};
            }
            pile.gravity = c.pile.self_weight ? c.gravity : 0.0;
            for (const auto& st : c.stages)
                pile.heads.push_back({st.pile_driven, st.pile_velocity, st.pile_loaded, st.pile_force, st.pile_rise_time,
                                      st.pile_struck, st.pile_struck ? c.pile.hammer.hammer : fem::HammerSpec{},
                                      c.pile.pile.element_size});
        }
    }
    return run;
}

template <int D>
std::vector<std::string> state_names(const mpm::MpmModel<D>& m) {
    const mpm::ConstitutiveModel* named = m.materials.front().get();
    for (const auto& mat : m.materials)
        if (mat->num_state() > named->num_state()) named = mat.get();
    std::vector<std::string> names;
    for (int k = 0; k < m.particles.state_stride; ++k) names.push_back(named->state_name(k));
    return names;
}

template MpmRun<2> build_mpm_run<2>(const MpmCase&);
template MpmRun<3> build_mpm_run<3>(const MpmCase&);
template std::vector<std::string> state_names<2>(const mpm::MpmModel<2>&);
template std::vector<std::string> state_names<3>(const mpm::MpmModel<3>&);

}  // namespace pilempm::io
