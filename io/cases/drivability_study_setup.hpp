#pragma once
// One location of a drivability study made into a drivability setup: the case's pile with
// the location's diameter, toe wall and length (final penetration + stick-up), the soil
// from its CPT, the energy plan from its record (normalised energy x reference energy),
// driven over the depths the record covers.
#include "coupling/wave_equation/field_comparison.hpp"
#include "io/cases/drivability_case.hpp"
#include "io/cases/field_records.hpp"

namespace pilempm::io {

struct StudyLocation {
    FieldRecord record;
    coupling::CptInterpretation cpt;
    coupling::MeasuredDriving measured;
    coupling::DrivabilitySetup setup;
};

StudyLocation build_study_location(const DrivabilityCase& c, const FieldRecord& r, double reference_energy);

// The plan's energy fractions for another reference energy (J).
void set_reference_energy(StudyLocation& l, const DrivabilityCase& c, double reference_energy);

}  // namespace pilempm::io
