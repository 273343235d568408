#pragma once
// Pile geometry as a list of stations along the axis; between two stations the inner
// and outer radii vary linearly. Both the rod and the axisymmetric meshes are built
// from the same stations, so the two models describe the same steel.
#include <vector>

namespace pilempm::fem {

struct PileSegment {
    double length = 0.0;          // m
    double outer_diameter = 0.0;  // m
    double wall_thickness = 0.0;  // m
};

struct PileStation {
    double z = 0.0;             // m, elevation in the pile frame: toe at 0, head at L
    double inner_radius = 0.0;  // m
    double outer_radius = 0.0;  // m
};

struct PileGeometry {
    std::vector<PileStation> stations;  // ordered by z, toe first
    double length() const { return stations.empty() ? 0.0 : stations.back().z; }
    double area_at(double z) const;     // steel cross-section area, m^2
    double inner_radius_at(double z) const;
    double outer_radius_at(double z) const;
};

// Segments are listed from the head down. Where the wall thickness or diameter changes,
// a linear taper of slope 1:taper_ratio is inserted at the lower end of the upper segment
// (the 1:4 weld transition of EN 1993-1-9 by default); 0 gives a step.
PileGeometry make_pile_geometry(const std::vector<PileSegment>& segments_head_to_toe,
                                double taper_ratio = 4.0);

}  // namespace pilempm::fem
