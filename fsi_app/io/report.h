// SPDX-License-Identifier: BSD-2-Clause
/* What a run did, for people and scripts: time per phase from PETSc's own log events, peak
   memory, and a JSON report (unknowns, Newton and Krylov iterations per step, results such as
   errors, phases, memory). */
#pragma once

#include "discretization/probes.h"
#include "io/phases.h"
#include <petscsnes.h>
#include <string>
#include <utility>
#include <vector>

namespace fsi {

/* What one time step (or load increment) did. */
struct StepRecord {
  PetscInt            step = 0;
  PetscReal           t    = 0;
  PetscInt            newton = 0, krylov = 0, cuts = 0; /* summed over every attempt */
  PetscReal           residual0 = -1; /* |F| at Newton's first iterate of the step's first attempt */
  SNESConvergedReason reason = SNES_CONVERGED_ITERATING;
  Phases              phases; /* of this step: seconds per phase, wall clock (total), peak memory so far */
};

struct RunReport {
  std::vector<std::pair<std::string, PetscInt>>              unknowns;
  std::vector<std::pair<std::string, std::vector<PetscInt>>> unknownsPerRank;
  std::vector<std::pair<std::string, PetscReal>> results;
  std::vector<std::pair<std::string, const Probes *>> series; /* probes' values over time, by field */
  std::vector<StepRecord>                        steps;
  PetscInt                                       restartedAt = -1; /* the checkpoint's step, -1: a fresh run */
  Phases                                         phases;
};

PetscErrorCode WriteReport(const char *file, MPI_Comm comm, const RunReport &r);

} // namespace fsi
