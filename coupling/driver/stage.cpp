#include "coupling/driver/stage.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pilempm::coupling {

bool StageLoad::acts_in(int stage) const {
    return stages.empty() || std::find(stages.begin(), stages.end(), stage) != stages.end();
}

double StageLoad::factor(int stage, bool quasi_static, double time_in_stage) const {
    if (!acts_in(stage)) return 0.0;
    if (duration <= 0.0) return 1.0;
    if (quasi_static || time_in_stage >= duration) return 0.0;
    const double phase = std::sin(std::numbers::pi * time_in_stage / duration);
    switch (shape) {
        case PulseShape::HalfSine: return phase;
        case PulseShape::SineSquared: return phase * phase;
        case PulseShape::Rectangular: break;
    }
    return 1.0;
}

}  // namespace pilempm::coupling
