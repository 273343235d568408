#include <sstream>

#include "fem/mesh/axisymmetric_mesher.hpp"
#include "fem/mesh/rod_mesh.hpp"
#include "io/yaml/case_error.hpp"
#include "io/cases/pile_wave_case.hpp"

namespace pilempm::io {

fem::PileWaveSetup build_pile_wave_setup(const PileWaveCase& c) {
    return build_pile_wave_setup(c, c.model, c.element_size);
}

fem::PileWaveSetup build_pile_wave_setup(const PileWaveCase& c, PileModel model,
                                              double element_size) {
    fem::PileWaveSetup s;
    const fem::PileGeometry geometry = fem::make_pile_geometry(c.segments, c.taper_ratio);
    s.mesh = model == PileModel::Rod
                 ? fem::mesh_rod(geometry, element_size)
                 : fem::mesh_axisymmetric_wall(geometry, element_size, c.radial_divisions,
                                               fem::default_pile_wall_geo());
    s.steel = c.steel;
    s.toe = c.toe;
    if (s.toe.condition == fem::ToeCondition::Dashpot && !c.toe_impedance_given)
        s.toe.impedance = geometry.area_at(0.0) * c.steel.youngs_modulus / c.steel.wave_speed();
    s.hammer = c.hammer;
    s.duration = c.duration;
    s.time_step = c.time_step;
    s.time_step_factor = c.time_step_factor;
    s.ram_element_size = element_size;
    s.gauge_depths = c.gauge_depths;
    s.snapshot_interval = c.snapshot_interval;
    if (c.time_step > 0.0) {
        const fem::ExplicitPile pile(s.mesh, s.steel, s.toe);
        const double stable = fem::pile_wave_stable_time_step(pile, s);
        if (c.time_step > stable) {
            std::ostringstream e, f;
            e << "a time step no larger than the stable one, " << stable << " s";
            f << c.time_step << " s";
            throw CaseError(c.file, c.line_of("simulation.time_step"), "simulation.time_step", e.str(), f.str());
        }
    }
    return s;
}

}  // namespace pilempm::io
