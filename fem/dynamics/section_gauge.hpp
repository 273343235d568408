#pragma once
// A strain-gauge section of the pile: the elements cut by the plane z = const. Axial
// force = sum of element axial stress x the steel area each carries; velocity = mean
// axial velocity of their nodes. The same mechanism serves the head, the toe and gauges.
#include <vector>

#include "fem/dynamics/explicit_pile.hpp"

namespace pilempm::fem {

class SectionGauge {
public:
    SectionGauge(const fem::PileMesh& mesh, double z);
    double z() const { return z_; }
    double force_compression(const std::vector<double>& axial_stress) const;
    double velocity_down(const std::vector<double>& velocity, const fem::PileMesh& mesh) const;
    double displacement_down(const std::vector<double>& u, const fem::PileMesh& mesh) const;
    double area() const { return area_; }

private:
    double z_;
    double area_ = 0.0;
    std::vector<int> elements_;  // global element index (blocks in order)
    std::vector<double> element_area_;
    std::vector<int> nodes_;
};

}  // namespace pilempm::fem
