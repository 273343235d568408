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

VerificationCheck make_report(std::string name, double computed, double reference, std::string note) {
    VerificationCheck c = make_check(std::move(name), computed, reference, 0.0, false, std::move(note));
    c.informative = true;
    c.passed = true;
    return c;
}

}  // namespace pilempm
