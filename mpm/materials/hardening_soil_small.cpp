#include "mpm/materials/hardening_soil_small.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "core/symmetric_eigen.hpp"
#include "mpm/materials/power_near.hpp"
#include "mpm/materials/substepping.hpp"

namespace pilempm::mpm {

namespace {

constexpr double kA = 0.385;  // Benz's G_s / G0 = 1 / (1 + a gamma / gamma_0.7), a = 0.385
constexpr double kCorner = 0.05;  // width of the corner blend, x (s1 - s3)

// Contraction of two symmetric tensors stored as [xx yy zz xy yz zx] with tensor shear.
double ddot(const double* a, const double* b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + 2.0 * (a[3] * b[3] + a[4] * b[4] + a[5] * b[5]);
}

double tnorm(const double* a) { return std::sqrt(ddot(a, a)); }

// Frobenius norm of the product a b of two symmetric tensors [xx yy zz xy yz zx].
double product_norm(const double* a, const double* b) {
    const double A[3][3] = {{a[0], a[3], a[5]}, {a[3], a[1], a[4]}, {a[5], a[4], a[2]}};
    const double B[3][3] = {{b[0], b[3], b[5]}, {b[3], b[1], b[4]}, {b[5], b[4], b[2]}};
    double sum = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const double c = A[i][0] * B[0][j] + A[i][1] * B[1][j] + A[i][2] * B[2][j];
            sum += c * c;
        }
    return std::sqrt(sum);
}

// Isotropic elastic tangent on a tensor-shear strain: ds = lam tr(de) I + 2 G de.
void apply_elastic(double lam, double G, const double* de, double* ds) {
    const double tr = lam * (de[0] + de[1] + de[2]);
    for (int i = 0; i < 3; ++i) ds[i] = tr + 2.0 * G * de[i];
    for (int i = 3; i < 6; ++i) ds[i] = 2.0 * G * de[i];
}

// The least eigenvalue of a plane tensor (yz = zx = 0): the out-of-plane normal entry or
// the least of the in-plane pair, in closed form.
double plane_minor_principal(const double* t) {
    const core::PlanePrincipalPair p = core::plane_principal_pair(t);
    return std::min(t[2], p.mean - p.radius);
}

}  // namespace

// Principal stresses (compression positive) s[0] >= s[1] >= s[2] and unit eigenvectors.
struct HardeningSoilSmall::Principal {
    double s[3];
    double v[3][3];
    double s3m;  // the minor principal stress the stiffness follows (the least normal stress if t is diagonal)
    double wm;   // w^m at s3m
    // sum_i c_i v_i v_i^T as [xx yy zz xy yz zx]. Near a corner (triaxial compression
    // s2 = s3, extension s1 = s2) the coefficients of the two close principal stresses are
    // blended towards their mean, fully at the corner (Koiter's rule with equal
    // multipliers, independent of the arbitrary eigenvectors there), linearly over a band
    // of kCorner (s1 - s3): a gradient continuous across the corner lets the substepping
    // follow a return onto the edge instead of chattering between its two sides.
    void assemble(double c0, double c1, double c2, double* out) const {
        double c[3] = {c0, c1, c2};
        const double span = s[0] - s[2];
        if (!(span > 1e-12 * (std::abs(s[0]) + std::abs(s[2])))) {
            c[0] = c[1] = c[2] = (c0 + c1 + c2) / 3.0;
        } else {
            const double wc = 0.5 * std::max(0.0, 1.0 - (s[1] - s[2]) / (kCorner * span));
            const double we = 0.5 * std::max(0.0, 1.0 - (s[0] - s[1]) / (kCorner * span));
            if (wc > 0.0) {
                c[1] = (1.0 - wc) * c1 + wc * c2;
                c[2] = wc * c1 + (1.0 - wc) * c2;
            } else if (we > 0.0) {
                c[0] = (1.0 - we) * c0 + we * c1;
                c[1] = we * c0 + (1.0 - we) * c1;
            }
        }
        for (int k = 0; k < 6; ++k) out[k] = 0.0;
        for (int i = 0; i < 3; ++i) {
            const double* e = v[i];
            out[0] += c[i] * e[0] * e[0];
            out[1] += c[i] * e[1] * e[1];
            out[2] += c[i] * e[2] * e[2];
            out[3] += c[i] * e[0] * e[1];
            out[4] += c[i] * e[1] * e[2];
            out[5] += c[i] * e[2] * e[0];
        }
    }
};

// Yield values and, when asked, what the plastic corrector needs (gradients n, flows m,
// hardening moduli H = -df/dkappa dkappa/dlambda).
struct HardeningSoilSmall::Surfaces {
    bool valid;         // s3 + a clearly positive: the hardening laws are defined
    double fs, fc;      // Pa
    double scale;       // stress scale of the point for tolerances, Pa
    double pstar, R;    // p* and the cap radius, Pa
    double ns[6], ms[6], Hs;
    double nc[6];       // the cap's hardening modulus: cap_modulus (a power, wanted only on the cap)
};

HardeningSoilSmall::HardeningSoilSmall(const HardeningSoilSmallParameters& p)
    : par_(p), failure_(p.Eur_ref > 0 ? p.Eur_ref : 1.0, (p.nu_ur > -1.0 && p.nu_ur < 0.5) ? p.nu_ur : 0.2,
                        (p.phi > 0 && p.phi < 90) ? p.phi : 30.0,
                        (p.psi >= 0 && p.psi <= p.phi && p.phi < 90) ? p.psi : 0.0, p.c >= 0 ? p.c : 0.0,
                        std::numeric_limits<double>::infinity()) {
    auto need = [](bool ok, const char* what) {
        if (!ok) throw std::invalid_argument(std::string("hardening_soil_small: ") + what);
    };
    need(p.E50_ref > 0 && p.Eoed_ref > 0 && p.Eur_ref > 0 && p.G0_ref > 0, "E50_ref, Eoed_ref, Eur_ref, G0_ref > 0");
    need(p.nu_ur > -1.0 && p.nu_ur < 0.5, "-1 < nu_ur < 0.5");
    need(p.gamma_07 > 0, "gamma_0.7 > 0");
    need(p.m >= 0 && p.m <= 1, "0 <= m <= 1");
    need(p.p_ref > 0 && p.p_min > 0 && p.tolerance > 0, "p_ref, p_min, tolerance > 0");
    need(p.phi > 0 && p.phi < 90, "0 < phi < 90 deg");
    need(p.psi >= 0 && p.psi <= p.phi, "0 <= psi <= phi");
    need(p.c >= 0 && std::isfinite(p.c), "finite cohesion >= 0");
    need(p.R_f > 0 && p.R_f < 1, "0 < R_f < 1");
    need(p.ocr >= 1, "OCR >= 1");
    const double Gur = p.Eur_ref / (2.0 * (1.0 + p.nu_ur));
    need(p.G0_ref >= Gur, "G0_ref >= G_ur = Eur_ref / (2 (1 + nu_ur))");
    // The hyperbola needs the plastic part of its initial slope to be positive.
    need(p.Eur_ref > 2.0 * p.E50_ref / (2.0 - p.R_f), "Eur_ref > E_i = 2 E50_ref / (2 - R_f)");

    const double to_rad = std::numbers::pi / 180.0;
    sin_phi_ = std::sin(p.phi * to_rad);
    sin_psi_ = std::sin(p.psi * to_rad);
    sin_cv_ = (sin_phi_ - sin_psi_) / (1.0 - sin_phi_ * sin_psi_);
    a_ = p.c / std::tan(p.phi * to_rad);
    kf_ = 2.0 * sin_phi_ / (1.0 - sin_phi_);
    delta_ = (3.0 + sin_phi_) / (3.0 - sin_phi_);
    K0nc_ = p.K0_nc > 0 ? p.K0_nc : 1.0 - sin_phi_;
    need(K0nc_ < 1.0 && K0nc_ > (1.0 - sin_phi_) / (1.0 + sin_phi_),
         "K0_nc between (1 - sin phi) / (1 + sin phi) (Mohr-Coulomb) and 1");
    pref_s_ = p.p_ref + a_;
    Gur_over_G0_ = Gur / p.G0_ref;
    gamma_c_ = p.gamma_07 / kA * (std::sqrt(1.0 / Gur_over_G0_) - 1.0);
    lam_over_G_ = 2.0 * p.nu_ur / (1.0 - 2.0 * p.nu_ur);

    // Cap parameters in closed form from a K0nc oedometer at s1* = p_ref* (shifted
    // stresses, s3* = K0nc s1*): with the shear surface and the cap both loading,
    //   lateral  x (P - A) + b_lat g = -L,   axial  x (2A + P) + b_1 g = 1/Eoed - (1 - 2 nu K)/Eur
    // where x = d lambda_cap / d s1 (squared cap), A = qt / alpha^2, P = 2 p*/3, g = d gamma_p / d s1
    // (the shear surface follows the radial path), L the elastic lateral compliance.
    const double K = K0nc_, nu = p.nu_ur, S = pref_s_;
    const double qt = S * (1.0 - K), pstar = S * (1.0 + 2.0 * K) / 3.0, P = 2.0 * pstar / 3.0;
    const double Eur0 = p.Eur_ref * stiffness_factor(K * S - a_);
    const double L = (K - nu * (1.0 + K)) / Eur0;
    const double R0 = 1.0 / p.Eoed_ref - (1.0 - 2.0 * nu * K) / Eur0;
    double dq_dg = 0.0, dq_ds = 0.0;
    bool on_mc = false;
    const double gp0 = gamma_of(qt, K * S);
    qy(gp0, K * S, std::pow(std::max(K * S, p.p_min) / pref_s_, p.m), dq_dg, dq_ds, on_mc);
    need(!on_mc, "the K0nc state lies on the Mohr-Coulomb surface");
    const double g = ((1.0 - K) - K * dq_ds) / dq_dg;
    const double sphm = qt / (S * (1.0 + K));  // mobilised sin phi at the K0nc state
    double spsi = 0.0;
    if (sphm >= 0.75 * sin_phi_) spsi = std::clamp((sphm - sin_cv_) / (1.0 - sphm * sin_cv_), 0.0, sin_psi_);
    const double b1 = 0.5 * (1.0 - spsi), blat = -0.25 * (1.0 + spsi);
    const double Rp = R0 - b1 * g, Lp = L + blat * g;
    const double x = (Rp - 2.0 * Lp) / (3.0 * P);
    need(x > 0.0, "Eoed_ref too large for Eur_ref, E50_ref and K0_nc (no room for cap compression)");
    const double A = P + Lp / x;
    need(A > 0.0, "K0_nc and Eoed_ref give no cap shape (alpha); lower Eoed_ref or raise K0_nc");
    alpha_ = std::sqrt(qt / A);
    const double C = std::sqrt(qt * qt / (alpha_ * alpha_) + pstar * pstar) / S;
    beta_ = 2.0 * pstar * x * S * std::pow(C, p.m - 1.0);
}

const char* HardeningSoilSmall::state_name(int k) const {
    static const char* names[] = {"strain_history_xx", "strain_history_yy", "strain_history_zz",
                                  "strain_history_xy", "strain_history_yz", "strain_history_zx",
                                  "plastic_shear_strain", "cap_pressure_Pa", "shear_modulus_ratio"};
    return k >= 0 && k < 9 ? names[k] : "";
}

double HardeningSoilSmall::stiffness_factor(double s3) const {
    return std::pow(std::max(s3 + a_, par_.p_min) / pref_s_, par_.m);
}

double HardeningSoilSmall::stiffness_factor(double s3, const Principal& near) const {
    const double x = std::max(s3 + a_, par_.p_min) / pref_s_, x0 = std::max(near.s3m + a_, par_.p_min) / pref_s_;
    return power_near(x, x0, near.wm, par_.m);
}

// Principal stresses in descending order, from the Jacobi decomposition (core::symmetric_eigen3).
HardeningSoilSmall::Principal HardeningSoilSmall::principal(const double* t, const Principal* hint) const {
    Principal pr;
    double d[3], q[3][3];  // q[i]: the basis vector i (Cartesian components)
    core::symmetric_eigen3(t, hint ? hint->v : nullptr, d, q);
    // Descending order.
    int o[3] = {0, 1, 2};
    if (d[o[0]] < d[o[1]]) std::swap(o[0], o[1]);
    if (d[o[1]] < d[o[2]]) std::swap(o[1], o[2]);
    if (d[o[0]] < d[o[1]]) std::swap(o[0], o[1]);
    for (int i = 0; i < 3; ++i) {
        pr.s[i] = d[o[i]];
        for (int j = 0; j < 3; ++j) pr.v[i][j] = q[o[i]][j];
    }
    pr.s3m = pr.s[2];
    pr.wm = hint ? stiffness_factor(pr.s3m, *hint) : stiffness_factor(pr.s3m);
    return pr;
}

// The least principal stress alone: plane_minor_principal for a plane tensor, else the
// decomposition (near: a nearby one, as its frame).
double HardeningSoilSmall::minor_principal(const double* t, const Principal& near) const {
    return t[4] == 0.0 && t[5] == 0.0 ? plane_minor_principal(t) : principal(t, &near).s[2];
}

double HardeningSoilSmall::secant_stress_ratio(double g) const {
    if (g <= gamma_c_) return g / (1.0 + kA * g / par_.gamma_07);
    return gamma_c_ / (1.0 + kA * gamma_c_ / par_.gamma_07) + Gur_over_G0_ * (g - gamma_c_);
}

// The deviatoric part of the strain increment joins the history H after the principal
// directions in which it reverses the history are wiped (Benz 2007, after Simpson's brick
// model). Returns the secant G / G0 over the increment: the exact integral of the tangent
// along a monotonic path, so the secant curve does not depend on the step size.
double HardeningSoilSmall::history_ratio(double* H, const double* d, double& tangent_ratio) const {
    auto tangent = [this](double g) {
        const double r = par_.gamma_07 / (par_.gamma_07 + kA * g);
        return std::max(r * r, Gur_over_G0_);
    };
    const double mean = (d[0] + d[1] + d[2]) / 3.0;
    const double e[6] = {d[0] - mean, d[1] - mean, d[2] - mean, 0.5 * d[3], 0.5 * d[4], 0.5 * d[5]};
    const double ne = tnorm(e);
    if (!(ne > 1e-18)) {
        tangent_ratio = tangent(std::sqrt(1.5) * tnorm(H));
        return tangent_ratio;
    }
    double ev[3], v[3][3];
    core::symmetric_eigen3(e, nullptr, ev, v);
    const double dmax = std::max({std::abs(ev[0]), std::abs(ev[1]), std::abs(ev[2])});
    double Hm[6];
    for (int k = 0; k < 6; ++k) Hm[k] = H[k];
    for (int i = 0; i < 3; ++i) {
        if (std::abs(ev[i]) <= 1e-3 * dmax) continue;
        const double* u = v[i];
        const double h = Hm[0] * u[0] * u[0] + Hm[1] * u[1] * u[1] + Hm[2] * u[2] * u[2] +
                         2.0 * (Hm[3] * u[0] * u[1] + Hm[4] * u[1] * u[2] + Hm[5] * u[2] * u[0]);
        if (h * ev[i] < 0.0) {  // reversal in this direction
            Hm[0] -= h * u[0] * u[0];
            Hm[1] -= h * u[1] * u[1];
            Hm[2] -= h * u[2] * u[2];
            Hm[3] -= h * u[0] * u[1];
            Hm[4] -= h * u[1] * u[2];
            Hm[5] -= h * u[2] * u[0];
        }
    }
    const double ga = std::sqrt(3.0) * product_norm(Hm, e) / ne;
    for (int k = 0; k < 6; ++k) Hm[k] += e[k];
    const double gb = std::sqrt(3.0) * product_norm(Hm, e) / ne;
    for (int k = 0; k < 6; ++k) H[k] = Hm[k];
    tangent_ratio = tangent(gb);
    if (std::abs(gb - ga) <= 1e-9 * par_.gamma_07) return tangent(std::max(ga, gb));
    return (secant_stress_ratio(gb) - secant_stress_ratio(ga)) / (gb - ga);
}

// The hyperbola's yield deviator q_y at (gamma_p, s = s3 + a), capped at q_f, with its
// derivatives (implicit differentiation of A q q_a / (q_a - q) - B q = gamma_p).
double HardeningSoilSmall::qy(double gp, double s, double wm, double& dq_dg, double& dq_ds, bool& on_mc,
                              bool derivatives) const {
    const double qf = kf_ * s;
    if (s <= 0.0) {
        on_mc = true;
        dq_dg = 0.0;
        dq_ds = kf_;
        return std::max(qf, 0.0);
    }
    const bool floored = s < par_.p_min;
    const double A = (2.0 - par_.R_f) / (par_.E50_ref * wm), B = 2.0 / (par_.Eur_ref * wm);
    const double qa = qf / par_.R_f;
    const double g = std::max(gp, 0.0);
    const double b = (A - B) * qa + g;
    const double qh = g > 0.0 ? 2.0 * g * qa / (b + std::sqrt(b * b + 4.0 * B * g * qa)) : 0.0;
    if (qh >= qf) {
        on_mc = true;
        dq_dg = 0.0;
        dq_ds = kf_;
        return qf;
    }
    on_mc = false;
    if (!derivatives) return qh;
    const double r = qa - qh;
    const double Gq = A * qa * qa / (r * r) - B;
    const double dA = floored ? 0.0 : -par_.m * A / s, dB = floored ? 0.0 : -par_.m * B / s;
    const double Gs = dA * qh * qa / r - A * qh * qh / (r * r) * (kf_ / par_.R_f) - dB * qh;
    dq_dg = 1.0 / Gq;
    dq_ds = -Gs / Gq;
    return qh;
}

double HardeningSoilSmall::gamma_of(double q, double s) const {
    if (!(s > 0.0) || !(q > 0.0)) return 0.0;
    const double wm = std::pow(std::max(s, par_.p_min) / pref_s_, par_.m);
    const double A = (2.0 - par_.R_f) / (par_.E50_ref * wm), B = 2.0 / (par_.Eur_ref * wm);
    const double qf = kf_ * s, qa = qf / par_.R_f, qq = std::min(q, qf);
    return A * qq / (1.0 - qq / qa) - B * qq;
}

double HardeningSoilSmall::cap_radius(const Principal& pr) const {
    const double pstar = (pr.s[0] + pr.s[1] + pr.s[2]) / 3.0 + a_;
    const double qt = pr.s[0] + (delta_ - 1.0) * pr.s[1] - delta_ * pr.s[2];
    return std::sqrt(qt * qt / (alpha_ * alpha_) + pstar * pstar);
}

HardeningSoilSmall::Surfaces HardeningSoilSmall::surfaces(const Point& pt, const Principal& pr, bool grads) const {
    Surfaces S;
    const double s = pr.s[2] + a_, q = pr.s[0] - pr.s[2];
    S.valid = s > 0.01 * par_.p_min;
    S.scale = std::max(pr.s[0] + a_, par_.p_min);
    double dq_dg = 0.0, dq_ds = 0.0;
    bool on_mc = false;
    const double wm = pr.s3m == pr.s[2] ? pr.wm : stiffness_factor(pr.s[2]);
    S.fs = q - qy(pt.gp, s, wm, dq_dg, dq_ds, on_mc, grads);
    const double pstar = (pr.s[0] + pr.s[1] + pr.s[2]) / 3.0 + a_;
    const double qt = pr.s[0] + (delta_ - 1.0) * pr.s[1] - delta_ * pr.s[2];
    const double R = std::sqrt(qt * qt / (alpha_ * alpha_) + pstar * pstar);
    S.pstar = pstar;
    S.R = R;
    S.fc = R - pt.pp;
    if (!grads) return S;
    pr.assemble(1.0, 0.0, -1.0 - dq_ds, S.ns);
    // Mobilised dilatancy (Rowe, as in the HS model): none below 3/4 of the friction.
    const double den = pr.s[0] + pr.s[2] + 2.0 * a_;
    const double sphm = den > 0.0 ? std::min(q / den, 1.0) : 1.0;
    double spsi = 0.0;
    if (sphm >= 0.75 * sin_phi_) spsi = std::clamp((sphm - sin_cv_) / (1.0 - sphm * sin_cv_), 0.0, sin_psi_);
    pr.assemble(0.5 * (1.0 - spsi), 0.0, -0.5 * (1.0 + spsi), S.ms);
    S.Hs = dq_dg;
    const double Rs = std::max(R, 1e-12 * pref_s_);
    const double k = qt / (alpha_ * alpha_ * Rs), iso = pstar / (3.0 * Rs);
    pr.assemble(k + iso, k * (delta_ - 1.0) + iso, -k * delta_ + iso, S.nc);
    return S;
}

// d p_p* / d lambda_cap, which is also the cap's hardening modulus (p_p* is the radius).
double HardeningSoilSmall::cap_modulus(const Point& pt, const Surfaces& S) const {
    const double Rs = std::max(S.R, 1e-12 * pref_s_);
    const double pp = std::max(pt.pp, par_.p_min);
    return std::max(S.pstar, 0.0) / Rs * pref_s_ / beta_ * std::pow(pp / pref_s_, par_.m);
}

double HardeningSoilSmall::yield_max(const Point& pt, const Surfaces& S) const {
    return std::max(S.fs / S.scale, S.fc / std::max(pt.pp, par_.p_min));
}

void HardeningSoilSmall::elastic_moduli(const Principal& pr, double ratio, double& lam, double& G) const {
    G = ratio * par_.G0_ref * pr.wm;
    lam = lam_over_G_ * G;
}

// Two-stage (midpoint) hypoelastic step: the stiffness follows s3 within the step.
void HardeningSoilSmall::elastic_step(const Point& in, const Principal& pr_in, const double* de, double ratio,
                                      Point& out) const {
    double lam, G, ds[6];
    elastic_moduli(pr_in, ratio, lam, G);
    apply_elastic(lam, G, de, ds);
    double mid[6];
    for (int i = 0; i < 6; ++i) mid[i] = in.t[i] + 0.5 * ds[i];
    G = ratio * par_.G0_ref * stiffness_factor(minor_principal(mid, pr_in), pr_in);
    lam = lam_over_G_ * G;
    apply_elastic(lam, G, de, ds);
    out = in;
    for (int i = 0; i < 6; ++i) out.t[i] += ds[i];
}

// Elasto-plastic stress increment for the elastic predictor increment Dde: the active set
// of {shear, cap} whose multipliers are all positive (Koiter), none when unloading. False:
// outside the hardening laws' domain (near the apex). S: surfaces(pt, pr, true).
bool HardeningSoilSmall::plastic_rate(const Point& pt, const Principal& pr, const Surfaces& S, const double* Dde,
                                      double ratio, double* ds, double& dgp, double& dpp, int& candidates) const {
    if (!S.valid) return false;
    double lam, G, Dms[6], Dmc[6];
    elastic_moduli(pr, ratio, lam, G);
    apply_elastic(lam, G, S.ms, Dms);
    apply_elastic(lam, G, S.nc, Dmc);
    const double tol = 10.0 * par_.tolerance;
    // The surfaces the stress lies on; given (>= 0), those of the substep's first stage, so
    // that the midpoint stage, a little inside a curved surface, still follows it.
    if (candidates < 0)
        candidates = (S.fs >= -tol * S.scale ? 1 : 0) | (S.fc >= -tol * std::max(pt.pp, par_.p_min) ? 2 : 0);
    const bool on_s = candidates & 1, on_c = candidates & 2;
    const double Hc = on_c ? cap_modulus(pt, S) : 0.0;
    const double bs = ddot(S.ns, Dde), bc = ddot(S.nc, Dde);
    const double Ass = ddot(S.ns, Dms) + S.Hs, Acc = ddot(S.nc, Dmc) + Hc;
    const double Asc = ddot(S.ns, Dmc), Acs = ddot(S.nc, Dms);
    double ls = 0.0, lc = 0.0;
    bool done = false;
    if (on_s && on_c && (bs > 0.0 || bc > 0.0)) {
        const double det = Ass * Acc - Asc * Acs;
        if (det > 0.0) {
            const double x = (bs * Acc - Asc * bc) / det, y = (Ass * bc - Acs * bs) / det;
            if (x >= 0.0 && y >= 0.0) {
                ls = x;
                lc = y;
                done = true;
            }
        }
    }
    if (!done && on_s && bs > 0.0 && (!on_c || bc - bs / Ass * Acs <= 0.0)) {
        ls = bs / Ass;
        done = true;
    }
    if (!done && on_c && bc > 0.0 && (!on_s || bs - bc / Acc * Asc <= 0.0)) {
        lc = bc / Acc;
        done = true;
    }
    if (!done && on_s && bs > 0.0) ls = bs / Ass;  // rounding at a region boundary
    for (int i = 0; i < 6; ++i) ds[i] = Dde[i] - ls * Dms[i] - lc * Dmc[i];
    dgp = ls;
    dpp = lc * Hc;
    return true;
}

// Pulls a stress that drifted outside back onto the surfaces along D m (Potts & Gens 1985).
void HardeningSoilSmall::correct_drift(Point& pt, Principal& pr, double ratio, Surfaces& S, bool& S_current) const {
    const double tol = par_.tolerance;
    S_current = false;
    for (int it = 0; it < 6; ++it) {
        if (it > 0) pr = principal(pt.t, &pr);
        S = surfaces(pt, pr, true);
        S_current = true;
        if (!S.valid) return;
        const bool out_s = S.fs > tol * S.scale, out_c = S.fc > tol * std::max(pt.pp, par_.p_min);
        if (!out_s && !out_c) return;
        double lam, G, Dms[6], Dmc[6];
        elastic_moduli(pr, ratio, lam, G);
        apply_elastic(lam, G, S.ms, Dms);
        apply_elastic(lam, G, S.nc, Dmc);
        double ls = 0.0, lc = 0.0;
        const double Hc = out_c ? cap_modulus(pt, S) : 0.0;
        const double Ass = ddot(S.ns, Dms) + S.Hs, Acc = ddot(S.nc, Dmc) + Hc;
        if (out_s && out_c) {
            const double Asc = ddot(S.ns, Dmc), Acs = ddot(S.nc, Dms), det = Ass * Acc - Asc * Acs;
            if (det > 0.0) {
                ls = (S.fs * Acc - Asc * S.fc) / det;
                lc = (Ass * S.fc - Acs * S.fs) / det;
            }
            if (!(det > 0.0) || ls < 0.0 || lc < 0.0) {
                ls = S.fs / Ass;
                lc = 0.0;
            }
        } else if (out_s) {
            ls = S.fs / Ass;
        } else {
            lc = S.fc / Acc;
        }
        for (int i = 0; i < 6; ++i) pt.t[i] -= ls * Dms[i] + lc * Dmc[i];
        pt.gp = std::max(pt.gp + ls, 0.0);
        pt.pp = std::max(pt.pp + lc * Hc, a_ + par_.p_min);
        S_current = false;
    }
    pr = principal(pt.t, &pr);
}

// Every distinct stress is decomposed once: the decomposition (and the surfaces) of the
// substep's start serve its elastic predictor, both trials of a rejected substep and the
// first stage; the drift check of an accepted substep serves the next one.
bool HardeningSoilSmall::integrate(Point& pt, const double* de, double ratio, Principal& pr) const {
    const double tol = par_.tolerance;
    pr = principal(pt.t);
    // The gradients only once the step is known not to be elastic (most steps are).
    Surfaces S = surfaces(pt, pr, false);
    if (!S.valid) return false;
    bool S_current = false;  // S holds the gradients at pt
    if (yield_max(pt, S) > tol) {  // e.g. a set-up a hair outside
        correct_drift(pt, pr, ratio, S, S_current);
        if (!S_current) S = surfaces(pt, pr, false);
    }
    Point trial;
    elastic_step(pt, pr, de, ratio, trial);
    Principal pr_trial = principal(trial.t, &pr);
    const Surfaces St = surfaces(trial, pr_trial, false);
    if (!St.valid) return false;
    const double f0 = yield_max(pt, S), f1 = yield_max(trial, St);
    // Strictly elastic only: accepting trials up to the tolerance would give a point at the
    // vertex of the shear cone (isotropic, gamma_p = 0) an elastic band of width tol, with a
    // tangent there unlike the one just outside it.
    if (f1 <= 0.0) {
        pt = trial;
        pr = pr_trial;
        return true;
    }
    double alpha = 0.0;  // elastic share of the increment
    if (f0 < -tol) {
        // The elastic share: where the elastic path meets the first surface.
        alpha = pegasus_root(f0, f1, tol, [&](double a) {
            double part[6];
            for (int i = 0; i < 6; ++i) part[i] = a * de[i];
            elastic_step(pt, pr, part, ratio, trial);
            pr_trial = principal(trial.t, &pr);
            return yield_max(trial, surfaces(trial, pr_trial, false));
        }, 50);
        pt = trial;
        pr = pr_trial;
        S_current = false;
    }
    // Plastic part: modified Euler with local error control (Sloan et al. 2001).
    double rest[6];
    for (int i = 0; i < 6; ++i) rest[i] = (1.0 - alpha) * de[i];
    SubstepClock clock(tol, 20000, 1e-10);
    while (clock.unfinished()) {
        if (clock.exhausted()) return false;
        double d[6], ds1[6], ds2[6], dg1, dg2, dp1, dp2, Dde[6];
        for (int i = 0; i < 6; ++i) d[i] = clock.fraction() * rest[i];
        // Both stages share the substep's elastic predictor, so that a substep without
        // plastic flow is exactly the elastic step (no jump where a surface is touched). A
        // first substep over the whole increment from the start has it already: the trial.
        if (!(alpha == 0.0 && clock.first() && clock.fraction() == 1.0)) elastic_step(pt, pr, d, ratio, trial);
        for (int i = 0; i < 6; ++i) Dde[i] = trial.t[i] - pt.t[i];
        if (!S_current) {
            S = surfaces(pt, pr, true);
            S_current = true;
        }
        int candidates = -1;
        if (!plastic_rate(pt, pr, S, Dde, ratio, ds1, dg1, dp1, candidates)) return false;
        Point mid = pt;
        for (int i = 0; i < 6; ++i) mid.t[i] += ds1[i];
        mid.gp += dg1;
        mid.pp = std::max(mid.pp + dp1, a_ + par_.p_min);
        const Principal pr_mid = principal(mid.t, &pr);
        if (!plastic_rate(mid, pr_mid, surfaces(mid, pr_mid, true), Dde, ratio, ds2, dg2, dp2, candidates))
            return false;
        Point next = pt;
        double diff[6];
        for (int i = 0; i < 6; ++i) {
            next.t[i] += 0.5 * (ds1[i] + ds2[i]);
            diff[i] = 0.5 * (ds2[i] - ds1[i]);
        }
        next.gp += 0.5 * (dg1 + dg2);
        next.pp = std::max(next.pp + 0.5 * (dp1 + dp2), a_ + par_.p_min);
        const double scale = std::max(tnorm(next.t), par_.p_min);
        const double err = std::max({tnorm(diff) / scale, 0.5 * std::abs(dp2 - dp1) / next.pp,
                                     0.5 * std::abs(dg2 - dg1) / std::max(next.gp, 1e-5)});
        if (!clock.accept(err)) continue;
        Principal pr_next = principal(next.t, &pr);
        correct_drift(next, pr_next, ratio, S, S_current);
        pt = next;
        pr = pr_next;
    }
    return true;
}

// Near the apex, in tension, or where substepping fails: elastic predictor at the floored
// stiffness and the closed-form Mohr-Coulomb return; the hardening variables then follow
// the returned stress so that it lies on or inside both surfaces.
void HardeningSoilSmall::fallback(Point& pt, const double* de, double ratio) const {
    double lam, G, ds[6];
    elastic_moduli(principal(pt.t), ratio, lam, G);
    apply_elastic(lam, G, de, ds);
    double sigma[6], zero[6] = {0, 0, 0, 0, 0, 0}, eps_p = 0.0;
    for (int i = 0; i < 6; ++i) sigma[i] = -(pt.t[i] + ds[i]);
    const int point = 0;
    failure_.update(1, &point, zero, sigma, &eps_p, 1);
    for (int i = 0; i < 6; ++i) pt.t[i] = -sigma[i];
    const Principal pr = principal(pt.t);
    pt.gp = std::max(pt.gp, gamma_of(pr.s[0] - pr.s[2], pr.s[2] + a_));
    pt.pp = std::max({pt.pp, cap_radius(pr), a_ + par_.p_min});
}

void HardeningSoilSmall::initialise_state(const double* stress, double* state) const {
    Point pt;
    for (int i = 0; i < 6; ++i) pt.t[i] = -stress[i];
    const Principal pr = principal(pt.t);
    for (int i = 0; i < 6; ++i) state[i] = 0.0;
    state[6] = gamma_of(pr.s[0] - pr.s[2], pr.s[2] + a_);
    state[7] = std::max(par_.ocr * cap_radius(pr), a_ + par_.p_min) - a_;
    state[8] = 1.0;
}

double HardeningSoilSmall::p_wave_modulus() const {
    const double G = par_.G0_ref;
    return G * (lam_over_G_ + 2.0);
}

double HardeningSoilSmall::p_wave_modulus_at(const double* stress, const double*) const {
    double t[6];
    for (int i = 0; i < 6; ++i) t[i] = -stress[i];
    // The least principal stress alone (each step asks it of every point for the step size).
    const double s3 = t[4] == 0.0 && t[5] == 0.0 ? plane_minor_principal(t) : principal(t).s[2];
    const double G = par_.G0_ref * stiffness_factor(s3);
    return G * (lam_over_G_ + 2.0);
}

double HardeningSoilSmall::shear_yield(const double* stress, const double* state) const {
    Point pt;
    for (int i = 0; i < 6; ++i) pt.t[i] = -stress[i];
    pt.gp = state[6];
    pt.pp = state[7] + a_;
    return surfaces(pt, principal(pt.t), false).fs;
}

double HardeningSoilSmall::cap_yield(const double* stress, const double* state) const {
    Point pt;
    for (int i = 0; i < 6; ++i) pt.t[i] = -stress[i];
    pt.gp = state[6];
    pt.pp = state[7] + a_;
    return surfaces(pt, principal(pt.t), false).fc;
}

void HardeningSoilSmall::update(int count, const int* points, const double* dstrain, double* stress, double* state,
                                int stride) const {
    for (int k = 0; k < count; ++k) {
        const int idx = points[k];
        const double* e = dstrain + 6 * idx;
        double* s = stress + 6 * idx;
        double* st = state + static_cast<std::size_t>(stride) * idx;
        double tangent_ratio = 1.0;
        const double ratio = history_ratio(st, e, tangent_ratio);
        Point pt;
        for (int i = 0; i < 6; ++i) pt.t[i] = -s[i];
        pt.gp = std::max(st[6], 0.0);
        pt.pp = std::max(st[7] + a_, a_ + par_.p_min);
        // Compression-positive tensor strain increment.
        const double de[6] = {-e[0], -e[1], -e[2], -0.5 * e[3], -0.5 * e[4], -0.5 * e[5]};
        const Point start = pt;
        Principal pr;
        if (!integrate(pt, de, ratio, pr)) {
            pt = start;
            fallback(pt, de, ratio);
        } else {
            // The hardening return keeps q <= q_f only to the drift tolerance; past it, or in
            // tension beyond the apex, the Mohr-Coulomb return makes the stress admissible.
            const double sc = std::max(pr.s[0] + a_, par_.p_min);
            if (pr.s[0] - pr.s[2] - failure_deviator(pr.s[2]) > 10.0 * par_.tolerance * sc || pr.s[2] + a_ < 0.0) {
                double sigma[6], zero[6] = {0, 0, 0, 0, 0, 0}, eps_p = 0.0;
                for (int i = 0; i < 6; ++i) sigma[i] = -pt.t[i];
                const int point = 0;
                failure_.update(1, &point, zero, sigma, &eps_p, 1);
                for (int i = 0; i < 6; ++i) pt.t[i] = -sigma[i];
            }
        }
        for (int i = 0; i < 6; ++i) s[i] = -pt.t[i];
        st[6] = pt.gp;
        st[7] = pt.pp - a_;
        st[8] = tangent_ratio;
    }
}

}  // namespace pilempm::mpm
