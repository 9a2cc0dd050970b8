// SPDX-License-Identifier: BSD-2-Clause
/* First level: exact (or inexact, by options) solves on the overlapping subdomains
   Omega_i^delta, sum_i R_i^T A_i^{-1} R_i, or its restricted variant that prolongates each
   correction only on a nonoverlapping partition (each node goes to the subdomain of smallest
   id that contains it in Omega~). Also the set-up of every local factorisation (these and the
   interiors of the harmonic extension): Cholesky only where it can work, and a singular local
   matrix stops the set-up with a sentence instead of a NaN in the first application. */
#include "gdswimpl.h"
#include <algorithm>
#include <string>

using gdsw::LocalMatrix;
using gdsw::Subdomain;

static const char *const LocalMatrixNames[] = {"overlapping", "interior"};

/* Necessary for Cholesky: a positive diagonal (a saddle point's zero block, a zero row, a
   negative stabilisation fail it), and symmetry. Symmetry of the first values was decided on
   all subdomain matrices at once (PC_GDSW::symmetric); new values with the same pattern (a
   Newton tangent that gains convection) are checked again here. */
static PetscErrorCode MayBeSPD(PC pc, Mat A, PetscBool *spd)
{
  Vec       d;
  PetscReal min, norm;

  PetscFunctionBegin;
  PetscCall(MatCreateVecs(A, &d, nullptr));
  PetscCall(MatGetDiagonal(A, d));
  PetscCall(VecMin(d, nullptr, &min));
  PetscCall(VecDestroy(&d));
  *spd = (PetscBool)(min > 0);
  if (*spd && pc->setupcalled && pc->flag == SAME_NONZERO_PATTERN) {
    PetscCall(MatNorm(A, NORM_INFINITY, &norm));
    PetscCall(MatIsSymmetric(A, 1e-12 * norm, spd));
  }
  PetscFunctionReturn(0);
}

/* LU with the solver asked for, unless it only does Cholesky (CHOLMOD): then UMFPACK. */
static PetscErrorCode SwitchToLU(KSP ksp)
{
  PC            pc;
  Mat           A;
  MatSolverType asked;
  char          solver[64] = "";

  PetscFunctionBegin;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(KSPGetOperators(ksp, &A, nullptr));
  PetscCall(PCFactorGetMatSolverType(pc, &asked));
  if (asked && strcmp(asked, MATSOLVERCHOLMOD)) PetscCall(PetscStrncpy(solver, asked, sizeof(solver)));
#if defined(PETSC_HAVE_SUITESPARSE)
  else PetscCall(PetscStrncpy(solver, MATSOLVERUMFPACK, sizeof(solver)));
#endif
  PetscCall(PetscObjectReference((PetscObject)A));
  PetscCall(KSPReset(ksp));
  PetscCall(KSPSetOperators(ksp, A, A));
  PetscCall(MatDestroy(&A));
  PetscCall(PCSetType(pc, PCLU));
  if (solver[0]) PetscCall(PCFactorSetMatSolverType(pc, solver));
  PetscFunctionReturn(0);
}

/* A Cholesky factorisation that may fail (symmetric, positive diagonal, yet indefinite: a
   hyperelastic tangent under extreme compression). CHOLMOD raises an error rather than a PC
   failure, and prints its warnings itself, before PETSc sees its status, unless its print
   level (an option of the factor, read at the symbolic factorisation) is at most 1: errors
   only. The user's own -mat_cholmod_print is left alone. */
static PetscErrorCode TryCholesky(KSP ksp, PetscBool *ok)
{
  PC             pc;
  PCFailedReason reason = PC_NOERROR;
  MatSolverType  solver;
  const char    *prefix;
  char           name[256];
  PetscBool      quiet = PETSC_FALSE, set;
  PetscOptions   options = ((PetscObject)ksp)->options;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCFactorGetMatSolverType(pc, &solver));
  if (solver && !strcmp(solver, MATSOLVERCHOLMOD)) {
    PetscCall(PCGetOptionsPrefix(pc, &prefix));
    PetscCall(PetscSNPrintf(name, sizeof(name), "-%smat_cholmod_print", prefix ? prefix : ""));
    PetscCall(PetscOptionsHasName(options, nullptr, name, &set));
    quiet = (PetscBool)!set;
  }
  if (quiet) PetscCall(PetscOptionsSetValue(options, name, "1"));
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  ierr = KSPSetUp(ksp);
  PetscCall(PetscPopErrorHandler());
  if (quiet) PetscCall(PetscOptionsClearValue(options, name));
  if (!ierr) PetscCall(PCGetFailedReason(pc, &reason));
  *ok = (PetscBool)(!ierr && reason == PC_NOERROR);
  PetscFunctionReturn(0);
}

/* Why a set-up factorisation is unusable, or nullptr: the solver's own report (a zero pivot of
   PETSc's LU, MUMPS's INFOG(1) = -10), or, for a solver that only warns (UMFPACK on a singular
   matrix), a solve with the factor that gives Inf or NaN. */
static PetscErrorCode FactorFailure(KSP ksp, const char **failure)
{
  PC             pc;
  PCFailedReason reason;
  PetscBool      factor;
  Mat            A, F;
  Vec            b, x;
  PetscReal      norm;

  PetscFunctionBegin;
  *failure = nullptr;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCGetFailedReason(pc, &reason));
  if (reason != PC_NOERROR) {
    *failure = PCFailedReasons[reason];
    PetscFunctionReturn(0);
  }
  PetscCall(PetscObjectTypeCompareAny((PetscObject)pc, &factor, PCLU, PCCHOLESKY, PCILU, PCICC, ""));
  if (!factor) PetscFunctionReturn(0);
  PetscCall(KSPGetOperators(ksp, &A, nullptr));
  PetscCall(PCFactorGetMatrix(pc, &F));
  PetscCall(MatCreateVecs(A, &x, &b));
  PetscCall(VecSet(b, 1.0));
  PetscCall(MatSolve(F, b, x));
  PetscCall(VecNorm(x, NORM_INFINITY, &norm));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  if (PetscIsInfOrNanReal(norm)) *failure = PCFailedReasons[PC_FACTOR_NUMERIC_ZEROPIVOT];
  PetscFunctionReturn(0);
}

/* The global dof of the first zero row of a local matrix, or -1. */
static PetscErrorCode ZeroRow(PC pc, const Subdomain &s, LocalMatrix which, Mat A, PetscInt *dof)
{
  PC_GDSW           *gd = (PC_GDSW *)pc->data;
  Vec                m;
  const PetscScalar *v;
  PetscInt           n, local = -1;

  PetscFunctionBegin;
  PetscCall(MatCreateVecs(A, nullptr, &m));
  PetscCall(MatGetRowMaxAbs(A, m, nullptr));
  PetscCall(VecGetLocalSize(m, &n));
  PetscCall(VecGetArrayRead(m, &v));
  for (PetscInt r = 0; r < n && local < 0; r++)
    if (v[r] == 0.0) local = r;
  PetscCall(VecRestoreArrayRead(m, &v));
  PetscCall(VecDestroy(&m));
  *dof = -1;
  if (local < 0) PetscFunctionReturn(0);
  const PetscInt *idx;
  IS              rows = which == gdsw::OVERLAPPING ? s.overlap : s.isI;
  PetscCall(ISGetIndices(rows, &idx));
  *dof = which == gdsw::OVERLAPPING ? idx[local] : s.nodes[idx[local] / gd->bs] * gd->bs + idx[local] % gd->bs;
  PetscCall(ISRestoreIndices(rows, &idx));
  PetscFunctionReturn(0);
}

/* Set up the solver of one local matrix of subdomain s and record its factorisation. Cholesky,
   when asked for, is tried only on a matrix that may be SPD and never again on one where it
   failed; LU replaces it. A singular matrix stops the set-up with a sentence. */
PetscErrorCode GDSWSetUpLocalSolver(PC pc, KSP ksp, Subdomain &s, LocalMatrix which)
{
  PC                   lpc;
  Mat                  A;
  PetscInt             n, dof;
  PetscBool            cholesky, lu, spd = PETSC_FALSE, ok = PETSC_FALSE;
  const char          *failure, *prefix;
  gdsw::Factorisation &kind = s.factorisation[which];
  const bool           failedBefore = kind == gdsw::LU_NOT_SPD;

  PetscFunctionBegin;
  PetscCall(KSPGetPC(ksp, &lpc));
  PetscCall(KSPGetOperators(ksp, &A, nullptr));
  PetscCall(MatGetSize(A, &n, nullptr));
  PetscCall(PetscObjectTypeCompare((PetscObject)lpc, PCCHOLESKY, &cholesky));
  if (cholesky && !failedBefore) PetscCall(MayBeSPD(pc, A, &spd));
  if (spd) PetscCall(TryCholesky(ksp, &ok));
  if (cholesky && !ok) {
    if (spd) PetscCall(PetscInfo(pc, "Cholesky failed on the %s matrix of subdomain %" PetscInt_FMT " (%" PetscInt_FMT " dofs, not positive definite): LU instead\n", LocalMatrixNames[which], s.gid, n));
    else if (!failedBefore) PetscCall(PetscInfo(pc, "the %s matrix of subdomain %" PetscInt_FMT " (%" PetscInt_FMT " dofs) has a diagonal entry <= 0 or is not symmetric: LU instead of Cholesky\n", LocalMatrixNames[which], s.gid, n));
    PetscCall(SwitchToLU(ksp));
  }
  if (!ok) PetscCall(KSPSetUp(ksp));
  PetscCall(PetscObjectTypeCompare((PetscObject)lpc, PCLU, &lu));
  kind = ok ? gdsw::CHOLESKY : (cholesky || failedBefore ? gdsw::LU_NOT_SPD : (lu ? gdsw::LU : gdsw::OTHER));
  PetscCall(FactorFailure(ksp, &failure));
  if (!failure) PetscFunctionReturn(0);
  PetscCall(ZeroRow(pc, s, which, A, &dof));
  PetscCall(KSPGetOptionsPrefix(ksp, &prefix));
  PetscCheck(dof >= 0, PETSC_COMM_SELF, PETSC_ERR_MAT_LU_ZRPVT,
             "PCGDSW: the %s matrix of subdomain %" PetscInt_FMT " (%" PetscInt_FMT " dofs) could not be factored (%s): the operator is singular there; check the boundary conditions, or let PETSc's LU shift the zero pivots with -%spc_factor_mat_solver_type petsc -%spc_factor_shift_type nonzero",
             LocalMatrixNames[which], s.gid, n, failure, prefix, prefix);
  SETERRQ(PETSC_COMM_SELF, PETSC_ERR_MAT_LU_ZRPVT,
          "PCGDSW: the %s matrix of subdomain %" PetscInt_FMT " (%" PetscInt_FMT " dofs) could not be factored (%s): the operator is singular there, its row of global dof %" PetscInt_FMT " is zero; give that dof a nonzero diagonal (MatZeroRowsColumns() with diag 1 if it takes no part in the problem) or remove it",
          LocalMatrixNames[which], s.gid, n, failure, dof);
}

/* -pc_view: how many overlapping and interior matrices got each factorisation. */
PetscErrorCode GDSWViewLocalSolvers(PC pc, PetscViewer viewer)
{
  PC_GDSW                 *gd = (PC_GDSW *)pc->data;
  static const char *const names[] = {nullptr, "Cholesky", "LU", "LU instead of Cholesky (not symmetric positive definite)", "other solvers"};
  PetscInt                 local[2][5] = {{0}}, count[2][5];

  PetscFunctionBegin;
  for (const auto &s : *gd->sub)
    for (int m = 0; m < 2; m++) local[m][s.factorisation[m]]++;
  PetscCallMPI(MPIU_Allreduce(local, count, 10, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)pc)));
  for (int m = 0; m < 2; m++) {
    std::string line;
    for (int k = gdsw::CHOLESKY; k <= gdsw::OTHER; k++)
      if (count[m][k]) line += (line.empty() ? "" : ", ") + std::to_string(count[m][k]) + " " + names[k];
    if (!line.empty()) PetscCall(PetscViewerASCIIPrintf(viewer, "  local factorisations of the %s matrices: %s\n", LocalMatrixNames[m], line.c_str()));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode CreateScatters(PC pc)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;
  const PetscInt bs = gd->bs;
  std::vector<PetscInt> all, keepPos, keepGlobal;
  PetscInt total = 0;
  Vec      x;
  IS       is, isw;

  PetscFunctionBegin;
  for (auto &s : *gd->sub) {
    PetscInt        n;
    const PetscInt *idx;
    PetscCall(ISGetLocalSize(s.overlap, &n));
    PetscCall(ISGetIndices(s.overlap, &idx));
    s.wOffset = total;
    for (PetscInt k = 0; k < n; k++) {
      all.push_back(idx[k]);
      const PetscInt node = idx[k] / bs;
      auto it = std::lower_bound(s.nodes.begin(), s.nodes.end(), node);
      if (it != s.nodes.end() && *it == node && (*gd->sets)[s.setOf[it - s.nodes.begin()]][0] == s.gid) {
        keepPos.push_back(total + k);
        keepGlobal.push_back(idx[k]);
      }
    }
    PetscCall(ISRestoreIndices(s.overlap, &idx));
    total += n;
    PetscCall(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n, nullptr, &s.x));
    PetscCall(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n, nullptr, &s.y));
  }
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, total, &gd->work));
  PetscCall(VecDuplicate(gd->work, &gd->workOut));
  PetscCall(MatCreateVecs(gd->A, &x, nullptr));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, total, all.data(), PETSC_USE_POINTER, &is));
  PetscCall(VecScatterCreate(x, is, gd->work, nullptr, &gd->restrictTo));
  PetscCall(ISDestroy(&is));
  if (gd->firstLevel == PC_GDSW_FIRST_LEVEL_RESTRICTED) {
    PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)keepPos.size(), keepPos.data(), PETSC_USE_POINTER, &isw));
    PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)keepGlobal.size(), keepGlobal.data(), PETSC_USE_POINTER, &is));
    PetscCall(VecScatterCreate(gd->workOut, isw, x, is, &gd->prolongFrom));
    PetscCall(ISDestroy(&is));
    PetscCall(ISDestroy(&isw));
  }
  PetscCall(VecDestroy(&x));
  PetscFunctionReturn(0);
}

PetscErrorCode GDSWSetUpFirstLevel(PC pc, MatReuse reuse)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;
  auto    &sub = *gd->sub;
  const PetscInt n = (PetscInt)sub.size();

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(GDSW_LocalFactor, pc, 0, 0, 0));
  if (reuse == MAT_INITIAL_MATRIX) PetscCall(CreateScatters(pc));
  for (PetscInt i = 0; i < n; i++) {
    Subdomain &s = sub[i];
    if (!s.ksp) {
      PetscCall(KSPCreate(PETSC_COMM_SELF, &s.ksp));
      PetscCall(KSPSetErrorIfNotConverged(s.ksp, pc->erroriffailure));
      PetscCall(PetscObjectIncrementTabLevel((PetscObject)s.ksp, (PetscObject)pc, 1));
      PetscCall(KSPSetOptionsPrefix(s.ksp, ((PetscObject)pc)->prefix));
      PetscCall(KSPAppendOptionsPrefix(s.ksp, "pc_gdsw_sub_"));
      PetscCall(GDSWDefaultFactorSolver(s.ksp, nullptr, gd->symmetric));
      PetscCall(KSPSetFromOptions(s.ksp));
    }
    PetscCall(KSPSetOperators(s.ksp, s.Aovl, s.Aovl));
    PetscCall(GDSWSetUpLocalSolver(pc, s.ksp, s, gdsw::OVERLAPPING));
  }
  PetscCall(PetscLogEventEnd(GDSW_LocalFactor, pc, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* y += sum_i R~_i^T A_i^{-1} R_i x, or its transpose y += sum_i R_i^T A_i^{-T} R~_i x. For the
   restricted first level R~_i reverses the prolongation's scatter: each dof is read by the one
   subdomain that prolongates it, and is zero in the others. */
PetscErrorCode GDSWApplyFirstLevel(PC pc, Vec x, Vec y, PetscBool transpose)
{
  PC_GDSW        *gd         = (PC_GDSW *)pc->data;
  const PetscBool restricted = (PetscBool)(gd->firstLevel == PC_GDSW_FIRST_LEVEL_RESTRICTED);
  PetscScalar    *w, *wo;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(GDSW_ApplyLocal, pc, x, y, 0));
  if (transpose && restricted) {
    PetscCall(VecSet(gd->work, 0.0));
    PetscCall(VecScatterBegin(gd->prolongFrom, x, gd->work, INSERT_VALUES, SCATTER_REVERSE));
    PetscCall(VecScatterEnd(gd->prolongFrom, x, gd->work, INSERT_VALUES, SCATTER_REVERSE));
  } else {
    PetscCall(VecScatterBegin(gd->restrictTo, x, gd->work, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(gd->restrictTo, x, gd->work, INSERT_VALUES, SCATTER_FORWARD));
  }
  PetscCall(VecGetArray(gd->work, &w));
  PetscCall(VecGetArray(gd->workOut, &wo));
  for (auto &s : *gd->sub) {
    PetscCall(VecPlaceArray(s.x, w + s.wOffset));
    PetscCall(VecPlaceArray(s.y, wo + s.wOffset));
    if (transpose) PetscCall(KSPSolveTranspose(s.ksp, s.x, s.y));
    else PetscCall(KSPSolve(s.ksp, s.x, s.y));
    PetscCall(KSPCheckSolve(s.ksp, pc, s.y));
    PetscCall(VecResetArray(s.x));
    PetscCall(VecResetArray(s.y));
  }
  PetscCall(VecRestoreArray(gd->work, &w));
  PetscCall(VecRestoreArray(gd->workOut, &wo));
  if (!transpose && restricted) {
    PetscCall(VecScatterBegin(gd->prolongFrom, gd->workOut, y, ADD_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(gd->prolongFrom, gd->workOut, y, ADD_VALUES, SCATTER_FORWARD));
  } else {
    PetscCall(VecScatterBegin(gd->restrictTo, gd->workOut, y, ADD_VALUES, SCATTER_REVERSE));
    PetscCall(VecScatterEnd(gd->restrictTo, gd->workOut, y, ADD_VALUES, SCATTER_REVERSE));
  }
  PetscCall(PetscLogEventEnd(GDSW_ApplyLocal, pc, x, y, 0));
  PetscFunctionReturn(0);
}
