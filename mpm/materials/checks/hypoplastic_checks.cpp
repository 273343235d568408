// Hypoplasticity (von Wolffersdorff 1996): the closed forms its construction guarantees
// (issue 5, verification 1). Pressures in the laws are shifted by p_t, as in the model.
#include <algorithm>
#include <cmath>
#include <string>

#include "mpm/materials/checks/element_test_checks.hpp"

namespace pilempm::mpm {


namespace {

// Bauer's law: e_x(p) = e_x0 exp(-(3 p / h_s)^n) for x = i, c, d.
double bauer(const MaterialParameters& m, double e0, double p) {
    return e0 * std::exp(-std::pow(3.0 * (p + m.hypo.p_t) / m.hypo.h_s, m.hypo.n));
}

}  // namespace

// Monotonic drained shearing ends at the critical state: e = e_c(p') and, on the
// Matsuoka-Nakai surface of phi_c, |q| / (p' + p_t) = 6 sin phi_c / (3 -+ sin phi_c).
std::vector<VerificationCheck> critical_void_ratio(const ElementTestContext& ctx) {
    const std::string check = "critical_void_ratio";
    ctx.require_model("hypoplastic", check);
    ctx.first_of("triaxial_drained", check);
    const auto& m = ctx.c.material;
    const int ie = ctx.state_index("void_ratio", check);
    const double s = std::sin(m.friction_angle * M_PI / 180.0);
    std::vector<VerificationCheck> out;
    for (const auto& r : ctx.results) {
        if (r.input->type != "triaxial_drained") continue;
        const auto& end = r.path.back();
        const bool compression = end.axial_strain > 0.0;
        const double M = 6.0 * s / (compression ? 3.0 - s : 3.0 + s);
        const std::string name = r.input->name;
        out.push_back(make_check(name + "_final_void_ratio", end.state[ie], bauer(m, m.hypo.e_c0, end.p), 0.01, true,
                                 "e = e_c(p') = e_c0 exp(-(3 p'/h_s)^n) at critical state"));
        out.push_back(make_check(name + "_final_stress_ratio", std::abs(end.q) / (end.p + m.hypo.p_t), M, 0.01, true,
                                 compression ? "q / (p' + p_t) = 6 sin phi_c / (3 - sin phi_c)"
                                             : "|q| / (p' + p_t) = 6 sin phi_c / (3 + sin phi_c)"));
    }
    return out;
}

// Isotropic compression from the loosest state stays on e_i(p') = e_i0 exp(-(3 p'/h_s)^n):
// f_b is built so that Bauer's law solves it.
std::vector<VerificationCheck> isotropic_compression_line(const ElementTestContext& ctx) {
    const std::string check = "isotropic_compression_line";
    ctx.require_model("hypoplastic", check);
    const auto& r = ctx.first_of("isotropic", check);
    const auto& m = ctx.c.material;
    const int ie = ctx.state_index("void_ratio", check);
    double worst = 0.0, p_prev = 0.0;
    for (const auto& rec : r.path) {
        if (rec.p < p_prev) break;  // the first (loading) leg only
        p_prev = rec.p;
        const double ei = bauer(m, m.hypo.e_i0, rec.p);
        worst = std::max(worst, std::abs(rec.state[ie] - ei) / ei);
    }
    return {make_check("isotropic_max_void_ratio_error_relative", worst, 0.0, 0.01, false,
                       "max |e - e_i(p')| / e_i(p') along isotropic loading from e_i(p'_0)")};
}

}  // namespace pilempm::mpm
