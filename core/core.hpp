#pragma once
// core: the vocabulary every library may include and nothing else: the conventions (units,
// signs, axes, Voigt order, the per-radian rule), tables of columns on their way to CSV,
// HDF5 and plots, and verification checks (a computed number against an independent
// reference with a stated tolerance). It depends on no other folder. linear_algebra/ (its
// own library, pilempm_linear_algebra) solves sparse systems through Trilinos.
#include "core/conventions.hpp"
#include "core/linear_algebra/sparse_linear_solver.hpp"
#include "core/table.hpp"
#include "core/verification_check.hpp"
#include "core/voigt.hpp"
