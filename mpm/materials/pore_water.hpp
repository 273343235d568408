#pragma once
// Pore water of saturated soil: how each material drains, the water's properties and the
// free water surface. The solver carries excess pore pressure (over hydrostatic,
// compression positive): the hydrostatic part balances the water's weight exactly, so it
// enters the equations only as buoyancy and the seabed's water load needs no boundary term.
#include <string>

namespace pilempm::mpm {

// dry: no water. drained: the water flows freely (excess pressure stays zero) but adds its
// mass and buoyancy. undrained: the water moves with the skeleton and its pressure follows
// the volume change with K_w / n. coupled: the water has its own velocity w (v-w, Darcy drag).
enum class Drainage { Dry, Drained, Undrained, Coupled };

const char* drainage_name(Drainage d);

struct MaterialDrainage {
    Drainage drainage = Drainage::Dry;
    double porosity = 0.0;          // initial n (saturated materials)
    double darcy_resistance = 0.0;  // mu / kappa = rho_w g / k_hydraulic, Pa s / m^2 (coupled)
    bool saturated() const { return drainage != Drainage::Dry; }
};

struct PoreWater {
    double density = 1000.0;       // kg/m^3
    double bulk_modulus = 2.2e9;   // K_w, Pa
    bool free_surface = false;     // a free water surface (hydrostatic pressure below it)
    double level = 0.0;            // its elevation, m (vertical axis)
    double gravity = 9.81;         // m/s^2, the magnitude the hydrostatic pressure uses
    double hydrostatic_pressure(double z) const {
        return free_surface && z < level ? density * gravity * (level - z) : 0.0;
    }
    bool submerged(double z) const { return free_surface && z < level; }
    // Cavitation: water cannot take an absolute pressure below zero (its vapour pressure,
    // some 2 kPa, neglected), so the excess pressure stays above -(p_atm + hydrostatic).
    bool cavitation = false;
    double atmospheric_pressure = 101.325e3;  // Pa, on the free surface
    double least_excess_pressure(double z) const { return -(atmospheric_pressure + hydrostatic_pressure(z)); }
};

// The P-wave speeds of a saturated soil point (skeleton P-wave modulus M, porosity n, solid
// mass per volume rho_s (1 - n)): undrained, sqrt((M + K_w / n) / rho_sat), the limit of low
// permeability; and the fastest wave of the v-w equations without drag (the largest
// eigenvalue of the two-phase 1D wave operator), which bounds the explicit step at any
// permeability because the drag, taken semi-implicitly, only damps.
struct SaturatedWaveSpeeds {
    double undrained = 0.0, fastest = 0.0;  // m/s
};
SaturatedWaveSpeeds saturated_wave_speeds(double M, double porosity, double solid_density_partial, const PoreWater& w);

// Skempton's B of an elastic skeleton of bulk modulus K with incompressible grains
// (Gassmann): dp / d sigma_mean = 1 / (1 + n K / K_w).
double skempton_b(double skeleton_bulk_modulus, double porosity, double water_bulk_modulus);

}  // namespace pilempm::mpm
