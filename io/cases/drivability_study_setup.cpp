#include "io/cases/drivability_study_setup.hpp"

#include <stdexcept>

namespace pilempm::io {

void set_reference_energy(StudyLocation& l, const DrivabilityCase& c, double reference_energy) {
    l.setup.energy_plan_depth = l.record.driven_depth;
    l.setup.energy_plan_level.clear();
    for (double e : l.record.normalised_energy) l.setup.energy_plan_level.push_back(e * reference_energy / c.rated_energy);
}

StudyLocation build_study_location(const DrivabilityCase& c, const FieldRecord& r, double reference_energy) {
    if (r.driven_depth.size() < 2)
        throw std::invalid_argument("location " + r.location + ": fewer than two driven depths in the record");
    StudyLocation l;
    l.record = r;
    DrivabilityCase k = c;
    fem::PileSegment seg = c.segments.back();
    seg.length = r.final_penetration + c.study.stick_up;
    seg.outer_diameter = r.diameter;
    seg.wall_thickness = r.toe_wall;
    k.segments = {seg};
    l.cpt = coupling::interpret_cpt(r.cpt, c.cpt_options, c.soil.water_depth);
    k.soil = l.cpt.profile;
    k.start_depth = r.driven_depth.front();
    k.final_depth = r.driven_depth.back();
    l.setup = build_drivability_setup(k);
    l.measured.depth = r.driven_depth;
    l.measured.blows_per_m = r.blows_per_m;
    l.measured.cumulative_blows = r.cumulative_blows;
    set_reference_energy(l, c, reference_energy);
    return l;
}

}  // namespace pilempm::io
