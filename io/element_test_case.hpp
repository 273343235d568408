#pragma once
// An element-test case (analysis: element_test): one material, an initial effective
// stress, and a list of laboratory tests, each a path of legs from that initial state.
#include <string>
#include <vector>

#include "io/material_input.hpp"
#include "io/pile_hammer_input.hpp"
#include "mpm/element_test.hpp"

namespace pilempm::io {

struct ElementTestInput {
    std::string name, type;  // triaxial_drained | triaxial_undrained | oedometer | isotropic
    std::vector<mpm::ElementLeg> legs;
    double void_ratio = -1.0;  // > 0: start from this e instead of the material's
};

struct ElementTestCase : CaseFile {
    MaterialInput material;
    double axial_stress = 0.0, lateral_stress = 0.0;  // initial, effective, Pa, compression +
    std::vector<ElementTestInput> tests;
    bool plots = true;
    std::vector<std::string> verification_checks;  // names from element_test_check_names
};

// The closed-form checks an element-test case may ask for (app/element_test_checks.cpp
// holds what each computes).
inline const std::vector<std::string> element_test_check_names = {
    "critical_state_drained",  // modified Cam clay
    "undrained_path",          // modified Cam clay
    "critical_void_ratio",         // hypoplastic
    "isotropic_compression_line",  // hypoplastic
    "subloading_critical_state",     // subloading Cam clay: q / p' = M(theta) at the end
    "subloading_smooth_transition",  // subloading Cam clay, OCR > 1: no stiffness jump
    "subloading_reduces_to_mcc",     // subloading Cam clay against modified Cam clay
    "subloading_oedometer",          // subloading Cam clay: NCL slope, elastic unloading
    "small_strain_stiffness_decay",  // hardening soil small
    "e50_and_failure",               // hardening soil small
};

ElementTestCase read_element_test_case(const std::string& file);

}  // namespace pilempm::io
