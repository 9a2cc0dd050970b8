// SPDX-License-Identifier: BSD-2-Clause
#include "time_loop.h"

namespace fsi {

/* A Jacobian set up once for good (lag -1: a linear operator) must be rebuilt when dt changes. */
static PetscErrorCode RebuildLaggedOperator(SNES snes)
{
  PetscInt lag;

  PetscFunctionBegin;
  PetscCall(SNESGetLagJacobian(snes, &lag));
  if (lag == -1) PetscCall(SNESSetLagJacobian(snes, -2));
  PetscCall(SNESGetLagPreconditioner(snes, &lag));
  if (lag == -1) PetscCall(SNESSetLagPreconditioner(snes, -2));
  PetscFunctionReturn(0);
}

/* SNES's step-length test (-snes_stol) also ends a Newton iteration that stagnates far from
   its residual tolerance (a preconditioner too weak for the tangent): say so, with the numbers,
   rather than let CONVERGED_SNORM_RELATIVE pass for a converged state. */
static PetscErrorCode WarnIfStagnated(SNES snes, PetscReal t)
{
  const PetscReal *norms;
  PetscInt         n;
  PetscReal        fnorm, atol, rtol, stol;

  PetscFunctionBegin;
  PetscCall(SNESGetFunctionNorm(snes, &fnorm));
  PetscCall(SNESGetTolerances(snes, &atol, &rtol, &stol, nullptr, nullptr));
  PetscCall(SNESGetConvergenceHistory(snes, (PetscReal **)&norms, nullptr, &n));
  const PetscReal tol = PetscMax(atol, n > 0 ? rtol * norms[0] : 0.0);
  if (fnorm > 10 * tol)
    PetscCall(PetscPrintf(PetscObjectComm((PetscObject)snes), "warning: at t = %.4e Newton stopped on the step length (-snes_stol %g) with |F| = %.3e, %.3g times its tolerance %.3e: the state is not converged (a stronger preconditioner, or -snes_stol 0 to let Newton go on)\n", (double)t, (double)stol, (double)fnorm, (double)(fnorm / tol), (double)tol));
  PetscFunctionReturn(0);
}

/* From t to t + h.dt; on failure, two halves on the past states refined to h.dt / 2, after
   which the past states of step h.dt are shifted by the result. */
static PetscErrorCode Advance(const TimeLoop &loop, PetscReal t, PetscInt depth, Vec x, StepRecord &rec, PetscBool *ok)
{
  TimeHistory    &h  = *loop.history;
  const PetscReal dt = h.dt;
  Vec             x0;
  PetscInt        n, k;

  PetscFunctionBegin;
  PetscCall(VecDuplicate(x, &x0));
  PetscCall(VecCopy(x, x0));
  PetscCall(loop.setTime(t + dt));
  PetscCall(TimeHistoryExtrapolate(h, loop.predictorOrder, x));
  if (loop.predict) PetscCall(loop.predict(t + dt, x));
  PetscCall(SNESSolve(loop.snes, nullptr, x));
  PetscCall(SNESGetIterationNumber(loop.snes, &n));
  PetscCall(SNESGetLinearSolveIterations(loop.snes, &k));
  PetscCall(SNESGetConvergedReason(loop.snes, &rec.reason));
  if (rec.residual0 < 0) {
    const PetscReal *norms;
    PetscCall(SNESGetConvergenceHistory(loop.snes, (PetscReal **)&norms, nullptr, nullptr));
    rec.residual0 = norms[0];
  }
  rec.newton += n, rec.krylov += k;
  if (rec.reason == SNES_CONVERGED_SNORM_RELATIVE) PetscCall(WarnIfStagnated(loop.snes, t + dt));
  *ok = (PetscBool)(rec.reason > 0);
  PetscBool repeat = PETSC_FALSE;
  if (!*ok && loop.repair) PetscCall(loop.repair(rec.step, (PetscBool)(depth < loop.maxCuts), &repeat));
  if (*ok) PetscCall(TimeHistoryPush(h, x, t + dt));
  else if (repeat) {
    PetscCall(VecCopy(x0, x));
    PetscCall(Advance(loop, t, depth, x, rec, ok));
  } else if (depth < loop.maxCuts) {
    TimeHistory saved;
    PetscCall(PetscInfo(loop.snes, "step from t = %g with dt = %g failed (%s): two halves\n", (double)t, (double)dt, SNESConvergedReasons[rec.reason]));
    rec.cuts++;
    PetscCall(VecCopy(x0, x));
    PetscCall(TimeHistoryDuplicate(h, saved));
    PetscCall(TimeHistoryRefine(h, 2));
    PetscCall(RebuildLaggedOperator(loop.snes));
    PetscCall(Advance(loop, t, depth + 1, x, rec, ok));
    if (*ok) PetscCall(Advance(loop, t + dt / 2, depth + 1, x, rec, ok));
    PetscCall(TimeHistoryCopy(saved, h));
    PetscCall(TimeHistoryDestroy(saved));
    PetscCall(RebuildLaggedOperator(loop.snes));
    if (*ok) PetscCall(TimeHistoryPush(h, x, t + dt));
  }
  PetscCall(VecDestroy(&x0));
  PetscFunctionReturn(0);
}

PetscErrorCode RunTimeLoop(const TimeLoop &loop, PetscInt first, Vec x, std::vector<StepRecord> &records)
{
  PetscReal *norms;

  PetscFunctionBegin;
  PetscCall(SNESGetConvergenceHistory(loop.snes, &norms, nullptr, nullptr));
  if (!norms) PetscCall(SNESSetConvergenceHistory(loop.snes, nullptr, nullptr, PETSC_DECIDE, PETSC_TRUE)); /* |F_0| of each solve, PETSc's storage */
  for (PetscInt step = first + 1; step <= loop.steps; step++) {
    StepRecord     rec;
    PetscBool      ok;
    Phases         before, after;
    PetscLogDouble t0, t1;
    rec.step = step, rec.t = step * loop.history->dt;
    PetscCall(PetscTime(&t0));
    PetscCall(PhasesMeasure(PETSC_COMM_WORLD, 0, loop.splits, before));
    PetscCall(Advance(loop, (step - 1) * loop.history->dt, 0, x, rec, &ok));
    PetscCall(PetscTime(&t1));
    PetscCall(PhasesMeasure(PETSC_COMM_WORLD, t1 - t0, loop.splits, after));
    rec.phases = PhasesSince(before, after);
    records.push_back(rec);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s %" PetscInt_FMT "/%" PetscInt_FMT " t %.4e newton %" PetscInt_FMT " krylov %" PetscInt_FMT " %s%s (%.1f s, peak memory %.0f MiB)\n", loop.dynamic ? "step" : "load step", step, loop.steps, (double)rec.t, rec.newton, rec.krylov,
                            SNESConvergedReasons[rec.reason], rec.cuts ? " after halving the step" : "", rec.phases.total, rec.phases.peakMiB));
    if (!ok) break;
    PetscCall(loop.afterStep(step, rec.t, x));
  }
  PetscFunctionReturn(0);
}

} // namespace fsi
