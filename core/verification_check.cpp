#include "core/verification_check.hpp"

#include <cmath>
#include <utility>

namespace pilempm {

VerificationCheck make_check(std::string name, double computed, double reference, double tolerance, bool relative,
                             std::string note) {
    VerificationCheck c;
    c.name = std::move(name);
    c.computed = computed;
    c.reference = reference;
    c.tolerance = tolerance;
    c.relative = relative;
    c.note = std::move(note);
    const double err = std::abs(computed - reference);
    c.passed = std::isfinite(computed) && err <= tolerance * (relative ? std::abs(reference) : 1.0);
    return c;
}

}  // namespace pilempm
