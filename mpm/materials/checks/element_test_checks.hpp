#pragma once
// Closed-form checks of element tests, by name (the case's verification.checks). Each model
// family keeps its checks in its own file (<model>_checks.cpp); the table that maps
// a name to its function is in element_test_checks.cpp.
#include <string>
#include <vector>

#include "core/verification_check.hpp"
#include "mpm/materials/element_test.hpp"

namespace pilempm::mpm {

struct TestResult {
    const ElementTestDefinition* input;
    std::vector<ElementRecord> path;
};

// What every check may look at: the case, all test paths, the initial state and p'.
struct ElementTestContext {
    const ElementTestSetup& c;
    const ConstitutiveModel& model;
    const std::vector<TestResult>& results;
    const std::vector<double>& state0;
    double p0;
    // The first test of this type, or an error naming the check that needs it.
    const TestResult& first_of(const std::string& type, const std::string& check) const;
    // An error unless the case's material is `model`.
    void require_model(const std::string& model, const std::string& check) const;
    // Where the model keeps the state variable `name` in ElementRecord::state.
    int state_index(const std::string& name, const std::string& check) const;
};

std::vector<VerificationCheck> element_test_checks(const std::string& name, const ElementTestContext& ctx);

// Per model family.
std::vector<VerificationCheck> critical_state_drained(const ElementTestContext& ctx);
std::vector<VerificationCheck> undrained_path(const ElementTestContext& ctx);
std::vector<VerificationCheck> critical_void_ratio(const ElementTestContext& ctx);
std::vector<VerificationCheck> isotropic_compression_line(const ElementTestContext& ctx);
std::vector<VerificationCheck> subloading_critical_state(const ElementTestContext& ctx);
std::vector<VerificationCheck> subloading_smooth_transition(const ElementTestContext& ctx);
std::vector<VerificationCheck> subloading_reduces_to_mcc(const ElementTestContext& ctx);
std::vector<VerificationCheck> subloading_within_peak_cone(const ElementTestContext& ctx);
std::vector<VerificationCheck> subloading_oedometer(const ElementTestContext& ctx);
std::vector<VerificationCheck> small_strain_stiffness_decay(const ElementTestContext& ctx);
std::vector<VerificationCheck> e50_and_failure(const ElementTestContext& ctx);

}  // namespace pilempm::mpm
