#include "coupling/contact/contact_surface.hpp"

namespace pilempm::coupling {

const char* surface_side_name(SurfaceSide side) {
    switch (side) {
        case SurfaceSide::Outer: return "outer";
        case SurfaceSide::Inner: return "inner";
        case SurfaceSide::Toe: return "toe";
        case SurfaceSide::Head: return "head";
        case SurfaceSide::Other: break;
    }
    return "other";
}

}  // namespace pilempm::coupling
