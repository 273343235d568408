#pragma once
// fem: the steel pile as a deformable Lagrangian body and what strikes it.
// - mesh/: pile geometry (segments, tapers), rod meshes and gmsh axisymmetric wall meshes.
// - elements/: 2-node rods and 4-node axisymmetric quads (lumped mass, linear elastic).
// - dynamics/: explicit central-difference dynamics of the pile with its own stable step
//   (the coupled model subcycles it), strain-gauge sections, and PileSoilReaction: what
//   any soil does to the pile (Smith springs, or the MPM contact).
// - hammer/: prescribed pulses and the ram-cushion-helmet chain, and the blow stepper that
//   advances pile, hammer and soil together.
// - pile_wave/: the pile wave analysis (one blow) and its closed-form checks.
// fem knows nothing of the MPM soil; coupling joins them.
#include "fem/dynamics/explicit_pile.hpp"
#include "fem/dynamics/pile_soil_reaction.hpp"
#include "fem/dynamics/section_gauge.hpp"
#include "fem/hammer/blow_stepper.hpp"
#include "fem/hammer/hammer.hpp"
#include "fem/mesh/axisymmetric_mesher.hpp"
#include "fem/mesh/rod_mesh.hpp"
#include "fem/pile_wave/pile_wave.hpp"
