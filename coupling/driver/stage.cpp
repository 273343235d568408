#include "coupling/driver/stage.hpp"

#include <algorithm>

namespace pilempm::coupling {

bool StageLoad::acts_in(int stage) const {
    return stages.empty() || std::find(stages.begin(), stages.end(), stage) != stages.end();
}

bool StageLoad::active(int stage, bool quasi_static, double time_in_stage) const {
    if (!acts_in(stage)) return false;
    if (duration <= 0.0) return true;
    return !quasi_static && time_in_stage < duration;
}

}  // namespace pilempm::coupling
