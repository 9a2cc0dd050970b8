// SPDX-License-Identifier: BSD-2-Clause
/* First level: exact, incomplete or adaptive (incomplete where it is good enough) solves on the
   overlapping subdomains Omega_i^delta, sum_i R_i^T A_i^{-1} R_i, or its restricted variant that
   prolongates each correction only on a nonoverlapping partition (each node goes to the subdomain
   of smallest id that contains it in Omega~). Also the set-up of every local factorisation (these
   and the interiors of the harmonic extension): Cholesky only where it can work, and a singular
   local matrix stops the set-up with a sentence instead of a NaN in the first application. */
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

/* CHOLMOD's factor, in double or single precision */
static bool IsCholmod(MatSolverType solver)
{
  return solver && (!strcmp(solver, MATSOLVERCHOLMOD) || !strcmp(solver, MATSOLVERCHOLMODSINGLE));
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
  if (asked && !IsCholmod(asked)) PetscCall(PetscStrncpy(solver, asked, sizeof(solver)));
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
   only. CHOLMOD gets the node graph's nested dissection (ordering.cxx) as its only ordering
   (with inexact first levels, the overlapping matrices it factors exactly).
   The user's own -mat_cholmod_print, -mat_cholmod_nmethods and ordering type are left alone. */
static PetscErrorCode TryCholesky(PC pc, KSP ksp, Subdomain &s, LocalMatrix which, PetscBool *ok)
{
  PC             lpc;
  Mat            A;
  PCFailedReason reason = PC_NOERROR;
  MatSolverType  solver;
  const char    *prefix;
  char           print[256], nmethods[256], ordering[256];
  PetscBool      cholmod = PETSC_FALSE, quiet = PETSC_FALSE, ours = PETSC_FALSE, set;
  PetscOptions   options = ((PetscObject)ksp)->options;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscCall(KSPGetPC(ksp, &lpc));
  PetscCall(PCFactorGetMatSolverType(lpc, &solver));
  cholmod = (PetscBool)IsCholmod(solver);
  if (cholmod) {
    PetscCall(PCGetOptionsPrefix(lpc, &prefix));
    PetscCall(PetscSNPrintf(print, sizeof(print), "-%smat_cholmod_print", prefix ? prefix : ""));
    PetscCall(PetscOptionsHasName(options, nullptr, print, &set));
    quiet = (PetscBool)!set;
    PetscCall(PetscSNPrintf(ordering, sizeof(ordering), "-%spc_factor_mat_ordering_type", prefix ? prefix : ""));
    PetscCall(PetscOptionsHasName(options, nullptr, ordering, &set));
    PetscCall(PetscSNPrintf(nmethods, sizeof(nmethods), "-%smat_cholmod_nmethods", prefix ? prefix : ""));
    if (!set) PetscCall(PetscOptionsHasName(options, nullptr, nmethods, &set));
    /* the interior takes its order from the overlapping matrix's dissection, worth making only
       when the first level factors that matrix exactly too */
    ours = (PetscBool)(!set && (which == gdsw::OVERLAPPING || ((PC_GDSW *)pc->data)->localSolver == PC_GDSW_LOCAL_EXACT));
  }
  if (quiet) PetscCall(PetscOptionsSetValue(options, print, "1"));
  if (ours) {
    PetscCall(KSPGetOperators(ksp, &A, nullptr));
    PetscCall(GDSWComposeRowRanks(pc, s, which, A));
    PetscCall(PCFactorSetMatOrderingType(lpc, MATORDERINGGDSWNODES));
    PetscCall(PetscOptionsSetValue(options, nmethods, "1")); /* the given ordering only */
  }
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  ierr = KSPSetUp(ksp);
  PetscCall(PetscPopErrorHandler());
  /* a wrong option of the factorisation is the user's error, not a matrix Cholesky cannot do:
     set up again to raise it with its message */
  if (ierr == PETSC_ERR_ARG_OUTOFRANGE || ierr == PETSC_ERR_ARG_WRONG) PetscCall(KSPSetUp(ksp));
  if (quiet) PetscCall(PetscOptionsClearValue(options, print));
  if (ours) PetscCall(PetscOptionsClearValue(options, nmethods));
  if (!ierr) PetscCall(PCGetFailedReason(lpc, &reason));
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
  if (spd) PetscCall(TryCholesky(pc, ksp, s, which, &ok));
  if (cholesky && !ok) {
    if (spd) PetscCall(PetscInfo(pc, "Cholesky failed on the %s matrix of subdomain %" PetscInt_FMT " (%" PetscInt_FMT " dofs, not positive definite): LU instead\n", LocalMatrixNames[which], s.gid, n));
    else if (!failedBefore) PetscCall(PetscInfo(pc, "the %s matrix of subdomain %" PetscInt_FMT " (%" PetscInt_FMT " dofs) has a diagonal entry <= 0 or is not symmetric: LU instead of Cholesky\n", LocalMatrixNames[which], s.gid, n));
    PetscCall(SwitchToLU(ksp));
  }
  if (!ok) PetscCall(KSPSetUp(ksp));
  PetscBool incomplete;
  PetscCall(PetscObjectTypeCompare((PetscObject)lpc, PCLU, &lu));
  PetscCall(PetscObjectTypeCompareAny((PetscObject)lpc, &incomplete, PCICC, PCILU, ""));
  PetscBool single = PETSC_FALSE;
  if (ok) {
    Mat F;
    PetscCall(PCFactorGetMatrix(lpc, &F));
    PetscCall(GDSWFactorIsSingle(F, &single));
  }
  kind = ok ? (single ? gdsw::CHOLESKY_SINGLE : gdsw::CHOLESKY) : (cholesky || failedBefore ? gdsw::LU_NOT_SPD : (lu ? gdsw::LU : incomplete ? gdsw::INCOMPLETE : gdsw::OTHER));
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
  static const char *const names[] = {nullptr, "Cholesky", "Cholesky kept in single precision", "LU", "LU instead of Cholesky (not symmetric positive definite)", "incomplete (ICC/ILU)", "other solvers"};
  PetscInt                 local[2][gdsw::OTHER + 1] = {{0}}, count[2][gdsw::OTHER + 1];

  PetscFunctionBegin;
  for (const auto &s : *gd->sub)
    for (int m = 0; m < 2; m++) local[m][s.factorisation[m]]++;
  PetscCallMPI(MPIU_Allreduce(local, count, 2 * (gdsw::OTHER + 1), MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)pc)));
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

/* The local solver's defaults for -pc_gdsw_local_solver: the exact factorisation (Cholesky kept
   in single precision with -pc_gdsw_local_precision single), or ICC(0) / ILU(0) (PETSc's,
   natural ordering; ICC shifts its pivots to keep the factor positive). */
static PetscErrorCode DefaultLocalSolver(PC pc, KSP ksp, bool incomplete)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;
  PC       lpc;

  PetscFunctionBegin;
  if (!incomplete) {
    const bool single = GDSW_HAVE_SINGLE_FACTOR && gd->symmetric && gd->localPrecision == PC_GDSW_LOCAL_PRECISION_SINGLE;
    PetscCall(GDSWDefaultFactorSolver(ksp, single ? MATSOLVERCHOLMODSINGLE : nullptr, gd->symmetric));
    PetscFunctionReturn(0);
  }
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &lpc));
  PetscCall(PCSetType(lpc, gd->symmetric ? PCICC : PCILU));
  PetscFunctionReturn(0);
}

/* Condition estimate of M^{-1} A_i for the set-up incomplete factor M of A_i = A(Omega_i^delta):
   the extreme singular values from the Lanczos (CG) or Arnoldi (GMRES) coefficients of a few
   iterations on a fixed random right-hand side. Infinite when CG finds the preconditioner
   indefinite. */
static PetscErrorCode ConditionEstimate(PC pc, Subdomain &s, PetscReal *kappa)
{
  PC_GDSW           *gd = (PC_GDSW *)pc->data;
  const PetscInt     its = 12;
  KSP                est;
  PC                 lpc;
  Vec                b, x;
  PetscRandom        rnd;
  PetscReal          emax = 0, emin = 0;
  KSPConvergedReason reason;

  PetscFunctionBegin;
  PetscCall(KSPGetPC(s.ksp, &lpc));
  PetscCall(KSPCreate(PETSC_COMM_SELF, &est));
  PetscCall(KSPSetOptionsPrefix(est, ((PetscObject)pc)->prefix)); /* its own prefix: the outer -ksp_* options are not its */
  PetscCall(KSPAppendOptionsPrefix(est, "pc_gdsw_local_estimate_"));
  PetscCall(KSPSetType(est, gd->symmetric ? KSPCG : KSPGMRES));
  if (!gd->symmetric) PetscCall(KSPGMRESSetRestart(est, its));
  PetscCall(KSPSetOperators(est, s.Aovl, s.Aovl));
  PetscCall(KSPSetPC(est, lpc));
  PetscCall(KSPSetComputeSingularValues(est, PETSC_TRUE));
  PetscCall(KSPSetTolerances(est, 0.0, 0.0, PETSC_DEFAULT, its));
  PetscCall(KSPSetConvergenceTest(est, KSPConvergedSkip, nullptr, nullptr));
  PetscCall(KSPSetNormType(est, KSP_NORM_NONE));
  PetscCall(MatCreateVecs(s.Aovl, &x, &b));
  PetscCall(PetscRandomCreate(PETSC_COMM_SELF, &rnd));
  PetscCall(PetscRandomSetSeed(rnd, 271828 + (unsigned long)s.gid)); /* the same estimate in every run */
  PetscCall(PetscRandomSeed(rnd));
  PetscCall(VecSetRandom(b, rnd));
  PetscCall(KSPSolve(est, b, x));
  PetscCall(KSPGetConvergedReason(est, &reason));
  if (reason != KSP_DIVERGED_INDEFINITE_PC && reason != KSP_DIVERGED_INDEFINITE_MAT) PetscCall(KSPComputeExtremeSingularValues(est, &emax, &emin));
  *kappa = emin > 0 && !PetscIsInfOrNanReal(emax) ? emax / emin : PETSC_INFINITY;
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  PetscCall(KSPDestroy(&est));
  PetscFunctionReturn(0);
}

/* Adaptive local solvers: the incomplete factor of s stays if its condition estimate is at most
   -pc_gdsw_local_condition_max; otherwise s is factored exactly. */
static PetscErrorCode ChooseLocalSolver(PC pc, Subdomain &s)
{
  PC_GDSW  *gd = (PC_GDSW *)pc->data;
  PetscReal kappa = PETSC_INFINITY;
  PetscInt  n;

  PetscFunctionBegin;
  if (s.factorisation[gdsw::OVERLAPPING] != gdsw::INCOMPLETE) PetscFunctionReturn(0);
  PetscCall(ConditionEstimate(pc, s, &kappa));
  if (kappa <= gd->conditionMax) PetscFunctionReturn(0);
  PetscCall(MatGetSize(s.Aovl, &n, nullptr));
  char estimate[64]; /* C's %g: PETSc's printf marks whole numbers with a trailing point */
  snprintf(estimate, sizeof(estimate), "%.4g exceeds %g", (double)kappa, (double)gd->conditionMax);
  /* the subdomain's own solver reports, so that every rank prints its subdomains */
  PetscCall(PetscInfo(s.ksp, "PCGDSW subdomain %" PetscInt_FMT " (%" PetscInt_FMT " dofs): the incomplete factor's condition estimate %s: exact factorisation\n", s.gid, n, estimate));
  PetscCall(KSPReset(s.ksp));
  PetscCall(KSPSetOperators(s.ksp, s.Aovl, s.Aovl));
  PetscCall(DefaultLocalSolver(pc, s.ksp, false));
  PetscCall(GDSWSetUpLocalSolver(pc, s.ksp, s, gdsw::OVERLAPPING));
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
      PetscCall(DefaultLocalSolver(pc, s.ksp, gd->localSolver != PC_GDSW_LOCAL_EXACT));
      PetscCall(GDSWKSPSetFromOptions(s.ksp));
    }
    PetscCall(KSPSetOperators(s.ksp, s.Aovl, s.Aovl));
    PetscCall(GDSWSetUpLocalSolver(pc, s.ksp, s, gdsw::OVERLAPPING));
    if (reuse == MAT_INITIAL_MATRIX && gd->localSolver == PC_GDSW_LOCAL_ADAPTIVE) PetscCall(ChooseLocalSolver(pc, s));
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
