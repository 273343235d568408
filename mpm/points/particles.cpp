#include "mpm/points/particles.hpp"

namespace pilempm::mpm {

template <int D>
void Particles<D>::add(const double* position, double point_mass, double point_volume,
                       const double* lengths, int material_id) {
    for (int d = 0; d < D; ++d) {
        x.push_back(position[d]);
        v.push_back(0.0);
        external_force.push_back(0.0);
        w.push_back(0.0);
    }
    porosity.push_back(0.0);
    pore_pressure.push_back(0.0);
    mass.push_back(point_mass);
    volume.push_back(point_volume);
    volume0.push_back(point_volume);
    for (int i = 0; i < D; ++i)
        for (int j = 0; j < D; ++j) {
            F.push_back(i == j ? 1.0 : 0.0);
            C.push_back(0.0);
            domain0.push_back(i == j ? lengths[i] : 0.0);
        }
    for (int k = 0; k < 6; ++k) {
        stress.push_back(0.0);
        strain.push_back(0.0);
        dstrain.push_back(0.0);
    }
    material.push_back(material_id);
    field.push_back(0);
    for (int k = 0; k < state_stride; ++k) state.push_back(0.0);
}

template <int D>
std::size_t Particles<D>::bytes_per_point() const {
    // x, v, external_force (D); C, F, domain0 (D^2); mass, volume, volume0; stress, strain,
    // dstrain (6); porosity, pore pressure, w (D); state; material and field.
    return (4 * D + 3 * D * D + 5 + 18 + static_cast<std::size_t>(state_stride)) * sizeof(double) + 2 * sizeof(int);
}

template <int D>
void Particles<D>::resize_state(int stride) {
    state_stride = stride;
    state.assign(size() * static_cast<std::size_t>(stride), 0.0);
}

namespace {

// Compacts an array of `per` values per point to the kept points.
template <class T>
void compact(std::vector<T>& a, std::size_t per, const std::vector<char>& keep) {
    std::size_t out = 0;
    for (std::size_t i = 0; i < keep.size(); ++i) {
        if (!keep[i]) continue;
        for (std::size_t k = 0; k < per; ++k) a[out * per + k] = a[i * per + k];
        ++out;
    }
    a.resize(out * per);
}

}  // namespace

template <int D>
void Particles<D>::keep_only(const std::vector<char>& keep) {
    for (auto* a : {&x, &v, &external_force, &w}) compact(*a, D, keep);
    for (auto* a : {&C, &F, &domain0}) compact(*a, D * D, keep);
    for (auto* a : {&mass, &volume, &volume0, &porosity, &pore_pressure}) compact(*a, 1, keep);
    for (auto* a : {&stress, &strain, &dstrain}) compact(*a, 6, keep);
    compact(material, 1, keep);
    compact(field, 1, keep);
    if (state_stride > 0) compact(state, static_cast<std::size_t>(state_stride), keep);
}

template struct Particles<2>;
template struct Particles<3>;

}  // namespace pilempm::mpm
