#pragma once
// Runs the verification checks a case asks for, including the extra runs some need (the
// rod twin of an axisymmetric pile, the refined meshes of a convergence study).
#include <vector>

#include "coupling/pile_wave_verification.hpp"
#include "io/json_writer.hpp"
#include "io/pile_wave_case.hpp"

namespace pilempm::app {

std::vector<coupling::VerificationCheck> run_verification(const io::PileWaveCase& c,
                                                          const coupling::PileWaveSetup& setup,
                                                          const coupling::PileWaveResult& result,
                                                          io::JsonObject& details, bool quiet);

io::JsonObject verification_json(const io::CaseFile& c,
                                 const std::vector<coupling::VerificationCheck>& checks,
                                 const io::JsonObject& details);

}  // namespace pilempm::app
