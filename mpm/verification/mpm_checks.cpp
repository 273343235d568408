#include "mpm/verification/mpm_checks.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "mpm/analysis/granular_collapse.hpp"
#include "mpm/verification/pore_water_checks.hpp"

namespace pilempm::mpm {


double parameter(const MpmCheckContext& c, const char* key, const char* check) {
    auto it = c.parameters.find(key);
    if (it == c.parameters.end())
        throw std::invalid_argument(std::string(check) + " needs verification." + key + " in the case file");
    return it->second;
}

const std::vector<double>& column(const Table& t, const std::string& name) {
    for (std::size_t k = 0; k < t.columns.size(); ++k)
        if (t.columns[k] == name) return t.data[k];
    throw std::invalid_argument("history has no column " + name + " (add output.probes)");
}

namespace {

// Max error of the vertical stress against rho g (original depth), over rho g H.
template <int D>
VerificationCheck self_weight(const MpmCheckContext& c, const MpmModel<D>& m, const std::vector<double>& x0) {
    const double surface = parameter(c, "surface", "self_weight_stress");
    const auto& p = m.particles;
    double worst = 0.0, base = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) base = std::max(base, (surface - x0[D * i + D - 1]) * p.mass[i] / p.volume0[i]);
    base *= c.gravity;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double rho = p.mass[i] / p.volume0[i];
        const double exact = -rho * c.gravity * (surface - x0[D * i + D - 1]);
        worst = std::max(worst, std::abs(p.stress[6 * i + (D == 2 ? 1 : 2)] - exact) / base);
    }
    return make_check("vertical_stress_max_error_relative", worst, 0.0, 0.02, false,
                      "max |sigma_v - rho g z| / (rho g H) over all material points");
}

// Lame: sigma_r = -p a^2/(b^2-a^2) (b^2/r^2 - 1), sigma_theta = p a^2/(b^2-a^2) (b^2/r^2 + 1).
// Stresses of a linear basis are first-order accurate at arbitrary points but second-order
// at cell centres: the check compares each cell's mean point stress with the exact value at
// the cell's mean (initial) radius.
std::vector<VerificationCheck> lame(const MpmCheckContext& c, const MpmModel<2>& m, const std::vector<double>& x0) {
    const double a = parameter(c, "inner_radius", "lame_cylinder"), b = parameter(c, "outer_radius", "lame_cylinder");
    const double pr = parameter(c, "pressure", "lame_cylinder");
    const auto& g = m.grid;
    const auto& p = m.particles;
    const int cells = g.cells[0];
    std::vector<double> r_sum(cells, 0.0), sr(cells, 0.0), st(cells, 0.0), n(cells, 0.0);
    for (std::size_t i = 0; i < p.size(); ++i) {
        const int k = g.cell_of(0, x0[2 * i]);
        r_sum[k] += x0[2 * i];
        sr[k] += p.stress[6 * i + 0];
        st[k] += p.stress[6 * i + 2];
        n[k] += 1.0;
    }
    double err_r = 0.0, err_t = 0.0;
    const double k = pr * a * a / (b * b - a * a);
    for (int j = 0; j < cells; ++j) {
        if (n[j] == 0.0) continue;
        const double r = r_sum[j] / n[j];
        err_r = std::max(err_r, std::abs(sr[j] / n[j] + k * (b * b / (r * r) - 1.0)) / pr);
        err_t = std::max(err_t, std::abs(st[j] / n[j] - k * (b * b / (r * r) + 1.0)) / pr);
    }
    return {make_check("radial_stress_max_error_over_p", err_r, 0.0, 0.02, false,
                       "Lame solution against the cell-averaged point stresses, every cell"),
            make_check("hoop_stress_max_error_over_p", err_t, 0.0, 0.02, false,
                       "Lame solution against the cell-averaged point stresses, every cell")};
}

}  // namespace

// Half-amplitude arrival of the pulse at a probe (linear between samples).
double arrival(const std::vector<double>& t, const std::vector<double>& v, double plateau, double& dt) {
    double when = -1.0;
    for (std::size_t i = 1; i < t.size(); ++i) {
        const double a = std::abs(v[i - 1]) - 0.5 * plateau, b = std::abs(v[i]) - 0.5 * plateau;
        if (t[i] > t[i - 1]) dt = std::max(dt, t[i] - t[i - 1]);
        if (when < 0.0 && a < 0.0 && b >= 0.0) when = t[i - 1] + (t[i] - t[i - 1]) * a / (a - b);
    }
    return when;
}

namespace {

// Travel time of the pulse between two probes `depth` apart: the wave speed, free of how
// the surface load enters the first row of points. A P-wave (a pressure pulse) is timed on
// the vertical velocity against c_p, an S-wave (a shear traction pulse) on the horizontal
// velocity against c_s; verification.pressure is the pulse's peak, within 2 % of depth / c
// (the discrete wave is a little slower than the continuum's: the error shrinks with h).
template <int D>
VerificationCheck wave_arrival(const MpmCheckContext& c, const MpmModel<D>& m, const Table& history, bool shear) {
    const char* check = shear ? "shear_wave_arrival" : "wave_arrival";
    const double depth = parameter(c, "depth", check);
    const double amplitude = parameter(c, "pressure", check);
    const double rho = c.density;
    const auto& model = *m.materials.front();
    const double speed = std::sqrt((shear ? model.shear_modulus() : model.p_wave_modulus()) / rho);
    const double plateau = amplitude / (rho * speed);  // particle speed behind the front
    const auto& t = column(history, "time_s");
    const std::string v = shear ? "_velocity_x_m_s" : "_velocity_vertical_m_s";
    double dt = 0.0;
    const double first = arrival(t, column(history, "probe0" + v), plateau, dt);
    const double second = arrival(t, column(history, "probe1" + v), plateau, dt);
    return make_check(shear ? "shear_wave_travel_time_between_probes_s" : "wave_travel_time_between_probes_s",
                      second - first, depth / speed, 0.02, true,
                      std::string("half-amplitude arrivals at two probes against their distance / ") +
                          (shear ? "c_s" : "c_p"));
}

// The share of the wave's energy the absorbing boundary took, two ways: the dashpots' work
// over the work the loads put in, and one minus the energy left in the body over its peak;
// each at least verification.absorbed_share (default 0.97).
std::vector<VerificationCheck> absorbed(const MpmCheckContext& c, const Table& history) {
    const double share = c.parameters.count("absorbed_share") ? c.parameters.at("absorbed_share") : 0.97;
    const auto& ke = column(history, "kinetic_energy_J");
    const auto& se = column(history, "elastic_energy_J");
    const double input = column(history, "external_work_J").back();
    const double taken = column(history, "absorbed_energy_J").back();
    double peak = 0.0;
    for (std::size_t i = 0; i < ke.size(); ++i) peak = std::max(peak, ke[i] + se[i]);
    const double left = peak > 0.0 ? 1.0 - (ke.back() + se.back()) / peak : 0.0;
    const double work = input > 0.0 ? taken / input : 0.0;
    auto at_least = [share](VerificationCheck k) {
        k.at_least = true;
        k.passed = k.computed >= share;
        return k;
    };
    return {at_least(make_check("wave_energy_absorbed_over_input", work, share, 0.0, false,
                                "work of the absorbing dashpots over the work of the loads")),
            at_least(make_check("wave_energy_fraction_absorbed", left, share, 0.0, false,
                                "1 - energy left in the body / its peak energy"))};
}

}  // namespace

// Strip footing on Tresca soil: the largest footing pressure (reaction of the pushed nodes,
// a half model: x2, over the footing width) against Prandtl's (2 + pi) c.
VerificationCheck footing(const MpmCheckContext& c, const Table& history, int D) {
    const double width = parameter(c, "footing_width", "footing_collapse");  // full width B
    const double cohesion = parameter(c, "reference", "footing_collapse");
    const auto& r = column(history, D == 2 ? "reaction_y_N" : "reaction_z_N");
    double peak = 0.0;
    for (double x : r) peak = std::max(peak, -x);  // the soil pushes the footing up
    const double q = 2.0 * peak / width;
    return make_check("footing_collapse_pressure_over_c", q / cohesion, 2.0 + M_PI, 0.05, true,
                      "Prandtl: q_u = (2 + pi) c for a strip footing on weightless Tresca soil");
}

// A rigid circular punch (the FE pile, its head loaded) on an elastic half-space: its
// settlement under the final head load P against Boussinesq's w = P (1 - nu^2) / (2 a E).
// Read off the pile's history columns; the settlement counts the contact's penalty
// compliance (it shrinks with the point size) and the domain's finite depth (stiffer).
VerificationCheck rigid_punch(const MpmCheckContext& c, const Table& history) {
    const double a = parameter(c, "punch_radius", "rigid_punch");
    if (c.model != "linear_elastic") throw std::invalid_argument("rigid_punch is the closed form of a linear_elastic half-space");
    const double load = column(history, "pile_head_force_N").back();
    const double settlement = column(history, "pile_head_settlement_m").back();
    const double tol = c.parameters.count("settlement_tolerance") ? c.parameters.at("settlement_tolerance") : 0.05;
    const double nu = c.poisson_ratio;
    return make_check("punch_settlement_m", settlement, load * (1.0 - nu * nu) / (2.0 * a * c.youngs_modulus), tol,
                      true, "rigid smooth circular punch on an elastic half-space: w = P (1 - nu^2) / (2 a E)");
}

// A half-sine blow F0 sin(pi t / t_i) on the head of a pile whose head sees no reflection
// before t_i (its stick-up above the soil and its length both longer than c t_i / 2): the
// head moves at v = F / Z, so the hammer puts in F0^2 t_i / (2 Z) by the pulse's end: the
// blow's ENTHRU (the hammer's work on the head, summed over the pile's substeps) at the end
// of its stage.
VerificationCheck hammer_energy(const MpmCheckContext& c, const Table& history) {
    const char* check = "hammer_energy_into_pile";
    const double peak = parameter(c, "impulse_peak", check), duration = parameter(c, "impulse_time", check);
    const double impedance = parameter(c, "pile_impedance", check), stage = parameter(c, "blow_stage", check);
    const auto& st = column(history, "stage");
    const auto& enthru = column(history, "enthru_J");
    double work = 0.0;
    for (std::size_t i = 0; i < st.size(); ++i)
        if (st[i] == stage) work = enthru[i];
    // 0.5 %: the 1D closed form leaves out the wall's lateral inertia (0.05 to 0.1 % here).
    return make_check("hammer_energy_into_pile_J", work, peak * peak * duration / (2.0 * impedance), 0.005, true,
                      "half-sine blow on a pile head without reflections: F0^2 t_i / (2 Z)");
}

// Blow after blow of the same half-sine on a pile driven deeper each time: each blow puts
// the same F0^2 t_i / (2 Z) into the pile (no wave back at the head before t_i, whatever the
// soil did in the blows and pauses before). The blows are the stages where ENTHRU is not
// zero; the blow furthest from the closed form is reported, and all `blows` must have run.
// Within 0.5 % unless `energy_tolerance` says otherwise (a pile still moving on the soil
// when the next blow strikes takes a little more or less).
std::vector<VerificationCheck> hammer_energy_every_blow(const MpmCheckContext& c, const Table& history) {
    const char* check = "hammer_energy_every_blow";
    const double peak = parameter(c, "impulse_peak", check), duration = parameter(c, "impulse_time", check);
    const double impedance = parameter(c, "pile_impedance", check), blows = parameter(c, "blows", check);
    const double reference = peak * peak * duration / (2.0 * impedance);
    const auto tolerance = c.parameters.count("energy_tolerance") ? c.parameters.at("energy_tolerance") : 0.005;
    const auto& st = column(history, "stage");
    const auto& enthru = column(history, "enthru_J");
    std::map<double, double> per_stage;  // the blow's stage, its ENTHRU at the end
    for (std::size_t i = 0; i < st.size(); ++i)
        if (enthru[i] != 0.0) per_stage[st[i]] = std::max(per_stage[st[i]], enthru[i]);
    double worst = reference;
    for (const auto& [stage, work] : per_stage)
        if (std::abs(work - reference) > std::abs(worst - reference)) worst = work;
    // The ledger: the pile can hold no more than the hammer and its weight put in since the
    // blow began (the soil gives back at most what it took), whatever it does after the
    // pulse; a pile fed by the time stepping rings up past it (it did, before the contact
    // followed the pile's substeps). The weight's work: a 10.1 MN monopile setting 6 mm adds
    // 4 % to a blow's 1.5 MJ.
    const auto& pile_energy = column(history, "pile_energy_J");
    const auto& weight = column(history, "pile_weight_work_J");
    std::map<double, double> weight_at_start;  // the blow's stage, its weight work the row before
    double most = 0.0, of = 1.0;
    for (std::size_t i = 0; i < st.size(); ++i) {
        if (!per_stage.count(st[i])) continue;
        if (!weight_at_start.count(st[i])) weight_at_start[st[i]] = weight[i > 0 ? i - 1 : i];
        const double in = per_stage[st[i]] + weight[i] - weight_at_start[st[i]];
        if (pile_energy[i] / in > most / of) most = pile_energy[i], of = in;
    }
    // 1 % for the head plate's share of the strain energy that f_int, a substep old, misses.
    VerificationCheck ledger = make_check("blow_energy_not_in_pile_least", 1.0 - most / of, -0.01, 0.0, false,
                                          "1 - the pile's largest strain + kinetic energy in a blow over its ENTHRU and its "
                                          "weight's work since the blow began: "
                                          "at least -1 %");
    ledger.at_least = true;
    ledger.passed = std::isfinite(ledger.computed) && ledger.computed >= ledger.reference;
    return {make_check("hammer_energy_worst_blow_J", per_stage.empty() ? 0.0 : worst, reference, tolerance, true,
                       "every half-sine blow of a drive on a pile head without reflections: F0^2 t_i / (2 Z)"),
            ledger,
            make_check("blows_struck", static_cast<double>(per_stage.size()), blows, 0.0, false,
                       "the drive's blows, each with its ENTHRU")};
}

// What a long run must conserve, over its whole history: the points' mass (none made or
// lost) and the grains' volume sum (1 - n) V (each step's porosity update keeps every point's,
// whatever its volume does), each to round-off of its first row: 1e-12 and 1e-10 relative
// (`mass_tolerance`, `grain_volume_tolerance`). The pore water's volume n V changes by the
// water the soil draws in or sends out: reported against its start, not judged.
std::vector<VerificationCheck> conservation(const MpmCheckContext& c, const Table& history) {
    const auto& mass = column(history, "soil_mass_kg");
    const auto& volume = column(history, "soil_volume_m3");
    const auto& water = column(history, "pore_water_volume_m3");
    if (mass.empty()) throw std::invalid_argument("conservation: the run recorded no history");
    auto tolerance = [&](const char* key, double otherwise) {
        return c.parameters.count(key) ? c.parameters.at(key) : otherwise;
    };
    double worst_mass = 0.0, worst_grains = 0.0;
    const double grains0 = volume.front() - water.front();
    for (std::size_t i = 0; i < mass.size(); ++i) {
        worst_mass = std::max(worst_mass, std::abs(mass[i] / mass.front() - 1.0));
        worst_grains = std::max(worst_grains, std::abs((volume[i] - water[i]) / grains0 - 1.0));
    }
    return {make_check("soil_mass_largest_change", worst_mass, 0.0, tolerance("mass_tolerance", 1e-12), false,
                       "largest |m / m_0 - 1| of the points' mass over the run"),
            make_check("grain_volume_largest_change", worst_grains, 0.0, tolerance("grain_volume_tolerance", 1e-10),
                       false, "largest |V_s / V_s0 - 1| of the grains' volume sum (1 - n) V over the run"),
            make_report("pore_water_volume_m3", water.back(), water.front(),
                        "the pore water's volume sum n V at the end against the start (per radian in axisymmetry)")};
}

// The penalty contact's largest penetration over the run, as a fraction of the cell
// (`max_penetration_over_cell`, the deepest pair each step), against issue 13's bound of 1 %
// (`penetration_tolerance`): the contact's stiffness rule (README, Penalty rule) must hold
// it for the stresses the case reaches.
VerificationCheck contact_penetration(const MpmCheckContext& c, const Table& history) {
    const auto& penetration = column(history, "max_penetration_over_cell");
    double worst = 0.0;
    for (double g : penetration)
        if (g > worst) worst = g;  // NaN rows (before a resume across builds) are skipped
    const double bound = c.parameters.count("penetration_tolerance") ? c.parameters.at("penetration_tolerance") : 0.01;
    return make_check("contact_largest_penetration_over_cell", worst, 0.0, bound, false,
                      "the deepest any material point reached into the pile over the run, over the cell");
}

// A rigid ram (mass m, striking at v0, no cushion) on the head of a pile of impedance Z that
// sends no wave back before T: m dv/dt = m g - Z v, so v = a + (v0 - a) e^{-t / tau} with
// a = m g / Z, tau = m / Z, and the ram has put Z int_0^T v^2 dt through the head by T:
// a^2 T + 2 a b tau (1 - e^{-T/tau}) + b^2 tau / 2 (1 - e^{-2T/tau}) times Z, b = v0 - a.
// The blow's ENTHRU at T (linear between the rows around it) against it; the head plate's
// mass takes its share of the impact (m_head / m of the energy), so it converges with the
// pile's elements.
VerificationCheck ram_energy(const MpmCheckContext& c, const Table& history) {
    const char* check = "ram_energy_into_pile";
    const double m = parameter(c, "ram_mass", check), v0 = parameter(c, "impact_velocity", check);
    const double z = parameter(c, "pile_impedance", check), stage = parameter(c, "blow_stage", check);
    const double at = parameter(c, "at_time", check);
    const double a = m * c.gravity / z, b = v0 - a, tau = m / z;
    const double reference = z * (a * a * at + 2.0 * a * b * tau * (1.0 - std::exp(-at / tau)) +
                                  0.5 * b * b * tau * (1.0 - std::exp(-2.0 * at / tau)));
    const auto& st = column(history, "stage");
    const auto& t = column(history, "time_s");
    const auto& enthru = column(history, "enthru_J");
    // The stage began a step before its first row (a quasi-static stage before it leaves its
    // pseudo-time in its own last row): the rows from there, ENTHRU 0 at the start.
    std::vector<double> time{0.0}, work_at{0.0};
    for (std::size_t i = 0; i < st.size(); ++i)
        if (st[i] == stage) time.push_back(t[i]), work_at.push_back(enthru[i]);
    if (time.size() > 2) time[0] = 2.0 * time[1] - time[2];
    double work = 0.0;
    bool found = false;
    for (std::size_t i = 1; i < time.size() && !found; ++i)
        if (time[i] - time[0] >= at) {
            const double w = (at - (time[i - 1] - time[0])) / (time[i] - time[i - 1]);
            work = work_at[i - 1] * (1.0 - w) + work_at[i] * w;
            found = true;
        }
    if (!found) throw std::invalid_argument("ram_energy_into_pile: the blow's stage ends before at_time");
    return make_check("ram_energy_into_pile_J", work, reference, 0.01, true,
                      "rigid ram on a pile head without reflections: Z int v^2 dt, m dv/dt = m g - Z v");
}

// An elastic layer loaded by gravity from zero stress between rollers has no lateral
// strain: sigma_h = nu / (1 - nu) sigma_v in every horizontal direction (the hoop stress
// too in axisymmetry). Points above a tenth of the largest sigma_v are left out: their
// ratio is one of two small numbers.
template <int D>
VerificationCheck lateral_stress_ratio(const MpmCheckContext& c, const MpmModel<D>& m) {
    if (c.model != "linear_elastic")
        throw std::invalid_argument("lateral_stress_ratio is the closed form of a linear_elastic layer");
    const double reference = c.poisson_ratio / (1.0 - c.poisson_ratio);
    const auto& p = m.particles;
    const int vertical = D == 2 ? 1 : 2;
    double deepest = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) deepest = std::min(deepest, p.stress[6 * i + vertical]);
    std::vector<int> horizontal = {0};
    if (D == 3) horizontal.push_back(1);
    if (D == 2 && m.axisymmetric) horizontal.push_back(2);
    double worst = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double sv = p.stress[6 * i + vertical];
        if (sv > 0.1 * deepest) continue;
        for (int h : horizontal) worst = std::max(worst, std::abs(p.stress[6 * i + h] / sv - reference));
    }
    auto check = make_check("lateral_over_vertical_stress_max_deviation", worst, 0.0, 1e-3, false,
                            "|sigma_h / sigma_v - nu / (1 - nu)| of an elastic layer loaded by gravity between rollers");
    check.note += " (nu / (1 - nu) = " + std::to_string(reference) + ")";
    return check;
}

// A nil step on a state in equilibrium (a K0 state of horizontal layers) moves nothing: the
// largest displacement of any point, in cell sizes.
template <int D>
VerificationCheck nil_step_displacement(const MpmModel<D>& m, const std::vector<double>& x0) {
    double h = m.grid.spacing[0];
    for (int d = 1; d < D; ++d) h = std::min(h, m.grid.spacing[d]);
    double worst = 0.0;
    for (std::size_t k = 0; k < x0.size(); ++k) worst = std::max(worst, std::abs(m.particles.x[k] - x0[k]));
    return make_check("nil_step_max_displacement_over_cell", worst / h, 0.0, 1e-3, false,
                      "largest |x - x0| after the nil step over the cell size: an equilibrium state stays put");
}

// RMS of (sigma_v - rho g z) / (rho g H) over the points of a column under its weight
// (z from the surface in the original configuration), against an absolute bound
// (verification.noise_bound).
template <int D>
VerificationCheck stress_noise(const MpmCheckContext& c, const MpmModel<D>& m, const std::vector<double>& x0) {
    const double surface = parameter(c, "surface", "stress_noise");
    const double bound = parameter(c, "noise_bound", "stress_noise");
    const auto& p = m.particles;
    double sum = 0.0, base = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
        base = std::max(base, c.gravity * (surface - x0[D * i + D - 1]) * p.mass[i] / p.volume0[i]);
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double exact = -c.gravity * (surface - x0[D * i + D - 1]) * p.mass[i] / p.volume0[i];
        const double e = (p.stress[6 * i + (D == 2 ? 1 : 2)] - exact) / base;
        sum += e * e;
    }
    return make_check("vertical_stress_rms_error_relative", std::sqrt(sum / static_cast<double>(p.size())), 0.0,
                      bound, false, "RMS of (sigma_v - rho g z) / (rho g H) over the points, against an absolute bound");
}

// The run-out at the deposit's front and, with verification.front_thickness (m, 2D), where
// the deposit first thins below that thickness; both against the same law.
template <int D>
std::vector<VerificationCheck> runout(const MpmCheckContext& c, const MpmModel<D>& m) {
    const double width = parameter(c, "initial_width", "granular_runout");
    const double height = parameter(c, "height", "granular_runout");
    const bool axi = D == 2 && m.axisymmetric;
    const double a = height / width;
    const std::string law = std::string("Lube et al. (") + (axi ? "2004" : "2005") + ") at a = H / L_0";
    std::vector<VerificationCheck> out;
    if constexpr (D == 2) {
        // The body of the deposit converges with the grid: its final height is judged.
        const auto profile = deposit_profile(m);
        out.push_back(make_check("normalised_final_height", deposit_height(profile) / width,
                                 lube_final_height(a, axi), 0.10, true,
                                 "H_inf / L_0, the deposit's highest thickness, against " + law));
        // The run-out is not a continuum quantity at the very front (a toe a few grains
        // thick): reported, read at the front and at a tenth of the initial height.
        const double t = c.parameters.count("front_thickness") ? c.parameters.at("front_thickness") : 0.1 * height;
        const double front = thickness_front(m, profile, t);
        out.push_back(make_report("normalised_runout_at_thickness", (front - m.grid.origin[0] - width) / width,
                                  lube_runout(a, axi),
                                  "(L_f - L_0) / L_0 where the deposit first thins below " + std::to_string(t) +
                                      " m, beside " + law + " (read at the very front)"));
    } else {
        throw std::invalid_argument("granular_runout reads a 2D deposit profile");
    }
    out.push_back(make_report("normalised_runout", (deposit_front<D>(m) - m.grid.origin[0] - width) / width,
                              lube_runout(a, axi), "(L_f - L_0) / L_0 at the deposit's front, beside " + law));
    return out;
}

template <int D>
std::vector<VerificationCheck> run_mpm_verification(const MpmCheckContext& c, const MpmModel<D>& m,
                                                    const std::vector<double>& x0, const Table& history) {
    std::vector<VerificationCheck> out;
    for (const auto& name : c.checks) {
        if (name == "self_weight_stress") out.push_back(self_weight<D>(c, m, x0));
        else if (name == "lame_cylinder") {
            if constexpr (D == 2) {
                auto v = lame(c, m, x0);
                out.insert(out.end(), v.begin(), v.end());
            } else {
                throw std::invalid_argument("lame_cylinder is an axisymmetric check");
            }
        } else if (name == "wave_arrival") out.push_back(wave_arrival<D>(c, m, history, false));
        else if (name == "shear_wave_arrival") out.push_back(wave_arrival<D>(c, m, history, true));
        else if (name == "absorbed_energy") {
            auto v = absorbed(c, history);
            out.insert(out.end(), v.begin(), v.end());
        }
        else if (name == "stress_noise") out.push_back(stress_noise<D>(c, m, x0));
        else if (name == "lateral_stress_ratio") out.push_back(lateral_stress_ratio<D>(c, m));
        else if (name == "nil_step_displacement") out.push_back(nil_step_displacement<D>(m, x0));
        else if (name == "footing_collapse") out.push_back(footing(c, history, D));
        else if (name == "rigid_punch") out.push_back(rigid_punch(c, history));
        else if (name == "hammer_energy_into_pile") out.push_back(hammer_energy(c, history));
        else if (name == "ram_energy_into_pile") out.push_back(ram_energy(c, history));
        else if (name == "hammer_energy_every_blow") {
            auto v = hammer_energy_every_blow(c, history);
            out.insert(out.end(), v.begin(), v.end());
        } else if (name == "conservation") {
            auto v = conservation(c, history);
            out.insert(out.end(), v.begin(), v.end());
        } else if (name == "contact_penetration") out.push_back(contact_penetration(c, history));
        else if (name == "granular_runout") {
            auto v = runout<D>(c, m);
            out.insert(out.end(), v.begin(), v.end());
        }
        else if (name == "terzaghi_consolidation") {
            auto v = terzaghi_consolidation<D>(c, m, x0, history);
            out.insert(out.end(), v.begin(), v.end());
        } else if (name == "undrained_wave_speed" || name == "fast_wave_speed") {
            auto v = saturated_wave_arrival<D>(c, m, history, name == "fast_wave_speed");
            out.insert(out.end(), v.begin(), v.end());
        }
        else if (name == "poroelastic_wave_history") {
            auto v = poroelastic_wave_history<D>(c, m, x0, history);
            out.insert(out.end(), v.begin(), v.end());
        }
        else if (name == "hydrostatic_equilibrium") {
            auto v = hydrostatic_equilibrium<D>(c, m, x0);
            out.insert(out.end(), v.begin(), v.end());
        } else if (name == "skempton_b") out.push_back(skempton_b_check<D>(c, m));
        else throw std::invalid_argument("verification check " + name + " is not available yet for MPM cases");
    }
    return out;
}

template std::vector<VerificationCheck> run_mpm_verification<2>(const MpmCheckContext&, const MpmModel<2>&,
                                                                const std::vector<double>&, const Table&);
template std::vector<VerificationCheck> run_mpm_verification<3>(const MpmCheckContext&, const MpmModel<3>&,
                                                                const std::vector<double>&, const Table&);

}  // namespace pilempm::mpm
