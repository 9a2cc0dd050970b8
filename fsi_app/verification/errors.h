// SPDX-License-Identifier: BSD-2-Clause
/* Errors of a P1 or P2 field against an exact solution: L2 norm and H1 seminorm, with the
   norms of the exact solution for relative values, integrated by the element's own loops over
   the current configuration (the mesh moved by the P2 displacement `mesh`, if given). */
#pragma once

#include "discretization/cells.h"
#include "io/report.h"

namespace fsi {

/* value u and gradient G[i*3+j] = du_i/dx_j at x and time t (a scalar field: u[0], G[0..2]) */
using ExactSolution = void (*)(const PetscReal x[3], PetscReal t, const void *ctx, PetscReal u[3], PetscReal G[9]);

/* u = 0: ComputeErrors() then gives the norms of the discrete field. */
void ZeroSolution(const PetscReal x[3], PetscReal t, const void *ctx, PetscReal u[3], PetscReal G[9]);

struct Errors {
  PetscReal l2, h1, l2Exact, h1Exact; /* ||u_h - u||, |u_h - u|_1, ||u||, |u|_1 */
};

/* X is global; its essential values are inserted at time t. */
PetscErrorCode ComputeErrors(DM dm, const FieldCells &cells, Vec X, PetscReal t, ExactSolution exact, const void *ctx, Errors &e, const FieldCells *mesh = nullptr);

/* Print "<what> L2 error ... relative ..." and the H1 line, and add <what>_l2_error, ... to the
   report ("" for the block's main field: l2_error, ...). */
PetscErrorCode ReportErrors(const char *what, const Errors &e, RunReport &report);

} // namespace fsi
