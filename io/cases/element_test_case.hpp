#pragma once
// An element-test case (analysis: element_test): one material, an initial effective
// stress, and a list of laboratory tests, each a path of legs from that initial state.
#include <string>
#include <vector>

#include "io/cases/material_input.hpp"
#include "io/cases/pile_hammer_input.hpp"
#include "mpm/materials/element_test.hpp"

namespace pilempm::io {

using ElementTestInput = mpm::ElementTestDefinition;

struct ElementTestCase : CaseFile, mpm::ElementTestSetup {
    bool plots = true;
    std::vector<std::string> verification_checks;  // names from element_test_check_names
};

// The closed-form checks an element-test case may ask for (mpm/materials/checks/
// holds what each computes).
inline const std::vector<std::string> element_test_check_names = {
    "critical_state_drained",  // modified Cam clay
    "undrained_path",          // modified Cam clay
    "critical_void_ratio",         // hypoplastic
    "isotropic_compression_line",  // hypoplastic
    "subloading_critical_state",     // subloading Cam clay: q / p' = M(theta) at the end
    "subloading_smooth_transition",  // subloading Cam clay, OCR > 1: no stiffness jump
    "subloading_reduces_to_mcc",     // subloading Cam clay against modified Cam clay
    "subloading_within_peak_cone",   // subloading Cam clay inside its bounding cone, no tension
    "subloading_oedometer",          // subloading Cam clay: NCL slope, elastic unloading
    "small_strain_stiffness_decay",  // hardening soil small
    "e50_and_failure",               // hardening soil small
};

ElementTestCase read_element_test_case(const std::string& file);

}  // namespace pilempm::io
