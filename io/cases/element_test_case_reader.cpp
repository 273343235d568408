#include "io/cases/element_test_case.hpp"

#include "io/yaml/yaml_reader.hpp"

namespace pilempm::io {

namespace {

ElementTestInput read_test(MapReader m, int index, const MaterialInput& material) {
    ElementTestInput t;
    t.type = m.choice("type", {"triaxial_drained", "triaxial_undrained", "oedometer", "isotropic"});
    t.name = m.text_or("name", t.type + "_" + std::to_string(index + 1));
    // Targets: axial strain (triaxial; negative for extension, alternating for cycles),
    // axial stress (oedometer) or mean stress (isotropic), compression positive.
    const bool triaxial = t.type.rfind("triaxial", 0) == 0;
    // Triaxial tests are strain-controlled unless control: stress, when the targets are
    // deviator stresses q (Pa, negative in extension), as in a cyclic triaxial test.
    const bool deviator = triaxial && m.choice_or("control", "strain", {"strain", "stress"}) == "stress";
    const bool strain = triaxial && !deviator;
    const auto targets = m.numbers("path", {strain     ? "axial strains (compression +)"
                                            : deviator ? "deviator stresses q in Pa (extension -)"
                                                       : "stresses in Pa (compression +)",
                                            [triaxial](double x) { return triaxial || x > 0.0; }});
    if (targets.empty()) m.fail("path", "at least one target", "an empty list");
    const int steps = m.integer_or("steps_per_leg", 500, 1);
    if (m.has("void_ratio")) {
        if (!mpm::has_void_ratio(material)) m.fail("void_ratio", "a material with a void ratio (modified_cam_clay, hypoplastic)", material.model);
        t.void_ratio = m.number("void_ratio", positive("the void ratio this test starts from"));
    }
    for (double target : targets) {
        mpm::ElementLeg leg;
        leg.axial_target = target;
        leg.steps = steps;
        if (deviator) leg.axial = mpm::ElementLeg::Deviator;
        if (t.type == "triaxial_drained") leg.lateral = mpm::ElementLeg::LateralStress;
        else if (t.type == "triaxial_undrained") leg.lateral = mpm::ElementLeg::Undrained;
        else {
            leg.axial = mpm::ElementLeg::AxialStress;
            leg.lateral = t.type == "oedometer" ? mpm::ElementLeg::LateralStrainZero
                                                : mpm::ElementLeg::LateralStressEqualsAxial;
        }
        t.legs.push_back(leg);
    }
    m.finish();
    return t;
}

}  // namespace

ElementTestCase read_element_test_case(const std::string& file) {
    MapReader root = load_yaml_file(file);
    ElementTestCase c;
    read_case_header(root, c, file, "element_test");
    c.material = read_material(root.map("material"), false);
    {
        MapReader s = root.map("initial_stress");
        c.axial_stress = s.number("axial", positive("effective axial stress in Pa (compression +)"));
        c.lateral_stress = s.number_or("lateral", c.axial_stress, positive("effective lateral stress in Pa (compression +)"));
        s.finish();
    }
    const auto tests = root.maps("tests");
    if (tests.empty()) root.fail("tests", "at least one test", "none");
    for (std::size_t k = 0; k < tests.size(); ++k) c.tests.push_back(read_test(tests[k], static_cast<int>(k), c.material));
    if (auto o = root.optional_map("output")) {
        c.plots = o->boolean_or("plots", true);
        o->finish();
    }
    if (auto v = root.optional_map("verification")) {
        c.verification_checks = v->words("checks", element_test_check_names);
        v->finish();
    }
    root.finish();
    return c;
}

}  // namespace pilempm::io
