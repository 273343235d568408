#pragma once
// Static resistance to driving at one penetration, as the soil model gives it: shaft
// resistance per metre of pile against depth below the mudline, and the toe resistance.
// Plain data, so SRD methods, bearing-graph studies and tests all produce the same thing.
#include <vector>

namespace pilempm::coupling {

struct ResistanceDistribution {
    double penetration = 0.0;     // m below the mudline
    std::vector<double> depth;    // m below the mudline, increasing, 0 .. penetration
    std::vector<double> shaft;    // N per m of pile (outside + inside or plug)
    double toe = 0.0;             // N
    // Optional Smith shaft damping J (s/m) of the stretch from the sample above down to each
    // sample, e.g. by soil type; empty: the SmithParameters value everywhere.
    std::vector<double> shaft_damping;

    double shaft_per_metre_at(double d) const;  // linear between samples, 0 outside
    double shaft_between(double d0, double d1) const;  // N, exact for the linear samples
    // Smith-viscous dashpot of the shaft between d0 and d1 (N s/m): the sum of J R_u over
    // it, each sample's J serving the stretch from the sample above down to it.
    double shaft_dashpot_between(double d0, double d1, double fallback) const;
    double shaft_total() const { return shaft_between(0.0, penetration); }
    double total() const { return shaft_total() + toe; }
};

}  // namespace pilempm::coupling
