#include "coupling/driver/recorders.hpp"

namespace pilempm::coupling {

template <int D>
double elastic_energy(const mpm::Particles<D>& p) {
    double e = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
        for (int k = 0; k < 6; ++k) e += 0.5 * p.stress[6 * i + k] * p.strain[6 * i + k] * p.volume[i];
    return e;
}

template <int D>
void EnergyRecorder<D>::add_columns(std::vector<std::string>& columns) const {
    columns.insert(columns.end(),
                   {"kinetic_energy_J", "elastic_energy_J", "absorbed_energy_J", "unbalanced_force_ratio",
                    "external_work_J"});
}

template <int D>
void EnergyRecorder<D>::sample(const mpm::MpmModel<D>& m, const mpm::MpmSolver<D>& solver,
                               std::vector<double>& row) const {
    row.push_back(solver.kinetic_energy());
    row.push_back(elastic_energy(m.particles) + pore_water_energy(m));
    row.push_back(solver.absorbed_energy());
    row.push_back(solver.unbalanced_force_ratio());
    row.push_back(solver.external_work());
}

template <int D>
void ConservationRecorder<D>::add_columns(std::vector<std::string>& columns) const {
    columns.insert(columns.end(), {"soil_mass_kg", "soil_volume_m3", "pore_water_volume_m3"});
}

template <int D>
void ConservationRecorder<D>::sample(const mpm::MpmModel<D>& m, const mpm::MpmSolver<D>&,
                                     std::vector<double>& row) const {
    const auto& p = m.particles;
    double mass = 0.0, volume = 0.0, water = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        mass += p.mass[i];
        volume += p.volume[i];
        water += p.porosity[i] * p.volume[i];  // n = 0 where dry
    }
    row.push_back(mass);
    row.push_back(volume);
    row.push_back(water);
}

template <int D>
void ReactionRecorder<D>::add_columns(std::vector<std::string>& columns) const {
    const char* axis = "xyz";
    for (int d = 0; d < D; ++d) columns.push_back(std::string("reaction_") + axis[d] + "_N");
}

template <int D>
void ReactionRecorder<D>::sample(const mpm::MpmModel<D>& m, const mpm::MpmSolver<D>&, std::vector<double>& row) const {
    for (int d = 0; d < D; ++d) {
        double r = 0.0;
        for (int n : nodes_)
            if (const auto* c = m.grid.find_condition(n)) r += c->reaction[d];
        row.push_back(r);
    }
}

template <int D>
void ProbeRecorder<D>::add_columns(std::vector<std::string>& columns) const {
    for (std::size_t k = 0; k < points_.size(); ++k) {
        columns.push_back("probe" + std::to_string(k) + "_velocity_vertical_m_s");
        columns.push_back("probe" + std::to_string(k) + "_stress_vertical_Pa");
        columns.push_back("probe" + std::to_string(k) + "_velocity_x_m_s");
        columns.push_back("probe" + std::to_string(k) + "_stress_x_Pa");  // radial in axisymmetry
        // The other horizontal stress: out of plane in 2D (the hoop stress in axisymmetry).
        columns.push_back("probe" + std::to_string(k) + (D == 2 ? "_stress_hoop_Pa" : "_stress_y_Pa"));
        columns.push_back("probe" + std::to_string(k) + "_volumetric_strain");  // V / V0 - 1, dilation positive
        columns.push_back("probe" + std::to_string(k) + "_elevation_m");         // where the point is now
        if (!pore_water_) continue;
        columns.push_back("probe" + std::to_string(k) + "_excess_pore_pressure_Pa");
        columns.push_back("probe" + std::to_string(k) + "_water_velocity_vertical_m_s");
    }
}

template <int D>
void ProbeRecorder<D>::sample(const mpm::MpmModel<D>& m, const mpm::MpmSolver<D>&, std::vector<double>& row) const {
    for (int p : points_) {
        row.push_back(m.particles.v[D * p + D - 1]);
        row.push_back(m.particles.stress[6 * p + (D == 2 ? 1 : 2)]);
        row.push_back(m.particles.v[D * p]);
        row.push_back(m.particles.stress[6 * p]);
        row.push_back(m.particles.stress[6 * p + (D == 2 ? 2 : 1)]);
        row.push_back(m.particles.volume[p] / m.particles.volume0[p] - 1.0);
        row.push_back(m.particles.x[D * p + D - 1]);
        if (!pore_water_) continue;
        row.push_back(m.particles.pore_pressure[p]);
        row.push_back(m.particles.w[D * p + D - 1]);
    }
}

template <int D>
double pore_water_energy(const mpm::MpmModel<D>& m) {
    if (!m.saturated()) return 0.0;
    const auto& p = m.particles;
    double e = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (p.porosity[i] > 0.0)
            e += 0.5 * p.pore_pressure[i] * p.pore_pressure[i] * p.porosity[i] / m.water.bulk_modulus * p.volume[i];
    return e;
}

template double pore_water_energy<2>(const mpm::MpmModel<2>&);
template double pore_water_energy<3>(const mpm::MpmModel<3>&);
template double elastic_energy<2>(const mpm::Particles<2>&);
template double elastic_energy<3>(const mpm::Particles<3>&);
template class EnergyRecorder<2>;
template class EnergyRecorder<3>;
template class ConservationRecorder<2>;
template class ConservationRecorder<3>;
template class ReactionRecorder<2>;
template class ReactionRecorder<3>;
template class ProbeRecorder<2>;
template class ProbeRecorder<3>;

}  // namespace pilempm::coupling
