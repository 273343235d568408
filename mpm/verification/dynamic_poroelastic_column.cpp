#include "mpm/verification/dynamic_poroelastic_column.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace pilempm::mpm {

using cplx = std::complex<double>;

cplx ColumnLoad::laplace(cplx s) const {
    const double T = duration;
    if (T <= 0.0) return pressure / s;
    const double a = std::numbers::pi / T;
    const cplx late = std::exp(-s * T);
    switch (shape) {
        case ColumnPulse::Rectangular: return pressure * (1.0 - late) / s;
        case ColumnPulse::HalfSine: return pressure * a * (1.0 + late) / (s * s + a * a);
        case ColumnPulse::SineSquared: return 2.0 * a * a * pressure * (1.0 - late) / (s * (s * s + 4.0 * a * a));
    }
    return 0.0;
}

namespace {

// At one Laplace parameter s, with the displacements u (skeleton) and U (water) of the
// half-space z >= 0 written as sum_i c_i phi_i exp(-lambda_i z), the 1D equations
//   mixture: rho_1 s^2 u + rho_2 s^2 U = M u'' - p'
//   water:   rho_2 s^2 U = -n p' - b s (U - u),   p = -Q ((1 - n) u' + n U')
// (rho_1 = (1 - n) rho_s, rho_2 = n rho_w, b = n^2 R, Q = K_w / n) become A X'' = B X:
// the modes are the roots mu = lambda^2 of det(B - mu A) = 0. The drained surface carries
// the load: sigma' - p = -q and p = 0 at z = 0.
struct Modes {
    cplx lambda[2];
    cplx pressure_amplitude[2];  // p = sum pressure_amplitude_i exp(-lambda_i z)
    cplx stress_amplitude[2];    // sigma' = sum stress_amplitude_i exp(-lambda_i z)
};

Modes surface_loaded_modes(const PoroelasticColumn& c, cplx s, cplx load) {
    const double n = c.porosity, M = c.p_wave_modulus, Q = c.water_bulk_modulus / n;
    const double rho1 = c.solid_density_partial, rho2 = n * c.water_density, b = n * n * c.darcy_resistance;
    const double A11 = M + (1.0 - n) * Q, A12 = n * Q, A21 = n * (1.0 - n) * Q, A22 = n * n * Q;
    const cplx s2 = s * s;
    const cplx B11 = rho1 * s2, B12 = rho2 * s2, B21 = -b * s, B22 = rho2 * s2 + b * s;
    // det(A) mu^2 - c1 mu + det(B) = 0, the larger root first and the other from the product.
    const double detA = A11 * A22 - A12 * A21;
    const cplx c1 = A22 * B11 + A11 * B22 - A12 * B21 - A21 * B12;
    const cplx detB = B11 * B22 - B12 * B21;
    const cplx root = std::sqrt(c1 * c1 - 4.0 * detA * detB);
    const cplx big = std::abs(c1 + root) >= std::abs(c1 - root) ? c1 + root : c1 - root;
    const cplx mu[2] = {big / (2.0 * detA), 2.0 * detB / big};
    Modes m{};
    cplx phi_u[2], psi[2];  // skeleton displacement and the pore-volume change (1 - n) u + n U
    for (int i = 0; i < 2; ++i) {
        m.lambda[i] = std::sqrt(mu[i]);  // principal root: Re > 0, decaying with depth
        const cplx r11 = B11 - mu[i] * A11, r12 = B12 - mu[i] * A12;
        const cplx r21 = B21 - mu[i] * A21, r22 = B22 - mu[i] * A22;
        cplx pu, pU;
        if (std::abs(r11) + std::abs(r12) >= std::abs(r21) + std::abs(r22)) pu = r12, pU = -r11;
        else pu = r22, pU = -r21;
        phi_u[i] = pu;
        psi[i] = (1.0 - n) * pu + n * pU;
    }
    // With d_i = lambda_i c_i: sigma' = -M sum d_i phi_u_i e_i, p = Q sum d_i psi_i e_i.
    // Surface: M sum d_i phi_u_i = q, sum d_i psi_i = 0.
    const cplx det = M * phi_u[0] * psi[1] - M * phi_u[1] * psi[0];
    const cplx d[2] = {load * psi[1] / det, -load * psi[0] / det};
    for (int i = 0; i < 2; ++i) {
        m.pressure_amplitude[i] = Q * d[i] * psi[i];
        m.stress_amplitude[i] = -M * d[i] * phi_u[i];
    }
    return m;
}

}  // namespace

// Durbin (1974): with s_k = gamma + i k pi / T,
//   f(t) = exp(gamma t) / T [Re F(gamma) / 2 + sum_k Re(F(s_k) exp(i k pi t / T))],  0 < t < 2T.
std::vector<ColumnResponse> poroelastic_column_history(const PoroelasticColumn& column, const ColumnLoad& load,
                                                       double depth, const std::vector<double>& times,
                                                       const LaplaceInversion& inversion) {
    if (!(column.porosity > 0.0 && column.porosity < 1.0) || !(column.p_wave_modulus > 0.0) ||
        !(column.water_bulk_modulus > 0.0) || !(column.solid_density_partial > 0.0) || column.darcy_resistance < 0.0)
        throw std::invalid_argument("poroelastic_column_history: a saturated elastic column needs 0 < n < 1, M, K_w, "
                                    "a solid density > 0 and a drag >= 0");
    if (times.empty()) return {};
    const double T = times.back() > 0.0 ? 2.0 * times.back() : 1.0;
    const double gamma = inversion.decay / T, dw = std::numbers::pi / T;
    const std::size_t nt = times.size();
    std::vector<cplx> rotation(nt), phase(nt, cplx(1.0, 0.0));
    std::vector<double> sum_p(nt), sum_s(nt);
    auto transform = [&](cplx s, cplx& p, cplx& sig) {
        const Modes m = surface_loaded_modes(column, s, load.laplace(s));
        p = sig = 0.0;
        for (int i = 0; i < 2; ++i) {
            const cplx e = std::exp(-m.lambda[i] * depth);
            p += m.pressure_amplitude[i] * e;
            sig += m.stress_amplitude[i] * e;
        }
    };
    cplx p0, s0;
    transform(cplx(gamma, 0.0), p0, s0);
    for (std::size_t j = 0; j < nt; ++j) {
        rotation[j] = std::polar(1.0, dw * times[j]);
        sum_p[j] = 0.5 * p0.real();
        sum_s[j] = 0.5 * s0.real();
    }
    for (int k = 1; k <= inversion.terms; ++k) {
        cplx p, sig;
        transform(cplx(gamma, dw * k), p, sig);
        for (std::size_t j = 0; j < nt; ++j) {
            phase[j] *= rotation[j];  // exp(i k pi t_j / T) by recurrence
            sum_p[j] += (p * phase[j]).real();
            sum_s[j] += (sig * phase[j]).real();
        }
    }
    std::vector<ColumnResponse> out(nt);
    for (std::size_t j = 0; j < nt; ++j) {
        const double scale = std::exp(gamma * times[j]) / T;
        out[j] = {scale * sum_p[j], scale * sum_s[j]};
    }
    return out;
}

}  // namespace pilempm::mpm
