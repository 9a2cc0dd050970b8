// SPDX-License-Identifier: BSD-2-Clause
/* What a run did, for people and scripts: time per phase from PETSc's own log events, peak
   memory, and a JSON report (unknowns, Newton and Krylov iterations per step, results such as
   errors, phases, memory). */
#pragma once

#include "discretization/probes.h"
#include "solver/time_loop.h"
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
/* `splits`: the named splits whose set-up (log event SplitSetUp_<name>) is reported, if run. */
PetscErrorCode PhasesMeasure(MPI_Comm comm, double total, const std::vector<std::string> &splits, Phases &p);

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
