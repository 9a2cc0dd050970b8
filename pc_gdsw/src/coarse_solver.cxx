// SPDX-License-Identifier: BSD-2-Clause
/* Coarse solver: A_0 (coarse_operator.cxx) factored by the coarse KSP (default: MUMPS on all
   ranks of the PC, options prefix -pc_gdsw_coarse_). */
#include "gdswimpl.h"

/* A floating operator (no Dirichlet row) whose null space is not attached would make A_0
   singular: say so instead of failing inside the factorisation. */
static PetscErrorCode CheckFloating(PC pc, PetscBool *floating)
{
  PC_GDSW     *gd = (PC_GDSW *)pc->data;
  MatNullSpace nsp;
  Vec          z, Az;
  PetscReal    nz, nAz, nA;

  PetscFunctionBegin;
  *floating = PETSC_FALSE;
  if (gd->nDirichletRows) PetscFunctionReturn(0);
  PetscCall(MatCreateVecs(gd->A, &z, &Az));
  PetscCall(VecStrideSet(z, 0, 1.0));
  PetscCall(MatMult(gd->A, z, Az));
  PetscCall(VecNorm(z, NORM_2, &nz));
  PetscCall(VecNorm(Az, NORM_2, &nAz));
  PetscCall(MatNorm(gd->A, NORM_INFINITY, &nA));
  PetscCall(VecDestroy(&z));
  PetscCall(VecDestroy(&Az));
  if (nAz > 1e-10 * nA * nz) PetscFunctionReturn(0);
  PetscCall(MatGetNullSpace(pc->pmat, &nsp));
  PetscCheck(nsp, PetscObjectComm((PetscObject)pc), PETSC_ERR_MAT_LU_ZRPVT,
             "PCGDSW: the operator is singular: it has no Dirichlet row and maps the constant vector of component 0 to zero (|A z|/|A||z| = %g), so the coarse matrix A_0 is singular too. Add a Dirichlet condition, or attach the null space with MatSetNullSpace() so that the Krylov method removes it",
             (double)(nAz / (nA * nz)));
  *floating = PETSC_TRUE;
  PetscFunctionReturn(0);
}

PetscErrorCode GDSWSetUpCoarseSolver(PC pc, PetscBool basisCurrent)
{
  PC_GDSW       *gd = (PC_GDSW *)pc->data;
  PCFailedReason reason;
  PC             cpc;
  PetscBool      floating, isMumps;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(GDSW_CoarseSetUp, pc, 0, 0, 0));
  PetscCall(GDSWAssembleCoarseOperator(pc, basisCurrent));
  if (!gd->coarseKsp) {
    PetscCall(CheckFloating(pc, &floating));
    PetscCall(KSPCreate(PetscObjectComm((PetscObject)pc), &gd->coarseKsp));
    PetscCall(PetscObjectIncrementTabLevel((PetscObject)gd->coarseKsp, (PetscObject)pc, 1));
    PetscCall(KSPSetOptionsPrefix(gd->coarseKsp, ((PetscObject)pc)->prefix));
    PetscCall(KSPAppendOptionsPrefix(gd->coarseKsp, "pc_gdsw_coarse_"));
    PetscCall(GDSWDefaultFactorSolver(gd->coarseKsp, MATSOLVERMUMPS, gd->symmetric));
    PetscCall(KSPSetOperators(gd->coarseKsp, gd->A0, gd->A0));
    PetscCall(GDSWKSPSetFromOptions(gd->coarseKsp));
    PetscCall(KSPGetPC(gd->coarseKsp, &cpc));
    PetscCall(PetscObjectTypeCompareAny((PetscObject)cpc, &isMumps, PCLU, PCCHOLESKY, ""));
    if (floating && isMumps) {
      /* the null space is attached: let MUMPS detect the null pivots of A_0 */
      MatSolverType st;
      PetscCall(PCFactorGetMatSolverType(cpc, &st));
      if (st && !strcmp(st, MATSOLVERMUMPS)) {
        Mat F;
        PetscCall(PCFactorSetUpMatSolverType(cpc));
        PetscCall(PCFactorGetMatrix(cpc, &F));
        PetscCall(MatMumpsSetIcntl(F, 24, 1));
        PetscCall(PetscInfo(pc, "floating operator with attached null space: MUMPS null-pivot detection on A_0\n"));
      }
    }
    PetscCall(MatCreateVecs(gd->A0, &gd->x0, &gd->r0));
    if (gd->combination == PC_COMPOSITE_SYMMETRIC_MULTIPLICATIVE) PetscCall(VecDuplicate(gd->x0, &gd->c0));
  } else PetscCall(KSPSetOperators(gd->coarseKsp, gd->A0, gd->A0));
  PetscCall(KSPSetUp(gd->coarseKsp));
  PetscCall(KSPGetPC(gd->coarseKsp, &cpc));
  PetscCall(PCGetFailedReason(cpc, &reason));
  PetscCheck(reason == PC_NOERROR, PetscObjectComm((PetscObject)pc), PETSC_ERR_MAT_LU_ZRPVT,
             "PCGDSW: the coarse matrix A_0 = Phi^T A Phi (dimension %" PetscInt_FMT ") could not be factored (%s): A is singular on the coarse space or in a subdomain interior; check the Dirichlet conditions, the near-null space and rows that are entirely zero",
             gd->coarseDim, PCFailedReasons[reason]);
  PetscCall(PetscLogEventEnd(GDSW_CoarseSetUp, pc, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* y += Phi A_0^{-1} Phi^T x, or with A_0^{-T} */
PetscErrorCode GDSWApplyCoarse(PC pc, Vec x, Vec y, PetscBool transpose)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(GDSW_ApplyCoarse, pc, x, y, 0));
  PetscCall(MatMultTranspose(gd->Phi, x, gd->r0));
  if (transpose) PetscCall(KSPSolveTranspose(gd->coarseKsp, gd->r0, gd->x0));
  else PetscCall(KSPSolve(gd->coarseKsp, gd->r0, gd->x0));
  PetscCall(MatMultAdd(gd->Phi, gd->x0, y, y));
  PetscCall(PetscLogEventEnd(GDSW_ApplyCoarse, pc, x, y, 0));
  PetscFunctionReturn(0);
}

/* Symmetric multiplicative (balanced, hybrid) combination, symmetric when A is:
     y = Q0 x + (I - Q0 A) M1 (I - A Q0) x,  Q0 = Phi A_0^{-1} Phi^T,
   so that M A Phi = Phi: the coarse space is solved exactly and the local solves see only the
   rest. With W = A Phi kept from the set-up it costs what the additive one does (one product
   with Phi^T and one with Phi) plus two with W: sparse (interface rows only) where Phi is harmonic
   for A, else with interior rows as dense as Phi's (phi.cxx):
     c = A_0^{-1} Phi^T x,  y = M1 (x - W c),  y += Phi (c - A_0^{-1} W^T y).
   For a nonsymmetric A the product with (A^T Phi) or its transpose goes through A. Transposed,
   y = Q0^T x + (I - Q0^T A^T) M1^T (I - A^T Q0^T) x. */
PetscErrorCode GDSWApplyBalanced(PC pc, Vec x, Vec y, PetscBool transpose)
{
  PC_GDSW  *gd   = (PC_GDSW *)pc->data;
  const bool viaA = !gd->symmetric;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(GDSW_ApplyCoarse, pc, x, y, 0));
  PetscCall(MatMultTranspose(gd->Phi, x, gd->r0));
  if (transpose) PetscCall(KSPSolveTranspose(gd->coarseKsp, gd->r0, gd->c0));
  else PetscCall(KSPSolve(gd->coarseKsp, gd->r0, gd->c0));
  if (transpose && viaA) { /* x - A^T Phi c */
    PetscCall(MatMult(gd->Phi, gd->c0, gd->tmp2));
    PetscCall(MatMultTranspose(gd->A, gd->tmp2, gd->tmp1));
  } else PetscCall(MatMult(gd->APhi, gd->c0, gd->tmp1));
  PetscCall(VecAYPX(gd->tmp1, -1.0, x));
  PetscCall(PetscLogEventEnd(GDSW_ApplyCoarse, pc, x, y, 0));
  PetscCall(GDSWApplyFirstLevel(pc, gd->tmp1, y, transpose));
  PetscCall(PetscLogEventBegin(GDSW_ApplyCoarse, pc, x, y, 0));
  if (!transpose && viaA) { /* (A^T Phi)^T y = Phi^T A y */
    PetscCall(MatMult(gd->A, y, gd->tmp1));
    PetscCall(MatMultTranspose(gd->Phi, gd->tmp1, gd->r0));
  } else PetscCall(MatMultTranspose(gd->APhi, y, gd->r0));
  if (transpose) PetscCall(KSPSolveTranspose(gd->coarseKsp, gd->r0, gd->x0));
  else PetscCall(KSPSolve(gd->coarseKsp, gd->r0, gd->x0));
  PetscCall(VecAXPY(gd->c0, -1.0, gd->x0));
  PetscCall(MatMultAdd(gd->Phi, gd->c0, y, y));
  PetscCall(PetscLogEventEnd(GDSW_ApplyCoarse, pc, x, y, 0));
  PetscFunctionReturn(0);
}
