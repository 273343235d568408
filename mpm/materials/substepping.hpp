#pragma once
// The pieces that explicit, error-controlled stress integration shares across models
// (Sloan et al. 2001): the clock that sizes the substeps of one strain increment from the
// local error of each, and the Pegasus iteration for where an elastic path meets a surface.
#include <algorithm>
#include <cmath>

namespace pilempm::mpm {

// Pseudo-time T runs from 0 to 1 over the increment. After each trial substep of size
// fraction(), accept(error) either advances T (error <= tolerance) or shrinks the step;
// the next step grows or shrinks by 0.9 sqrt(tolerance / error), within [0.1, 2].
class SubstepClock {
public:
    // Steps of at most min_forced are accepted whatever their error (0: never).
    SubstepClock(double tolerance, int max_substeps, double min_fraction, double min_forced = 0.0)
        : tol_(tolerance), max_(max_substeps), min_(min_fraction), forced_(min_forced) {}

    bool unfinished() const { return T_ < 1.0; }
    bool exhausted() const { return count_ > max_ || dT_ < min_; }
    double fraction() const { return dT_; }
    bool first() const { return T_ == 0.0; }
    bool accept(double error) {
        ++count_;
        const double grow = std::clamp(0.9 * std::sqrt(tol_ / std::max(error, 1e-16)), 0.1, 2.0);
        if (error > tol_ && dT_ > forced_) {
            dT_ *= grow;
            return false;
        }
        T_ += dT_;
        dT_ = std::min(dT_ * grow, 1.0 - T_);
        return true;
    }

private:
    double tol_;
    int max_;
    double min_, forced_;
    double T_ = 0.0, dT_ = 1.0;
    int count_ = 0;
};

// The root alpha in (0, 1) of f(alpha), given f(0) = f0 < 0 < f(1) = f1, to |f| <= tol.
// f may keep the state it evaluated: the last call is at the returned alpha.
template <class F>
double pegasus_root(double f0, double f1, double tol, F&& f, int max_iterations = 40) {
    double a0 = 0.0, a1 = 1.0, fa = f0, fb = f1, alpha = 0.0;
    for (int it = 0; it < max_iterations; ++it) {
        alpha = a1 - fb * (a1 - a0) / (fb - fa);
        const double fn = f(alpha);
        if (std::abs(fn) <= tol) break;
        if (fn * fb < 0.0) {
            a0 = a1;
            fa = fb;
        } else {
            fa *= fb / (fb + fn);
        }
        a1 = alpha;
        fb = fn;
    }
    return alpha;
}

}  // namespace pilempm::mpm
