#pragma once
// Runs the verification checks a case asks for, including the extra runs some need (the
// rod twin of an axisymmetric pile, the refined meshes of a convergence study).
#include <vector>

#include "fem/pile_wave/pile_wave_verification.hpp"
#include "io/writers/json_writer.hpp"
#include "io/cases/pile_wave_case.hpp"

namespace pilempm::app {

std::vector<VerificationCheck> run_verification(const io::PileWaveCase& c,
                                                          const fem::PileWaveSetup& setup,
                                                          const fem::PileWaveResult& result,
                                                          io::JsonObject& details, bool quiet);

io::JsonObject verification_json(const io::CaseFile& c,
                                 const std::vector<VerificationCheck>& checks,
                                 const io::JsonObject& details);

}  // namespace pilempm::app
