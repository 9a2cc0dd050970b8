// SPDX-License-Identifier: BSD-2-Clause
#include "solver.h"
#include "facsi/fluid_pc.h"
#include <algorithm>
#include <string>
#include <vector>

namespace fsi {

/* A block's rows without a diagonal entry stop PETSc's default preconditioner (ILU, or block
   Jacobi with ILU) at its first factorization: a scene without a solver is told which to add
   before its first step. */
static PetscErrorCode RefuseDefaultPC(KSP ksp, const Blocks &b)
{
  const char *prefix;
  PetscBool   given;
  const auto  blk = std::find_if(b.list.begin(), b.list.end(), [](const Block *x) { return x->RowsWithoutDiagonal(); });

  PetscFunctionBegin;
  if (blk == b.list.end()) PetscFunctionReturn(0);
  PetscCall(KSPGetOptionsPrefix(ksp, &prefix));
  PetscCall(PetscOptionsHasName(nullptr, prefix, "-pc_type", &given));
  PetscCheck(given, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG,
             "-pc_type: not given, and PETSc's default (ILU) cannot factor the rows of the %s block (they have no diagonal entry): choose a solver, e.g. -options_file scenes/fsi_mumps.opts (MUMPS) or scenes/fsi_facsi.opts (FaCSI with GDSW)", (*blk)->Name());
  PetscFunctionReturn(0);
}

/* Newton + the KSP/PC of the options database. A dynamic scene of linear blocks factors its
   operator once; rows with an energy take the critical-point line search (it does not reject
   good full Newton steps of stiff volumetric laws: arterial wall 7 -> 3 steps), the others
   PETSc's default backtracking on the residual norm. A single block configures the whole PC
   (gdsw: the wall's subdomains); several split it by name. */
PetscErrorCode CreateSolver(const Scene &sc, DM dm, const Blocks &b, SNES *snes)
{
  Mat       J;
  KSP       ksp;
  PC        pc;
  PetscBool linear = PETSC_TRUE, energy = PETSC_TRUE;

  PetscFunctionBegin;
  for (const Block *blk : b.list) linear = (PetscBool)(linear && blk->Linear()), energy = (PetscBool)(energy && blk->HasEnergy());
  PetscCall(SNESCreate(PETSC_COMM_WORLD, snes));
  PetscCall(SNESSetDM(*snes, dm));
  PetscCall(SystemCreateMatrix(dm, &J));
  PetscCall(SNESSetJacobian(*snes, J, J, nullptr, nullptr));
  if (linear && sc.Dynamic()) {
    PetscCall(SNESSetLagJacobian(*snes, -2));
    PetscCall(SNESSetLagJacobianPersists(*snes, PETSC_TRUE));
    PetscCall(SNESSetLagPreconditioner(*snes, -2));
    PetscCall(SNESSetLagPreconditionerPersists(*snes, PETSC_TRUE));
  }
  if (energy) {
    SNESLineSearch ls;
    PetscCall(SNESGetLineSearch(*snes, &ls));
    PetscCall(SNESLineSearchSetType(ls, SNESLINESEARCHCP));
  }
  PetscCall(SNESGetKSP(*snes, &ksp));
  PetscCall(RefuseDefaultPC(ksp, b));
  /* a Krylov solve that needs more iterations has failed (an indefinite tangent far from the
     solution): the step is halved instead of iterating for minutes (PETSc's default is 10000) */
  PetscCall(KSPSetTolerances(ksp, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, 500));
  PetscCall(SNESSetFromOptions(*snes));
  PetscCall(KSPGetPC(ksp, &pc));
  if (b.list.size() == 1) {
    MatNullSpace nsp;
    PetscCall(b.list[0]->ConfigurePC(dm, pc, &nsp));
    if (nsp) PetscCall(MatSetNearNullSpace(J, nsp));
    PetscCall(MatNullSpaceDestroy(&nsp));
  } else PetscCall(SetNamedSplits(*snes, dm, b.Splits()));
  PetscCall(MatDestroy(&J));
  PetscFunctionReturn(0);
}

/* A factorization whose solve failed: its KSP, PC, and error reduced over the ranks. */
struct FailedFactor {
  KSP            ksp;
  PC             pc;
  MatFactorError error;
};

/* The factorizations that made a KSP fail, through nested field splits and FaCSI's fluid step.
   Every step is reduced over the ranks: a factor fails on some of them only, and all of them
   must walk the same splits. */
static PetscErrorCode FailedFactors(KSP ksp, std::vector<FailedFactor> &found)
{
  KSPConvergedReason reason;
  PC                 pc;
  PetscBool          split, facsi, factor;
  PetscMPIInt        failed;
  MPI_Comm           comm = PetscObjectComm((PetscObject)ksp);

  PetscFunctionBegin;
  PetscCall(KSPGetConvergedReason(ksp, &reason));
  failed = reason == KSP_DIVERGED_PC_FAILED;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MAX, comm));
  if (!failed) PetscFunctionReturn(0);
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCFIELDSPLIT, &split));
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCFACSIFLUID, &facsi));
  PetscCall(PetscObjectTypeCompareAny((PetscObject)pc, &factor, PCLU, PCCHOLESKY, ""));
  if (split) {
    KSP     *sub;
    PetscInt n;
    PetscCall(PCFieldSplitGetSubKSP(pc, &n, &sub));
    for (PetscInt i = 0; i < n; i++) PetscCall(FailedFactors(sub[i], found));
    PetscCall(PetscFree(sub));
  } else if (facsi) {
    KSP inner;
    PetscCall(PCFaCSIFluidGetKSP(pc, &inner));
    if (inner) PetscCall(FailedFactors(inner, found));
  } else if (factor) {
    Mat            F;
    MatFactorError err;
    PetscCall(PCFactorGetMatrix(pc, &F));
    PetscCall(MatFactorGetError(F, &err));
    PetscMPIInt e = (PetscMPIInt)err;
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &e, 1, MPI_INT, MPI_MAX, comm));
    if (e) found.push_back({ksp, pc, (MatFactorError)e});
  }
  PetscFunctionReturn(0);
}

static std::string Prefix(KSP ksp)
{
  const char *prefix;
  return KSPGetOptionsPrefix(ksp, &prefix) || !prefix ? std::string() : std::string(prefix);
}

static PetscBool IsMUMPS(PC pc)
{
  MatSolverType solver;
  return (PetscBool)(!PCFactorGetMatSolverType(pc, &solver) && solver && !strcmp(solver, MATSOLVERMUMPS));
}

/* Which factorization made a KSP fail, as a sentence with its cure. */
static PetscErrorCode FactorFailure(KSP ksp, std::string *why)
{
  std::vector<FailedFactor> found;
  MatSolverType             solver;

  PetscFunctionBegin;
  PetscCall(FailedFactors(ksp, found));
  if (found.empty()) PetscFunctionReturn(0);
  const FailedFactor &f   = found.front();
  const std::string   pre = Prefix(f.ksp);
  PetscCall(PCFactorGetMatSolverType(f.pc, &solver));
  if (f.error == MAT_FACTOR_OUTMEMORY) *why = "the factorization of -" + pre + "pc_type ran out of workspace" + (IsMUMPS(f.pc) ? " (MUMPS: raise -" + pre + "mat_mumps_icntl_14, the percent added to its analysis' estimate, or -max_workspace_raises)" : "");
  else if (f.error == MAT_FACTOR_STRUCT_ZEROPIVOT || f.error == MAT_FACTOR_NUMERIC_ZEROPIVOT) *why = "the factorization of -" + pre + "pc_type met a zero pivot: that operator is singular (are its rigid or constant modes fixed by a condition?)";
  else *why = "the factorization of -" + pre + "pc_type failed in " + solver;
  PetscFunctionReturn(0);
}

PetscErrorCode RepairFactors(SNES snes, PetscInt step, PetscBool halving, PetscInt *raisesLeft, PetscBool *repeat)
{
  SNESConvergedReason       reason;
  KSP                       ksp;
  std::vector<FailedFactor> found;

  PetscFunctionBegin;
  *repeat = PETSC_FALSE;
  PetscCall(SNESGetConvergedReason(snes, &reason));
  if (reason != SNES_DIVERGED_LINEAR_SOLVE) PetscFunctionReturn(0);
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(FailedFactors(ksp, found));
  for (const FailedFactor &f : found) {
    if (f.error != MAT_FACTOR_OUTMEMORY || !IsMUMPS(f.pc) || *raisesLeft == 0) continue;
    const std::string pre = Prefix(f.ksp), name = "-" + pre + "mat_mumps_icntl_14";
    Mat               F;
    PetscInt          was;
    PetscCall(PCFactorGetMatrix(f.pc, &F));
    PetscCall(MatMumpsGetIcntl(F, 14, &was));
    const PetscInt now = was > 0 ? 2 * was : 20;
    PetscCall(PetscOptionsSetValue(nullptr, name.c_str(), std::to_string(now).c_str()));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "step %" PetscInt_FMT ": the factorization of -%spc_type ran out of workspace: %s raised from %" PetscInt_FMT " to %" PetscInt_FMT " (MUMPS's room beyond its analysis' estimate, in percent), and the step repeated\n", step, pre.c_str(), name.c_str(), was, now));
    *repeat = PETSC_TRUE;
  }
  if (*repeat) (*raisesLeft)--;
  if (!*repeat && !halving) PetscFunctionReturn(0); /* the run stops: CheckFinished() reads the failed factors */
  for (const FailedFactor &f : found) {
    /* a new factor: its KSP's next solve analyses the operator again and reads the options (a
       factor kept by a lagged Jacobian too) */
    Mat A, P;
    PetscCall(KSPGetOperators(f.ksp, &A, &P));
    PetscCall(PetscObjectReference((PetscObject)A));
    PetscCall(PetscObjectReference((PetscObject)P));
    PetscCall(PCReset(f.pc));
    PetscCall(KSPSetOperators(f.ksp, A, P));
    PetscCall(MatDestroy(&A));
    PetscCall(MatDestroy(&P));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CheckFinished(const Scene &sc, const Blocks &b, SNES snes, const RunReport &report)
{
  SNESConvergedReason reason = report.steps.empty() ? SNES_CONVERGED_ITERATING : report.steps.back().reason;
  const PetscInt      step   = report.steps.empty() ? 0 : report.steps.back().step;
  char                cure[160]; /* what to change: the load increments (statics) or the time step */
  std::string         cause;

  PetscFunctionBegin;
  if (sc.Dynamic()) PetscCall(PetscSNPrintf(cure, sizeof(cure), "reduce the time step (-dt %g now) or allow more halvings (-max_step_cuts %" PetscInt_FMT " now)", (double)sc.dt, sc.maxCuts));
  else PetscCall(PetscSNPrintf(cure, sizeof(cure), "apply the load in more increments (-structure_load_steps %" PetscInt_FMT " now) or allow more halvings (-max_step_cuts %" PetscInt_FMT " now)", sc.loadSteps, sc.maxCuts));
  if (reason == SNES_DIVERGED_FUNCTION_DOMAIN || reason == SNES_DIVERGED_LINE_SEARCH) { /* the line search may end on a point with no value */
    PetscMPIInt rank, first = 0, any;
    PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
    for (const Block *blk : b.list)
      if (cause.empty()) cause = blk->InvertedCause();
    PetscMPIInt mine = cause.empty() ? PETSC_MPI_INT_MAX : rank;
    PetscCallMPI(MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD)); /* the cause as the first rank that saw it says */
    if (reason == SNES_DIVERGED_FUNCTION_DOMAIN || any != PETSC_MPI_INT_MAX) {
      first   = any == PETSC_MPI_INT_MAX ? 0 : any;
      int len = (int)cause.size();
      PetscCallMPI(MPI_Bcast(&len, 1, MPI_INT, first, PETSC_COMM_WORLD));
      cause.resize(len);
      PetscCallMPI(MPI_Bcast(&cause[0], len, MPI_CHAR, first, PETSC_COMM_WORLD));
      SETERRQ(PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "Newton stopped in step %" PetscInt_FMT ": %s in every step the line search tried, also on the step halved %" PetscInt_FMT " times; %s", step, cause.empty() ? "the residual had no value" : cause.c_str(), sc.maxCuts, cure);
    }
  }
  if (reason == SNES_DIVERGED_LINEAR_SOLVE) {
    KSP                ksp;
    KSPConvergedReason kreason;
    PetscCall(SNESGetKSP(snes, &ksp));
    PetscCall(KSPGetConvergedReason(ksp, &kreason));
    PetscCall(FactorFailure(ksp, &cause));
    PetscCheck(cause.empty(), PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "the linear solver failed in step %" PetscInt_FMT ": %s", step, cause.c_str());
    SETERRQ(PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "the linear solver failed in step %" PetscInt_FMT " (%s, also on the step halved %" PetscInt_FMT " times); see -ksp_monitor_true_residual; CG needs a symmetric preconditioner (PCASM: -pc_asm_type basic); -pc_type lu -pc_factor_mat_solver_type mumps tells whether the preconditioner is the cause", step, KSPConvergedReasons[kreason], sc.maxCuts);
  }
  PetscCheck(reason >= 0, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "Newton did not converge in step %" PetscInt_FMT " (%s, also on the step halved %" PetscInt_FMT " times); see -snes_monitor, or %s", step, SNESConvergedReasons[reason], sc.maxCuts, cure);
  PetscFunctionReturn(0);
}

} // namespace fsi
