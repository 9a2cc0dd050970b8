// SPDX-License-Identifier: BSD-2-Clause
/* The loop over time steps (dynamics) or load increments (statics), one nonlinear solve each.
   A step that fails (Newton diverged, an element inverted, the linear solver failed) is first
   mended where it can be (a direct solver given more workspace: the step repeated at its size),
   else retried as two half steps, recursively up to a limit, with the time scheme's past states
   interpolated to the finer step; the outer steps keep their size, so output times and
   checkpoints do not depend on the cuts. */
#pragma once

#include "io/report.h"
#include "core/time_history.h"
#include <functional>
#include <petscsnes.h>
#include <vector>

namespace fsi {

struct TimeLoop {
  SNES                                       snes;
  TimeHistory                               *history; /* h.dt is the step; no past states in statics */
  PetscInt                                   steps, maxCuts;
  PetscInt                                   predictorOrder; /* Newton's first iterate: the past states extrapolated (core/time_history.h) */
  PetscBool                                  dynamic;
  std::vector<std::string>                   splits;    /* named splits whose set-up each step's phases report */
  std::function<PetscErrorCode(PetscReal t)> setTime;   /* loads at time (or load fraction) t */
  std::function<PetscErrorCode(PetscReal t, Vec x)> predict; /* the first iterate of the step to t (may be empty) */
  std::function<PetscErrorCode(PetscInt step, PetscReal t, Vec x)> afterStep; /* output, checkpoints */
  std::function<PetscErrorCode(PetscInt step, PetscBool halving, PetscBool *repeat)> repair; /* after a failed step, before it is halved (halving) or not: mend what failed; *repeat: try it at its size again (may be empty) */
};

/* Steps first+1 .. loop.steps from state x at step `first`; one record per step attempted.
   Stops at the first step that fails after every cut (its record has reason < 0). */
PetscErrorCode RunTimeLoop(const TimeLoop &loop, PetscInt first, Vec x, std::vector<StepRecord> &records);

} // namespace fsi
