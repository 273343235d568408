#pragma once
// Material points as a structure of arrays. D = 2 (plane strain or axisymmetric; x = r
// when axisymmetric, y up) or D = 3 (z up). In 2D the volume and mass are per unit
// thickness (plane strain) or per radian (axisymmetric).
#include <cstddef>
#include <vector>

namespace pilempm::mpm {

template <int D>
struct Particles {
    std::vector<double> x;        // D per point, m
    std::vector<double> v;        // D per point, m/s
    std::vector<double> C;        // D*D per point: affine velocity field (APIC), 1/s, row-major
    std::vector<double> mass;     // kg
    std::vector<double> volume;   // m^3 (current)
    std::vector<double> volume0;  // m^3 (initial)
    std::vector<double> F;        // D*D per point, deformation gradient, row-major
    std::vector<double> domain0;  // D*D per point: the D edge vectors of the initial
                                  // particle domain (row k = vector k), for GIMP and CPDI
    std::vector<double> stress;   // 6 per point, Voigt, Pa, tension positive (effective)
    std::vector<double> strain;   // 6 per point, accumulated log-free small-strain sum
    std::vector<double> dstrain;  // 6 per point, this step's increment (scratch)
    std::vector<int> material;    // index into the material list
    std::vector<int> field;       // the grid's velocity field it moves with (0: the default)
    std::vector<double> state;    // state_stride per point
    int state_stride = 0;
    std::vector<double> external_force;  // D per point, N (tractions mapped to points)
    // Pore water (saturated materials; zero for dry ones). The porosity is owned here: models
    // that keep a void ratio read it from the point.
    std::vector<double> porosity;        // n, current
    std::vector<double> pore_pressure;   // excess over hydrostatic, Pa, compression positive
    std::vector<double> w;               // D per point: water velocity (coupled materials), m/s

    std::size_t size() const { return mass.size(); }
    // Bytes each point takes in these arrays.
    std::size_t bytes_per_point() const;
    // Appends one point at rest with F = I and zero stress; domain0 = diag(lengths).
    void add(const double* position, double point_mass, double point_volume, const double* lengths,
             int material_id);
    void resize_state(int stride);
    // Keeps the points with keep[i] != 0, in order (the others are removed from every array).
    void keep_only(const std::vector<char>& keep);
};

}  // namespace pilempm::mpm
