// SPDX-License-Identifier: BSD-2-Clause
/* Seconds per phase of a run or of one time step, from PETSc's own log events, and the peak
   memory: what the report and the per-step progress print. */
#pragma once

#include <petscsys.h>
#include <string>
#include <utility>
#include <vector>

namespace fsi {

struct Phases {
  double assembly = 0; /* residual and Jacobian (SNESFunctionEval + SNESJacobianEval) */
  double setup    = 0; /* preconditioner set-up (PCSetUp) */
  double krylov   = 0; /* Krylov iterations (KSPSolve; the outer PCSetUp is not inside it, but inner solvers
                          set up at first use, as PCFIELDSPLIT's, are: their set-up counts in both) */
  std::vector<std::pair<std::string, double>> splitSetUp; /* of each named split (in setup) */
  double total    = 0; /* the time loop, wall clock */
  double peakMiB  = 0; /* largest resident set, summed over ranks */
};

/* Start PETSc's event log if -log_view has not (the phases read it). */
PetscErrorCode PhasesBegin();
/* `splits`: the named splits whose set-up (log event SplitSetUp_<name>) is reported, if run.
   Collective: each phase is the slowest rank's. */
PetscErrorCode PhasesMeasure(MPI_Comm comm, double total, const std::vector<std::string> &splits, Phases &p);
/* The phases of an interval: `now` less `before` (measured at its start), the peak memory kept. */
Phases PhasesSince(const Phases &before, const Phases &now);

} // namespace fsi
