/* Checkpoints: the state a run needs to continue exactly as if never stopped (step, time, the
   solution and the past states of the time scheme), in PETSc binary, written to a temporary
   file and renamed, so a crash while writing leaves the previous checkpoint intact. */
#pragma once

#include "solver/time_history.h"

namespace fsi {

struct CheckpointHeader {
  PetscInt  step = 0; /* completed steps */
  PetscReal t    = 0;
};

PetscErrorCode CheckpointWrite(const char *file, DM dm, const CheckpointHeader &c, Vec x, const TimeHistory &h);

/* Errors name the file and what does not match this run (ranks, unknowns, time scheme). */
PetscErrorCode CheckpointRead(const char *file, DM dm, CheckpointHeader &c, Vec x, TimeHistory &h);

} // namespace fsi
