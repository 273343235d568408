#pragma once
// The blows of a coupled driving run (`pilempm run` of an `analysis: mpm` case with a
// driving stage), read back from its output folder as a target of the fast path's
// calibration: blows.csv for the sets and depths, history.csv for the head's record.
#include <string>

#include "coupling/wave_equation/fast_path_calibration.hpp"

namespace pilempm::io {

// The run's blows after the first `skip_blows`: their mean set, ENTHRU and depth before
// the blow, and the head record (force, velocity down) of the last of them, timed from
// its start. A missing folder, file or column, or too few blows, is a CaseError naming
// the case file and key (`where`) or the CSV file.
coupling::CalibrationTarget read_coupled_run(const std::string& folder, int skip_blows, const std::string& case_file,
                                             int line, const std::string& where);

}  // namespace pilempm::io
