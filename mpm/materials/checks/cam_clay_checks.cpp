// Modified Cam clay: the drained and undrained triaxial paths against the closed-form
// critical-state solutions (issue 5, verification 3).
#include <algorithm>
#include <cmath>

#include "mpm/materials/checks/element_test_checks.hpp"

namespace pilempm::mpm {


// The swelling line through the initial state meets the NCL at p_c0: e_N = e0 + lambda ln p_c0
// - kappa ln(p_c0 / p0); the CSL lies (lambda - kappa) ln 2 below the NCL.
std::vector<VerificationCheck> critical_state_drained(const ElementTestContext& ctx) {
    ctx.require_model("modified_cam_clay", "critical_state_drained");
    const auto& c = ctx.c;
    const auto& r = ctx.first_of("triaxial_drained", "critical_state_drained");
    const auto& state0 = ctx.state0;
    const double p0 = ctx.p0;
    const auto& m = c.material;
    const auto& end = r.path.back();
    const double M = m.critical_state_ratio, sr = c.lateral_stress;
    const double pf = 3.0 * sr / (3.0 - M);
    const double eN = state0[1] + m.lambda * std::log(state0[0]) - m.kappa * std::log(state0[0] / p0);
    const double e_cs = eN - (m.lambda - m.kappa) * std::log(2.0) - m.lambda * std::log(end.p);
    return {make_check("drained_final_stress_ratio", end.q / end.p, M, 0.01, true, "q / p' = M at critical state"),
            make_check("drained_final_mean_stress_Pa", end.p, pf, 0.01, true, "p' = 3 sigma'_r / (3 - M)"),
            make_check("drained_final_void_ratio", end.state[1], e_cs, 0.01, true,
                       "e on the CSL: e_N - (lambda - kappa) ln 2 - lambda ln p'")};
}

// At constant volume p_c = p_c0 (p0 / p')^(kappa / (lambda - kappa)), and the path lies on
// the yield surface q^2 = M^2 p' (p_c - p'); it ends at p_c / 2.
std::vector<VerificationCheck> undrained_path(const ElementTestContext& ctx) {
    ctx.require_model("modified_cam_clay", "undrained_path");
    const auto& c = ctx.c;
    const auto& r = ctx.first_of("triaxial_undrained", "undrained_path");
    const auto& state0 = ctx.state0;
    const double p0 = ctx.p0;
    const auto& m = c.material;
    const double M = m.critical_state_ratio, e = m.kappa / (m.lambda - m.kappa);
    // End point: p_c0 (p0 / p)^e = 2 p  ->  p = (p_c0 p0^e / 2)^(1 / (1 + e)).
    const double pf = std::pow(state0[0] * std::pow(p0, e) / 2.0, 1.0 / (1.0 + e));
    double worst = 0.0;
    bool yielded = false;
    for (const auto& rec : r.path) {
        const double pc = state0[0] * std::pow(p0 / rec.p, e);
        if (rec.state[0] > state0[0] * (1.0 + 1e-9)) yielded = true;
        if (yielded) worst = std::max(worst, std::abs(rec.q - M * std::sqrt(std::max(0.0, rec.p * (pc - rec.p)))));
    }
    const auto& end = r.path.back();
    return {make_check("undrained_final_mean_stress_Pa", end.p, pf, 0.01, true, "p' = p_c / 2 at constant volume"),
            make_check("undrained_final_deviator_Pa", end.q, M * pf, 0.01, true, "q = M p'"),
            make_check("undrained_path_max_deviator_error_relative", worst / (M * pf), 0.0, 0.01, false,
                       "max |q - M sqrt(p' (p_c - p'))| / q_f along the yielding path")};
}

}  // namespace pilempm::mpm
