#include "fem/dynamics/section_gauge.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pilempm::fem {

SectionGauge::SectionGauge(const fem::PileMesh& mesh, double z) : z_(z) {
    // Pick the element row whose axial extent holds z; on a node row prefer the one below
    // (inside the pile at the head) unless z is the toe.
    int global = 0;
    std::vector<std::pair<int, double>> hits;
    for (const auto& b : mesh.blocks) {
        for (int e = 0; e < b.num_elements(); ++e, ++global) {
            const double lo = b.z_min[e], hi = b.z_max[e];
            const double tol = 1e-9 * (hi - lo);
            const bool inside = z > lo + tol && z < hi - tol;
            const bool on_top = std::abs(z - hi) <= tol;
            const bool on_bottom_of_toe = std::abs(z - lo) <= tol && lo <= tol;
            if (inside || on_top || on_bottom_of_toe) hits.push_back({global, b.section_area[e]});
        }
    }
    if (hits.empty()) throw std::invalid_argument("gauge outside the pile");
    // Keep one row: the elements whose centroid is nearest below-or-at the plane.
    global = 0;
    std::vector<double> centroid;
    for (const auto& b : mesh.blocks)
        for (int e = 0; e < b.num_elements(); ++e) centroid.push_back(b.centroid_z[e]);
    double nearest = 1e300;
    for (auto [e, a] : hits) nearest = std::min(nearest, std::abs(centroid[e] - z));
    std::vector<int> node_set;
    for (auto [e, a] : hits) {
        if (std::abs(std::abs(centroid[e] - z) - nearest) > 1e-6 * (1.0 + nearest)) continue;
        elements_.push_back(e);
        element_area_.push_back(a);
        area_ += a;
    }
    // Nodes of the selected elements on the side nearest the plane.
    int offset = 0;
    for (const auto& b : mesh.blocks) {
        for (int e : elements_) {
            const int local = e - offset;
            if (local < 0 || local >= b.num_elements()) continue;
            for (int k = 0; k < b.nodes_per_element; ++k)
                node_set.push_back(b.connectivity[local * b.nodes_per_element + k]);
        }
        offset += b.num_elements();
    }
    std::sort(node_set.begin(), node_set.end());
    node_set.erase(std::unique(node_set.begin(), node_set.end()), node_set.end());
    double dz_best = 1e300;
    for (int n : node_set) dz_best = std::min(dz_best, std::abs(mesh.z(n) - z));
    for (int n : node_set)
        if (std::abs(std::abs(mesh.z(n) - z) - dz_best) <= 1e-9 * (1.0 + dz_best)) nodes_.push_back(n);
}

double SectionGauge::force_compression(const std::vector<double>& axial_stress) const {
    double f = 0.0;
    for (std::size_t k = 0; k < elements_.size(); ++k) f -= axial_stress[elements_[k]] * element_area_[k];
    return f;
}

double SectionGauge::velocity_down(const std::vector<double>& v, const fem::PileMesh& mesh) const {
    double s = 0.0;
    for (int n : nodes_) s -= v[mesh.axial_dof(n)];
    return s / static_cast<double>(nodes_.size());
}

double SectionGauge::displacement_down(const std::vector<double>& u,
                                       const fem::PileMesh& mesh) const {
    return velocity_down(u, mesh);
}

}  // namespace pilempm::fem
