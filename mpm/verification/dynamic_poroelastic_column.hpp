#pragma once
// The reference for waves in a saturated column: the 1D v-w equations (the solver's, in
// pore_water.hpp's terms) solved exactly in the Laplace domain for a half-space loaded at
// its drained surface, then inverted numerically (Durbin's Fourier series on the Bromwich
// line). The construction follows Verruijt (2010, ch. 11) and de Boer et al. (1993); with
// compressible water there are two P-waves, coupled by the drag, and no closed form in t.
#include <complex>
#include <vector>

namespace pilempm::mpm {

struct PoroelasticColumn {
    double p_wave_modulus = 0.0;      // M of the skeleton, Pa
    double porosity = 0.0;            // n
    double solid_density_partial = 0.0;  // (1 - n) rho_s, kg/m^3
    double water_density = 1000.0;    // rho_w, kg/m^3
    double water_bulk_modulus = 2.2e9;   // K_w, Pa
    double darcy_resistance = 0.0;    // R = mu / kappa = rho_w g / k, Pa s / m^2 (0: no drag)
};

// The surface load's time shape (total stress, compression positive): a step held from
// t = 0 (duration 0), a rectangular pulse, p sin(pi t / T) or p sin^2(pi t / T).
enum class ColumnPulse { Rectangular, HalfSine, SineSquared };
struct ColumnLoad {
    double pressure = 0.0;  // Pa
    double duration = 0.0;  // s; 0: held
    ColumnPulse shape = ColumnPulse::Rectangular;
    std::complex<double> laplace(std::complex<double> s) const;  // the load's transform
};

struct ColumnResponse {
    double excess_pore_pressure = 0.0;  // Pa, compression positive
    double effective_stress = 0.0;      // sigma'_zz, Pa, tension positive
};

struct LaplaceInversion {
    int terms = 1 << 15;     // Fourier terms on the Bromwich line
    double decay = 8.0;      // gamma T: the aliasing error is exp(-2 gamma T) of the signal
};

// The response at `depth` below the loaded, drained surface at each of `times` (ascending,
// >= 0). The half-period of the series is twice the last time, so the aliased copy of the
// signal is damped by exp(-2 decay) and the series' error grows at most by exp(decay / 2).
std::vector<ColumnResponse> poroelastic_column_history(const PoroelasticColumn& column, const ColumnLoad& load,
                                                       double depth, const std::vector<double>& times,
                                                       const LaplaceInversion& inversion = {});

}  // namespace pilempm::mpm
