#pragma once
// io: everything that touches files. Physics never does.
// - yaml/: strict YAML reading (unknown keys are errors; file, line, key, expected, found).
// - cases/: the case file of each analysis, validated into SI structs, and the builders
//   that turn a case into a model and a run.
// - writers/: CSV, JSON, VTK (.vtu + .pvd), plots, terminal progress, the staged output
//   folder (renamed into place only when complete), and the run output of the driver.
// - hdf5/: HDF5 results and checkpoints (the whole run state, bit for bit).
#include "io/cases/mpm_run_builder.hpp"
#include "io/hdf5/run_checkpoint.hpp"
#include "io/writers/mpm_run_output.hpp"
