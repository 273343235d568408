#pragma once
// coupling: what joins the FE pile and the MPM soil, and what drives a run.
// - driver/: the stage driver (stages, loads switched per stage with stage-relative times,
//   recorders, snapshot clock, stop requests by signal, checkpoint of the whole run state)
//   that every staged run goes through and the coupled model extends.
// - wave_equation/: the 1D fast path: SRD methods, Smith soil on the FE pile, driving to a
//   steady set and the drivability study.
// - contact/: the FE pile in the MPM soil: point-to-segment penalty contact with Coulomb
//   friction, the field cut along the pile's wall, the pile subcycled in each soil step.
#include "coupling/contact/coupled_pile.hpp"
#include "coupling/contact/pile_recorder.hpp"
#include "coupling/driver/stage_driver.hpp"
#include "coupling/wave_equation/drivability.hpp"
