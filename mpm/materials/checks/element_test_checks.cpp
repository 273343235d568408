#include "mpm/materials/checks/element_test_checks.hpp"

#include <functional>
#include <map>
#include <stdexcept>

namespace pilempm::mpm {

const TestResult& ElementTestContext::first_of(const std::string& type, const std::string& check) const {
    for (const auto& r : results)
        if (r.input->type == type) return r;
    throw std::invalid_argument(check + " needs a " + type + " test in the case");
}

void ElementTestContext::require_model(const std::string& model, const std::string& check) const {
    if (c.material.model != model) throw std::invalid_argument(check + " is a closed form of " + model);
}

int ElementTestContext::state_index(const std::string& name, const std::string& check) const {
    for (int k = 0; k < model.num_state(); ++k)
        if (name == model.state_name(k)) return k;
    throw std::invalid_argument(check + " needs the state variable " + name + ", which " + model.name() + " has not");
}

std::vector<VerificationCheck> element_test_checks(const std::string& name, const ElementTestContext& ctx) {
    using Check = std::function<std::vector<VerificationCheck>(const ElementTestContext&)>;
    static const std::map<std::string, Check> table = {
        {"critical_state_drained", critical_state_drained},
        {"undrained_path", undrained_path},
        {"critical_void_ratio", critical_void_ratio},
        {"isotropic_compression_line", isotropic_compression_line},
        {"subloading_critical_state", subloading_critical_state},
        {"subloading_smooth_transition", subloading_smooth_transition},
        {"subloading_reduces_to_mcc", subloading_reduces_to_mcc},
        {"subloading_within_peak_cone", subloading_within_peak_cone},
        {"subloading_oedometer", subloading_oedometer},
        {"small_strain_stiffness_decay", small_strain_stiffness_decay},
        {"e50_and_failure", e50_and_failure},
    };
    const auto it = table.find(name);
    if (it == table.end()) throw std::invalid_argument("no element-test check named " + name);
    return it->second(ctx);
}

}  // namespace pilempm::mpm
