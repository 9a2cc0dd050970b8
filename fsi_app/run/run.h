// SPDX-License-Identifier: BSD-2-Clause
/* A run of the scene the options database describes: its blocks, mesh, solver, the time loop
   with output and checkpoints, a restart, and what the run reports. */
#pragma once

#include <petscsys.h>

namespace fsi {

/* The whole run on PETSC_COMM_WORLD; an error names the option, file or cause that stopped it. */
PetscErrorCode RunScene();

} // namespace fsi
