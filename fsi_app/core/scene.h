// SPDX-License-Identifier: BSD-2-Clause
/* A scene: which blocks it solves, on which mesh, over which time, and the files it writes.
   Each block reads its own options (core/block.h); these are the scene's, which every block
   may read. */
#pragma once

#include "core/time_history.h"
#include <map>
#include <string>
#include <vector>

namespace fsi {

struct Scene {
  std::vector<std::string> blocks; /* the blocks a scene solves (run/registry.h) */
  /* mesh */
  char      mesh[PETSC_MAX_PATH_LEN] = "meshes/cube_L0.msh";
  PetscInt  refine                   = 0;
  PetscInt  meshOrder                = 0;          /* the cells' geometry: 0 as the file is, 1 straight, 2 curved */
  PetscBool meshReorder              = PETSC_TRUE; /* the points numbered by RCM of the cells before distribution */
  /* time, or load increments in statics */
  PetscReal  dt = 0, tFinal = 0.01;
  PetscInt   loadSteps = 1, maxCuts = 4;
  PetscInt   maxWorkspaceRaises = 3; /* a direct solver out of workspace: its room doubled and the step repeated */
  PetscInt   predictorOrder = 1; /* Newton's first iterate from the past states (core/time_history.h) */
  TimeScheme scheme    = BACKWARD_EULER;
  PetscBool  keepConstant = PETSC_TRUE; /* the constant Jacobian blocks assembled once (core/constant_rows.h) */
  PetscBool  directAdd    = PETSC_TRUE; /* element matrices added into the CSR storage (discretization/csr_add.h) */
  /* verification: each block's manufactured solution */
  PetscBool mms = PETSC_FALSE;
  /* files */
  char     output[PETSC_MAX_PATH_LEN] = "", checkpoint[PETSC_MAX_PATH_LEN] = "", restart[PETSC_MAX_PATH_LEN] = "", report[PETSC_MAX_PATH_LEN] = "";
  PetscInt outputEvery = 1, checkpointEvery = 10, checkpointKeep = 3;
  /* the options that define the problem, the blocks' too, with their values: a restart must have the same */
  std::map<std::string, std::string> problem;

  PetscBool Dynamic() const { return (PetscBool)(dt > 0); }
  PetscInt  Steps() const { return Dynamic() ? (PetscInt)PetscFloorReal(tFinal / dt + 0.5) : loadSteps; } /* ReadScene checked: a whole number */
};

/* The scene's options; then the blocks read theirs (run/registry.h). */
PetscErrorCode ReadScene(Scene &sc);

} // namespace fsi
