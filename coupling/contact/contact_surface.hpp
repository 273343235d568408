#pragma once
// The master side of a contact: straight segments between nodes in the soil's (r or x, y)
// plane, with the body they bound on the inner side of their outward normal. Whatever the
// body (an FE pile, a rigid plate) it fills positions and velocities before each step and
// takes back the nodal forces.
#include <vector>

namespace pilempm::coupling {

// Where a segment lies on the pile: what the head load splits into.
enum class SurfaceSide { Outer, Inner, Toe, Head, Other };

struct ContactSurface {
    std::vector<double> x;  // 2 per node, m, current position in the soil's frame
    std::vector<double> v;  // 2 per node, m/s
    // Segment k runs from node a[k] to node b[k]; its outward normal is (t_y, -t_x) / |t|,
    // t = x_b - x_a (the body lies to the left of a -> b: counter-clockwise boundaries).
    std::vector<int> a, b;
    std::vector<SurfaceSide> side;
    // 1 / mass of each node in the master's measure (1/kg; empty: a rigid, held surface),
    // for a penalty as stiff as the pair of bodies allows.
    std::vector<double> inverse_mass;

    int num_segments() const { return static_cast<int>(a.size()); }
    void add_segment(int from, int to, SurfaceSide where) {
        a.push_back(from);
        b.push_back(to);
        side.push_back(where);
    }
};

}  // namespace pilempm::coupling
