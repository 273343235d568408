#pragma once
// A named comparison of a computed number with an independent reference (closed form,
// published figure, conservation law) and a stated tolerance: what every verification
// case writes to verification.json and what the tests assert.
#include <string>

namespace pilempm {

struct VerificationCheck {
    std::string name;
    double computed = 0.0;
    double reference = 0.0;
    double tolerance = 0.0;
    bool relative = true;        // |c - r| <= tol |r|, else |c - r| <= tol
    bool at_least = false;       // passes when computed >= reference (a coverage check)
    bool within_factor = false;  // passes when reference / tol <= computed <= reference x tol
    bool informative = false;    // reported beside its reference, without a pass or fail
    bool passed = false;
    std::string note;
};

// passed = |computed - reference| <= tolerance (x |reference| when relative), and finite.
VerificationCheck make_check(std::string name, double computed, double reference, double tolerance, bool relative,
                             std::string note = "");
// A number reported next to a reference it is not judged against (passed stays true).
VerificationCheck make_report(std::string name, double computed, double reference, std::string note);

}  // namespace pilempm
