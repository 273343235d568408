#pragma once
// mpm: the soil as a Material Point Method continuum (explicit, updated Lagrangian, MUSL
// with a FLIP/PIC blend or APIC; plane strain, axisymmetric per radian, 3D).
// - grid/: the rectilinear background grid (node data as structure of arrays) and the
//   linear, uGIMP and CPDI shape functions (axisymmetric forms after Nairn & Guilkey).
// - points/: material points as structure of arrays.
// - solver/: one explicit step (scatter, grid update with supports, dashpots and walls,
//   gather, remap, objective stress update by each material in one batch); saturated soil
//   as single-point v-w (solid and water velocity fields, semi-implicit Darcy drag).
// - implicit/: the consolidation step (Biot u-p on the grid, Trilinos through core).
// - setup/: filling regions with points, boundaries on grid planes, K0 stress.
// - materials/: the constitutive models (a batched pure update of stress and state), their
//   factory from parameters, element tests and their closed-form checks; pore water.
// - analysis/, verification/: post-processing (collapse deposits) and closed-form checks.
// mpm knows nothing of the FE pile; coupling joins them.
#include "mpm/implicit/consolidation.hpp"
#include "mpm/materials/material_factory.hpp"
#include "mpm/setup/model_setup.hpp"
#include "mpm/solver/mpm_solver.hpp"
