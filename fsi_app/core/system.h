// SPDX-License-Identifier: BSD-2-Clause
/* The nonlinear system of a scene on one DM: the sum of the residuals and Jacobians of the
   blocks the scene names (structure, fluid, geometry, coupling), each adding its
   rows into the local vectors and the matrix. The essential values are inserted once, at the
   time of the step being solved, before any block reads the state. */
#pragma once

#include "core/block.h"
#include "core/constant_rows.h"
#include <vector>

namespace fsi {

struct System {
  std::vector<Block *> blocks;
  PetscReal            time = 0; /* of the step being solved (statics: the load fraction) */
  PetscBool            laidOut = PETSC_FALSE; /* the matrix's pattern is set (SystemCreateMatrix) */
  SNES                 snes    = nullptr;     /* told of a residual with no value (an inverted cell on any rank) */
  std::vector<PetscLogEvent> residualEvent, jacobianEvent; /* per block: Residual_<block>, Jacobian_<block> */
  PetscBool                  keepConstant = PETSC_TRUE;   /* the constant blocks' values kept (-jacobian_keep_constant) */
  PetscBool                  directAdd    = PETSC_TRUE;   /* element matrices into P's storage (-jacobian_direct_add) */
  ConstantRows               constant;
};

/* The Jacobian's matrix, without storage yet: the first Jacobian evaluation lays it out with
   exactly the entries the blocks insert (core/sparsity.h; DMCreateMatrix's pattern couples
   every field at a point with every other: the geometry's rows with the velocity, the
   multiplier's with all the fluid's and the wall's: 65 % zeros on the coupled tube). Later
   insertions outside the pattern are errors. Block size 3 when every node carries one
   3-component field (the wall alone: AMG aggregates nodes), else 1. */
PetscErrorCode SystemCreateMatrix(DM dm, Mat *J);

/* The system's residual and Jacobian become dm's DMSNES local callbacks; `s` must outlive dm.
   The blocks with a constant Jacobian are assembled at the first Jacobian only; later ones
   start from their kept values. Each block's share is logged (-log_view: Residual_<block>,
   Jacobian_<block>, ConstantRows for copying the kept values back, and AssembleJacobian for
   the matrix's assembly across ranks). */
PetscErrorCode SystemAttach(DM dm, System &s);

} // namespace fsi
