// SPDX-License-Identifier: BSD-2-Clause
/* PCGDSW: two-level overlapping Schwarz with the GDSW coarse space (Dohrmann, Klawonn,
   Widlund 2008; Heinlein, Klawonn, Rheinbach 2015, eq. 1):
       M^{-1} = Phi (Phi^T A Phi)^{-1} Phi^T + sum_i R_i^T A_i^{-1} R_i.
   This file holds the PC object: the operator's checks, the order of the setup modules, the
   solve's check of its KSP, apply and its transpose, view, creation and registration. The options are read in options.cxx, the public functions with the
   methods they call are in api_configuration.cxx, api_subdomains.cxx, api_coarse_space.cxx and api_first_level.cxx. */
#include "gdswimpl.h"
#include <algorithm>
#include <string>

const char *const PCGDSWCoarseSpaceTypes[] = {"gdsw", "rgdsw", "none", "PCGDSWCoarseSpaceType", "PC_GDSW_COARSE_", nullptr};
const char *const PCGDSWFirstLevelTypes[]  = {"additive", "restricted", "PCGDSWFirstLevelType", "PC_GDSW_FIRST_LEVEL_", nullptr};
const char *const PCGDSWRGDSWWeightTypes[] = {"equal", "distance", "PCGDSWRGDSWWeightType", "PC_GDSW_RGDSW_WEIGHTS_", nullptr};
const char *const PCGDSWLocalSolverTypes[] = {"exact", "incomplete", "adaptive", "PCGDSWLocalSolverType", "PC_GDSW_LOCAL_", nullptr};
const char *const PCGDSWLocalPrecisions[]  = {"double", "single", "PCGDSWLocalPrecision", "PC_GDSW_LOCAL_PRECISION_", nullptr};

/* The size rule's target when -pc_gdsw_subdomain_size is not given: exact local solves cost
   O(n^2) per subdomain in 3D, so fewer and larger ones (12000 dofs) balance them against the
   coarse problem; incomplete factors cost O(n) and lose quality with the subdomain's size, so
   smaller ones (3000 dofs) are faster (bench/results/gdsw_vs_amg). */
PetscInt GDSWSubdomainSizeTarget(const PC_GDSW *gd)
{
  if (gd->subdomainSize != PETSC_DECIDE) return gd->subdomainSize;
  return gd->localSolver == PC_GDSW_LOCAL_EXACT ? 12000 : 3000;
}

PetscLogEvent GDSW_Decomposition, GDSW_Interface, GDSW_Basis, GDSW_Extension, GDSW_CoarseSetUp, GDSW_LocalFactor, GDSW_Apply, GDSW_ApplyLocal, GDSW_ApplyCoarse;

/* Direct solver defaults, measured on 3D elasticity (bench/results): CHOLMOD Cholesky for
   symmetric operators, else UMFPACK LU (the paper's local solver), when PETSc has SuiteSparse;
   the coarse solver asks for MUMPS. Options override all of it. */
PetscErrorCode GDSWDefaultFactorSolver(KSP ksp, MatSolverType solver, PetscBool symmetric)
{
  PC pc;

  PetscFunctionBegin;
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, symmetric ? PCCHOLESKY : PCLU));
#if defined(PETSC_HAVE_SUITESPARSE)
  if (!solver) solver = symmetric ? MATSOLVERCHOLMOD : MATSOLVERUMFPACK;
#endif
#if !defined(PETSC_HAVE_MUMPS)
  if (solver && !strcmp(solver, MATSOLVERMUMPS)) solver = nullptr;
#endif
  if (solver) PetscCall(PCFactorSetMatSolverType(pc, solver));
  PetscFunctionReturn(0);
}

/* Symmetric as flagged by the application, or up to round-off in the assembled values. With
   overlap every entry a_ij lies in some overlapping subdomain matrix with both i and j, so each
   rank's A(U, U), the union of its subdomains, decides it: MatIsSymmetric() on the parallel
   operator gathers its transposed off-process blocks (measured: 4 of 9 s of the set-up on a
   100 k-dof wall), and one test per subdomain matrix visits the overlap's entries again. */
static PetscErrorCode IsSymmetric(PC pc, PetscBool *symmetric)
{
  PC_GDSW  *gd = (PC_GDSW *)pc->data;
  PetscBool set, flg, all = PETSC_TRUE;
  PetscReal norm;

  PetscFunctionBegin;
  PetscCall(MatIsSymmetricKnown(gd->A, &set, &flg));
  if (set) {
    *symmetric = flg;
    PetscFunctionReturn(0);
  }
  if (gd->overlap == 0) {
    PetscCall(MatNorm(gd->A, NORM_INFINITY, &norm));
    PetscCall(MatIsSymmetric(gd->A, 1e-12 * norm, symmetric));
    PetscFunctionReturn(0);
  }
  if (!gd->sub->empty()) {
    Mat AU = gd->AU ? gd->AU[0] : gd->A; /* one rank: A itself */
    PetscCall(MatNorm(AU, NORM_INFINITY, &norm));
    PetscCall(MatIsSymmetric(AU, 1e-12 * norm, &all));
  }
  PetscCallMPI(MPIU_Allreduce(&all, symmetric, 1, MPIU_BOOL, MPI_LAND, PetscObjectComm((PetscObject)pc)));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCReset_GDSW(PC pc)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  for (auto &s : *gd->sub) {
    PetscCall(ISDestroy(&s.nonoverlap));
    PetscCall(ISDestroy(&s.overlap));
    PetscCall(ISDestroy(&s.ovlInU));
    PetscCall(ISDestroy(&s.isI));
    PetscCall(ISDestroy(&s.isG));
    PetscCall(ISDestroy(&s.nonInOvl));
    PetscCall(MatDestroy(&s.Aovl));
    PetscCall(MatDestroy(&s.AII));
    PetscCall(MatDestroy(&s.AIG));
    PetscCall(MatDestroy(&s.PhiG));
    PetscCall(MatDestroy(&s.PhiI));
    PetscCall(KSPDestroy(&s.ksp));
    PetscCall(VecDestroy(&s.x));
    PetscCall(VecDestroy(&s.y));
  }
  gd->sub->clear();
  gd->sets->clear();
  PetscCall(PetscSFDestroy(&gd->nodeSF));
  if (gd->AU) PetscCall(MatDestroySubMatrices(1, &gd->AU));
  PetscCall(ISDestroy(&gd->isU));
  PetscCall(MatDestroy(&gd->A));
  PetscCall(MatDestroy(&gd->Phi));
  PetscCall(MatDestroy(&gd->PhiGamma));
  PetscCall(MatDestroy(&gd->PhiAssembled));
  PetscCall(VecScatterDestroy(&gd->phiCols));
  PetscCall(VecScatterDestroy(&gd->phiInterior));
  PetscCall(VecDestroy(&gd->phiColsWork));
  PetscCall(VecDestroy(&gd->phiIntWork));
  PetscCall(ISDestroy(&gd->keptCols));
  PetscCall(MatDestroy(&gd->A0));
  PetscCall(MatDestroy(&gd->APhi));
  PetscCall(MatDestroy(&gd->APhiGamma));
  PetscCall(KSPDestroy(&gd->coarseKsp));
  PetscCall(VecDestroy(&gd->r0));
  PetscCall(VecDestroy(&gd->x0));
  PetscCall(VecDestroy(&gd->c0));
  PetscCall(VecDestroy(&gd->work));
  PetscCall(VecDestroy(&gd->workOut));
  PetscCall(VecScatterDestroy(&gd->restrictTo));
  PetscCall(VecScatterDestroy(&gd->prolongFrom));
  PetscCall(VecDestroy(&gd->tmp1));
  PetscCall(VecDestroy(&gd->tmp2));
  PetscCall(PetscFree(gd->nonArr));
  PetscCall(PetscFree(gd->ovlArr));
  gd->coarseDim = 0;
  gd->counts[0] = gd->counts[1] = gd->counts[2] = 0;
  PetscFunctionReturn(0);
}

/* The operator as (MPI)AIJ: MATIS and (S)BAIJ are converted once, AIJ is referenced. */
static PetscErrorCode GetAIJOperator(PC pc, MatReuse reuse)
{
  PC_GDSW  *gd = (PC_GDSW *)pc->data;
  Mat       P  = pc->pmat;
  PetscBool isAIJ;
  PetscInt  M, N, m, n, bs;
  MPI_Comm  comm;

  PetscFunctionBegin;
  PetscCall(PetscObjectGetComm((PetscObject)pc, &comm));
  PetscCall(MatGetSize(P, &M, &N));
  PetscCall(MatGetLocalSize(P, &m, &n));
  PetscCheck(M == N, comm, PETSC_ERR_ARG_SIZ, "PCGDSW: the operator must be square; it is %" PetscInt_FMT " x %" PetscInt_FMT, M, N);
  PetscCheck(m == n, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "PCGDSW: the operator's local row and column sizes must agree; they are %" PetscInt_FMT " and %" PetscInt_FMT, m, n);
  PetscBool assembled;
  PetscCall(MatAssembled(P, &assembled));
  PetscCheck(assembled, comm, PETSC_ERR_ARG_WRONGSTATE, "PCGDSW: the operator is not assembled; call MatAssemblyBegin/End() first");
  PetscCall(PetscObjectTypeCompareAny((PetscObject)P, &isAIJ, MATSEQAIJ, MATMPIAIJ, ""));
  if (isAIJ) {
    if (reuse == MAT_INITIAL_MATRIX) {
      PetscCall(PetscObjectReference((PetscObject)P));
      gd->A = P;
    }
  } else {
    PetscBool known;
    PetscCall(PetscObjectTypeCompareAny((PetscObject)P, &known, MATSEQBAIJ, MATMPIBAIJ, MATSEQSBAIJ, MATMPISBAIJ, MATIS, ""));
    PetscCheck(known, comm, PETSC_ERR_SUP, "PCGDSW: matrix type %s is not supported; use AIJ, BAIJ, SBAIJ or IS", ((PetscObject)P)->type_name);
    PetscCall(MatConvert(P, MATAIJ, reuse == MAT_INITIAL_MATRIX ? MAT_INITIAL_MATRIX : MAT_REUSE_MATRIX, &gd->A));
  }
  /* dofs per node: the matrix block size, or what PCSetCoordinates implies */
  PetscCall(MatGetBlockSize(P, &bs));
  if (bs == 1 && gd->coords && gd->nCoordNodes > 0) {
    PetscCheck(m % gd->nCoordNodes == 0, PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP, "PCGDSW: PCSetCoordinates() gave %" PetscInt_FMT " local nodes, which does not divide the %" PetscInt_FMT " local rows of the operator into whole nodes", gd->nCoordNodes, m);
    bs = m / gd->nCoordNodes;
  }
  PetscCheck(bs >= 1 && bs <= 8 * (PetscInt)sizeof(PetscInt) - 2, comm, PETSC_ERR_ARG_OUTOFRANGE, "PCGDSW: block size %" PetscInt_FMT " is not supported", bs);
  PetscCheck(m % bs == 0, PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP, "PCGDSW: the block size %" PetscInt_FMT " (dofs per node) does not divide the local size %" PetscInt_FMT " of the operator", bs, m);
  gd->bs = bs;
  PetscFunctionReturn(0);
}

/* A NaN or Inf among the operator's values makes a factorisation fail with a zero pivot or
   return NaN: say what it is, with its row, before any factorisation sees it. */
static PetscErrorCode CheckFinite(PC pc)
{
  PC_GDSW        *gd = (PC_GDSW *)pc->data;
  Mat             part[2] = {gd->A, nullptr};
  const PetscInt *colmap = nullptr;
  PetscInt        rstart, cstart;
  PetscBool       mpi;

  PetscFunctionBegin;
  PetscCall(PetscObjectTypeCompare((PetscObject)gd->A, MATMPIAIJ, &mpi));
  if (mpi) PetscCall(MatMPIAIJGetSeqAIJ(gd->A, &part[0], &part[1], &colmap));
  PetscCall(MatGetOwnershipRange(gd->A, &rstart, nullptr));
  PetscCall(MatGetOwnershipRangeColumn(gd->A, &cstart, nullptr));
  for (PetscInt k = 0; k < 2 && part[k]; k++) {
    const PetscInt    *ia, *ja;
    const PetscScalar *v;
    PetscInt           n, bad = -1;
    PetscBool          done;
    PetscCall(MatGetRowIJ(part[k], 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
    PetscCall(MatSeqAIJGetArrayRead(part[k], &v));
    for (PetscInt j = 0; j < ia[n] && bad < 0; j++)
      if (PetscIsInfOrNanScalar(v[j])) bad = j;
    if (bad >= 0) {
      const PetscInt    row = (PetscInt)(std::upper_bound(ia, ia + n + 1, bad) - ia) - 1;
      const PetscInt    col = k ? colmap[ja[bad]] : cstart + ja[bad];
      const PetscScalar a   = v[bad];
      PetscMPIInt       rank;
      PetscCallMPI(MPI_Comm_rank(PetscObjectComm((PetscObject)pc), &rank));
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FP, "PCGDSW: the matrix has a non-finite entry (%s) in row %" PetscInt_FMT ", column %" PetscInt_FMT " (rank %d): the operator's values must be finite; this is no zero pivot, and no shift helps", PetscIsNanScalar(a) ? "nan" : "inf", rstart + row, col, rank);
    }
    PetscCall(MatSeqAIJRestoreArrayRead(part[k], &v));
    PetscCall(MatRestoreRowIJ(part[k], 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  }
  PetscFunctionReturn(0);
}

/* step() with the blocks it keeps (the subdomain matrices, the first level's factors) on huge
   pages. Not the harmonic extension: its factors and right-hand sides are freed subdomain by
   subdomain, and malloc()'s heap recycles them without a page fault. */
template <class Step>
static PetscErrorCode OnHugePages(PC pc, Step step)
{
  PC_GDSW  *gd = (PC_GDSW *)pc->data;
  PetscBool began;
  size_t    mark, bytes;

  PetscFunctionBegin;
  PetscCall(GDSWHugePagesBegin(pc, gd->hugePages, &began, &mark));
  PetscErrorCode ierr = step();
  PetscCall(GDSWHugePagesEnd(began, mark, &bytes));
  PetscCall(ierr);
  gd->hugeBytes += bytes;
  PetscFunctionReturn(0);
}

static PetscErrorCode SetUp(PC pc)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  gd->hugeBytes   = 0;
  PetscBool fresh = (PetscBool)(!pc->setupcalled || pc->flag == DIFFERENT_NONZERO_PATTERN);
  if (!fresh) {
    /* MatZeroRows() on other rows keeps the pattern but changes which dofs Phi must exclude */
    PetscCall(GetAIJOperator(pc, MAT_REUSE_MATRIX));
    PetscCall(CheckFinite(pc));
    PetscCall(GDSWDirichletRowsChanged(pc, &fresh));
    if (fresh) PetscCall(PetscInfo(pc, "the operator's Dirichlet rows changed with the same pattern: the decomposition and the coarse space are rebuilt\n"));
  }
  if (fresh) {
    PetscCall(PCReset_GDSW(pc));
    PetscCall(GetAIJOperator(pc, MAT_INITIAL_MATRIX));
    PetscCall(CheckFinite(pc));
    PetscCall(PetscLogEventBegin(GDSW_Decomposition, pc, 0, 0, 0));
    PetscCall(GDSWBuildDecomposition(pc));
    PetscCall(OnHugePages(pc, [&] { return GDSWExtractSubdomainMatrices(pc, MAT_INITIAL_MATRIX); }));
    PetscCall(IsSymmetric(pc, &gd->symmetric));
    PetscCall(PetscLogEventEnd(GDSW_Decomposition, pc, 0, 0, 0));
    PetscCall(PetscLogEventBegin(GDSW_Interface, pc, 0, 0, 0));
    PetscCall(GDSWBuildInterface(pc));
    PetscCall(PetscLogEventEnd(GDSW_Interface, pc, 0, 0, 0));
    gd->coarseActive = PETSC_FALSE;
    if (gd->coarseType != PC_GDSW_COARSE_NONE) {
      PetscCall(GDSWBuildCoarseBasis(pc));
      gd->coarseActive = (PetscBool)(gd->coarseDim > 0);
      if (gd->coarseActive) PetscCall(GDSWSetUpCoarseSolver(pc, PETSC_TRUE));
      else PetscCall(PetscInfo(pc, "the decomposition has no interface: no coarse level\n"));
    }
    PetscCall(OnHugePages(pc, [&] { return GDSWSetUpFirstLevel(pc, MAT_INITIAL_MATRIX); }));
    if (gd->coarseActive && gd->combination != PC_COMPOSITE_ADDITIVE) PetscCall(MatCreateVecs(gd->A, &gd->tmp1, &gd->tmp2)); /* residual after the coarse correction */
  } else {
    /* same pattern, new values (Newton, time stepping): numeric refactorisations only */
    PetscCall(GDSWExtractSubdomainMatrices(pc, MAT_REUSE_MATRIX));
    if (gd->coarseActive) {
      if (!gd->reuseCoarseBasis) PetscCall(GDSWUpdateCoarseBasis(pc));
      PetscCall(GDSWSetUpCoarseSolver(pc, (PetscBool)!gd->reuseCoarseBasis));
    }
    PetscCall(OnHugePages(pc, [&] { return GDSWSetUpFirstLevel(pc, MAT_REUSE_MATRIX); }));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode PCSetUp_GDSW(PC pc)
{
  PetscInt levels;

  PetscFunctionBegin;
  PetscCall(GDSWSerialRegionsBegin(&levels));
  PetscErrorCode ierr = SetUp(pc);
  PetscCall(GDSWSerialRegionsEnd(levels));
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

/* Single-precision local factors make the preconditioner linear only to about 1e-7 of each
   application. CG (its residual updated with the operator), the flexible methods (each
   preconditioned vector kept) and Richardson converge as with double factors; GMRES and the other
   methods that form their solution from many applications lose that rounding: their residual
   estimate goes on falling while the true residual stalls (Q1 elasticity: 3e-6 to 7e-6, reported
   CONVERGED_RTOL at 1e-10). Such a method is refused below a tolerance of 1e-4, a factor 10 above
   the stall measured; the KSP is known only here, at the solve. */
static PetscErrorCode PCPreSolve_GDSW(PC pc, KSP ksp, Vec b, Vec x)
{
  PC_GDSW  *gd = (PC_GDSW *)pc->data;
  PetscInt  single = 0;
  PetscBool exact;
  PetscReal rtol;
  KSPType   type;

  PetscFunctionBegin;
  if (gd->localPrecision != PC_GDSW_LOCAL_PRECISION_SINGLE) PetscFunctionReturn(0);
  for (const gdsw::Subdomain &s : *gd->sub) single += s.factorisation[gdsw::OVERLAPPING] == gdsw::CHOLESKY_SINGLE;
  PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, &single, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)pc)));
  if (!single) PetscFunctionReturn(0);
  PetscCall(PetscObjectTypeCompareAny((PetscObject)ksp, &exact, KSPCG, KSPFCG, KSPPIPEFCG, KSPFGMRES, KSPPIPEFGMRES, KSPGCR, KSPPIPEGCR, KSPRICHARDSON, KSPPREONLY, ""));
  PetscCall(KSPGetTolerances(ksp, &rtol, nullptr, nullptr, nullptr));
  PetscCall(KSPGetType(ksp, &type));
  PetscCheck(exact || rtol >= 1e-4, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_INCOMP,
             "PCGDSW: %s single keeps %" PetscInt_FMT " local factors in single precision, with which KSP %s stalls near a true relative residual of 1e-5 while it reports convergence: it cannot reach its -ksp_rtol %g. Use -ksp_type fgmres (or cg for a symmetric positive definite operator), or %s double",
             GDSWOptionName(pc, "-pc_gdsw_local_precision").c_str(), single, type, (double)rtol, GDSWOptionName(pc, "-pc_gdsw_local_precision").c_str());
  PetscFunctionReturn(0);
}

/* Multiplicative: y = Q0 x + M1 (x - A Q0 x), transposed y = M1^T x + Q0^T (x - A^T M1^T x);
   additive: y = M1 x + Q0 x. */
static PetscErrorCode Apply(PC pc, Vec x, Vec y, PetscBool transpose)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(GDSW_Apply, pc, x, y, 0));
  PetscCall(VecSet(y, 0.0));
  if (gd->coarseActive && gd->combination == PC_COMPOSITE_MULTIPLICATIVE) {
    PetscErrorCode (*first)(PC, Vec, Vec, PetscBool) = transpose ? GDSWApplyFirstLevel : GDSWApplyCoarse;
    PetscErrorCode (*second)(PC, Vec, Vec, PetscBool) = transpose ? GDSWApplyCoarse : GDSWApplyFirstLevel;
    PetscCall(first(pc, x, y, transpose));
    if (transpose) PetscCall(MatMultTranspose(pc->pmat, y, gd->tmp1));
    else PetscCall(MatMult(pc->pmat, y, gd->tmp1));
    PetscCall(VecAYPX(gd->tmp1, -1.0, x));
    PetscCall(second(pc, gd->tmp1, y, transpose));
  } else if (gd->coarseActive && gd->combination == PC_COMPOSITE_SYMMETRIC_MULTIPLICATIVE) {
    PetscCall(GDSWApplyBalanced(pc, x, y, transpose));
  } else {
    PetscCall(GDSWApplyFirstLevel(pc, x, y, transpose));
    if (gd->coarseActive) PetscCall(GDSWApplyCoarse(pc, x, y, transpose));
  }
  PetscCall(PetscLogEventEnd(GDSW_Apply, pc, x, y, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCApply_GDSW(PC pc, Vec x, Vec y)
{
  PetscFunctionBegin;
  PetscCall(Apply(pc, x, y, PETSC_FALSE));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCApplyTranspose_GDSW(PC pc, Vec x, Vec y)
{
  PetscFunctionBegin;
  PetscCall(Apply(pc, x, y, PETSC_TRUE));
  PetscFunctionReturn(0);
}

/* What the getters of the set-up's results check first. */
PetscErrorCode GDSWCheckSetUp(PC pc)
{
  PetscFunctionBegin;
  PetscCheck(pc->setupcalled, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_WRONGSTATE, "PCGDSW: call PCSetUp() first");
  PetscFunctionReturn(0);
}

static PetscErrorCode PCView_GDSW(PC pc, PetscViewer viewer)
{
  PC_GDSW  *gd = (PC_GDSW *)pc->data;
  PetscBool ascii;

  PetscFunctionBegin;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &ascii));
  if (!ascii) PetscFunctionReturn(0);
  PetscCall(PetscViewerASCIIPrintf(viewer, "  coarse space %s%s, %s combination, %s first level\n", PCGDSWCoarseSpaceTypes[gd->coarseType],
                                   gd->coarseType != PC_GDSW_COARSE_NONE && !gd->rotations ? " without rotations" : "", GDSWCombinationTypes[gd->combination], PCGDSWFirstLevelTypes[gd->firstLevel]));
  if (!pc->setupcalled) {
    if (gd->nsubPerRank == PETSC_DECIDE) PetscCall(PetscViewerASCIIPrintf(viewer, "  subdomains per rank: chosen at setup for about %" PetscInt_FMT " dofs each, overlap %" PetscInt_FMT " (not set up yet)\n", GDSWSubdomainSizeTarget(gd), gd->overlap));
    else PetscCall(PetscViewerASCIIPrintf(viewer, "  subdomains per rank %" PetscInt_FMT ", overlap %" PetscInt_FMT " (not set up yet)\n", gd->nsubPerRank, gd->overlap));
    PetscFunctionReturn(0);
  }
  const char *source = gd->nUser >= 0 ? "given by the application" : "from the matrix graph";
  PetscBool   isIS;
  PetscCall(PetscObjectTypeCompare((PetscObject)pc->pmat, MATIS, &isIS));
  if (isIS && gd->nUser < 0) source = "from the MATIS local-to-global map";
  if (gd->nUser < 0) {
    if (gd->nsubPerRank == PETSC_DECIDE) PetscCall(PetscViewerASCIIPrintf(viewer, "  subdomains per rank: chosen by the size rule, about %" PetscInt_FMT " dofs each (-pc_gdsw_subdomain_size): %" PetscInt_FMT " on rank 0\n", GDSWSubdomainSizeTarget(gd), gd->nsubRank0));
    else PetscCall(PetscViewerASCIIPrintf(viewer, "  subdomains per rank: %" PetscInt_FMT ", given (-pc_gdsw_subdomains)\n", gd->nsubPerRank));
    if (gd->repartition && !isIS) PetscCall(PetscViewerASCIIPrintf(viewer, "  repartitioned (-pc_gdsw_repartition): the whole matrix graph split by %s, not each rank's rows; %" PetscInt_FMT " subdomains on rank 0\n", gd->partitioner, gd->nsubRank0));
    if (gd->balanced) PetscCall(PetscViewerASCIIPrintf(viewer, "  the ranks' rows are unbalanced: the subdomains were redistributed, %" PetscInt_FMT " on rank 0\n", gd->nsubRank0));
  }
  PetscCall(PetscViewerASCIIPrintf(viewer, "  %" PetscInt_FMT " subdomains (%s), overlap %s, %" PetscInt_FMT " dofs per node, %" PetscInt_FMT " null-space vectors%s\n", gd->nGlobalSubdomains, source,
                                   gd->nUser >= 0 && gd->userOvl ? "given by the application" : (std::to_string(gd->overlap) + " graph layers").c_str(), gd->bs, gd->nz, gd->haveCoords ? " (rigid modes from coordinates)" : ""));
  PetscCall(PetscViewerASCIIPrintf(viewer, "  interface components: %" PetscInt_FMT " faces, %" PetscInt_FMT " edges, %" PetscInt_FMT " vertices; %" PetscInt_FMT " Dirichlet dofs excluded\n", gd->counts[0], gd->counts[1], gd->counts[2], gd->nDirichletRows));
  if (gd->coarseType == PC_GDSW_COARSE_RGDSW) {
    /* the distance weights are measured between the coordinates the rigid modes are built from */
    if (gd->rgdswWeights == PC_GDSW_RGDSW_WEIGHTS_EQUAL || gd->haveCoords) PetscCall(PetscViewerASCIIPrintf(viewer, "  RGDSW partition of unity: %s\n", PCGDSWRGDSWWeightTypes[gd->rgdswWeights]));
    else PetscCall(PetscViewerASCIIPrintf(viewer, "  RGDSW partition of unity: equal (the distance weights need PCSetCoordinates() as the source of the null space)\n"));
  }
  if (gd->coarseType != PC_GDSW_COARSE_NONE && !gd->coarseActive) PetscCall(PetscViewerASCIIPrintf(viewer, "  no interface, hence no coarse level\n"));
  if (gd->coarseActive) {
    PetscCall(PetscViewerASCIIPrintf(viewer, "  coarse dimension %" PetscInt_FMT "%s\n", gd->coarseDim, gd->reuseCoarseBasis ? " (basis reused across setups)" : ""));
    PetscCall(PetscViewerASCIIPrintf(viewer, "  coarse solver (prefix -%spc_gdsw_coarse_):\n", ((PetscObject)pc)->prefix ? ((PetscObject)pc)->prefix : ""));
    PetscCall(PetscViewerASCIIPushTab(viewer));
    PetscCall(KSPView(gd->coarseKsp, viewer));
    PetscCall(PetscViewerASCIIPopTab(viewer));
  }
  if (gd->localSolver == PC_GDSW_LOCAL_ADAPTIVE) {
    char bound[32];
    snprintf(bound, sizeof(bound), "%g", (double)gd->conditionMax);
    PetscCall(PetscViewerASCIIPrintf(viewer, "  local solvers adaptive: incomplete where its condition estimate is at most %s (-pc_gdsw_local_condition_max), exact elsewhere\n", bound));
  }
  PetscCall(GDSWViewLocalSolvers(pc, viewer));
  if (gd->hugePages) {
    double mib = (double)gd->hugeBytes / 1048576.0;
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &mib, 1, MPI_DOUBLE, MPI_SUM, PetscObjectComm((PetscObject)pc)));
    if (mib > 0) PetscCall(PetscViewerASCIIPrintf(viewer, "  blocks of 2 MiB or more on transparent huge pages in the last set-up: %.0f MiB (-pc_gdsw_huge_pages)\n", mib));
  }
  /* the first local solver stands for all: they share their options */
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(PetscObjectComm((PetscObject)pc), &rank));
  PetscCall(PetscViewerASCIIPrintf(viewer, "  local solver of the first subdomain (prefix -%spc_gdsw_sub_):\n", ((PetscObject)pc)->prefix ? ((PetscObject)pc)->prefix : ""));
  PetscViewer sv; /* collective: every rank takes the subviewer, rank 0 prints */
  PetscCall(PetscViewerGetSubViewer(viewer, PETSC_COMM_SELF, &sv));
  if (rank == 0) {
    PetscCall(PetscViewerASCIIPushTab(sv));
    if (gd->sub->empty()) PetscCall(PetscViewerASCIIPrintf(sv, "(rank 0 holds no subdomain)\n"));
    else PetscCall(KSPView((*gd->sub)[0].ksp, sv));
    PetscCall(PetscViewerASCIIPopTab(sv));
  }
  PetscCall(PetscViewerRestoreSubViewer(viewer, PETSC_COMM_SELF, &sv));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCDestroy_GDSW(PC pc)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCall(PCReset_GDSW(pc));
  PetscCall(GDSWDestroyUserSubdomains(gd));
  PetscCall(PetscFree(gd->coords));
  delete gd->sub;
  delete gd->sets;
  delete gd->dirichletMask;
  PetscCall(GDSWComposeSubdomainMethods(pc, PETSC_FALSE));
  PetscCall(GDSWComposeCoarseSpaceMethods(pc, PETSC_FALSE));
  PetscCall(GDSWComposeFirstLevelMethods(pc, PETSC_FALSE));
  PetscCall(GDSWComposeConfigurationMethods(pc, PETSC_FALSE));
  PetscCall(PetscFree(pc->data));
  PetscFunctionReturn(0);
}

/*MC
   PCGDSW - two-level overlapping Schwarz preconditioner with an energy-minimizing coarse space:
   GDSW [DKW08], its reduced-dimension variant RGDSW [DW17], or none (one-level Schwarz),

   M^{-1} = Phi (Phi^T A Phi)^{-1} Phi^T + sum_i R_i^T A_i^{-1} R_i,

   where the columns of Phi are the null space of the operator (rigid-body modes for elasticity)
   restricted to the interface components of a nonoverlapping decomposition (faces, edges and
   vertices, shared by the same subdomains) and extended harmonically into the subdomains
   [HKR16a], and A_i is the operator on the overlapping subdomain i. By default the coarse term
   Q_0 = Phi (Phi^T A Phi)^{-1} Phi^T and the local term M_1 are combined symmetric-multiplicatively
   (balanced), Q_0 + (I - Q_0 A) M_1 (I - A Q_0) (see `PCGDSWSetCombinationType()`).

   Options Database Keys:
+  -pc_gdsw_configuration <robust> - robust (exact local solvers, GDSW) or fast (adaptive local solvers, RGDSW: near an AMG's cost on benign elasticity, less robust); -pc_gdsw_local_solver and -pc_gdsw_coarse_space override it (see `PCGDSWSetConfiguration()`)
.  -pc_gdsw_subdomains <-1> - subdomains per MPI rank, METIS on the rank's node graph; -1 (`PETSC_DECIDE`): about -pc_gdsw_subdomain_size dofs each (see `PCGDSWSetSubdomainsPerRank()`)
.  -pc_gdsw_repartition <false> - the subdomains from a parallel partitioner of the whole matrix graph, not from each rank's rows (see `PCGDSWSetRepartition()`)
.  -pc_gdsw_subdomain_size <12000> - the target number of dofs per subdomain of that rule; 3000 with incomplete or adaptive local solvers (see `PCGDSWSetSubdomainSize()`)
.  -pc_gdsw_overlap <1> - layers of the matrix graph added to each subdomain (see `PCGDSWSetOverlap()`)
.  -pc_gdsw_coarse_space <gdsw> - gdsw, rgdsw or none (see `PCGDSWSetCoarseSpaceType()`)
.  -pc_gdsw_rgdsw_weights <distance> - RGDSW's partition of unity, distance or equal (see `PCGDSWSetRGDSWWeightType()`)
.  -pc_gdsw_rotations <true> - false: translations only, GDSW-nr (see `PCGDSWSetRotations()`)
.  -pc_gdsw_combination <symmetric_multiplicative> - symmetric_multiplicative (balanced), additive or multiplicative (see `PCGDSWSetCombinationType()`)
.  -pc_gdsw_first_level_type <additive> - additive or restricted, RAS (see `PCGDSWSetFirstLevelType()`)
.  -pc_gdsw_reuse_coarse_basis <false> - keep Phi when the operator's values change (see `PCGDSWSetReuseCoarseBasis()`)
.  -pc_gdsw_huge_pages <true> - during set-up, the blocks of 2 MiB or more that it keeps (local factors, subdomain matrices) on transparent huge pages where the kernel gives them on request (see `PCGDSWSetHugePages()`)
.  -pc_gdsw_local_solver <exact> - exact, incomplete or adaptive local solvers of the first level (see `PCGDSWSetLocalSolverType()`)
.  -pc_gdsw_local_condition_max <25> - the adaptive local solvers' bound (see `PCGDSWSetLocalConditionMax()`)
-  -pc_gdsw_local_precision <double> - single: the first level's Cholesky factors kept in single precision where that solves to within 1e-3 of double, for CG and FGMRES (other KSPs are refused below a -ksp_rtol of 1e-4; see `PCGDSWSetLocalPrecision()`)

   Notes:
   The subdomains are, in this order of preference, the application's (`PCGDSWSetSubdomains()`),
   a `MATIS` operator's local subdomains (each split by METIS when the size rule or `PCGDSWSetSubdomainsPerRank()` asks for more
   than one per rank), or METIS parts of each rank's node graph (or of the whole graph, `PCGDSWSetRepartition()`).

   The null space comes from the operator's near-null space (`MatSetNearNullSpace()`), else from
   the coordinates given with `PCSetCoordinates()` (rigid-body modes in 2D and 3D), else it is
   the translations of each of the block size's components.

   The subsolvers are `KSP` objects with the prefixes -pc_gdsw_sub_ (the overlapping subdomains),
   -pc_gdsw_extension_ (the interiors of the harmonic extension) and -pc_gdsw_coarse_ (A_0 =
   Phi^T A Phi, see `PCGDSWGetCoarseKSP()`). Defaults: `KSPPREONLY` with Cholesky (CHOLMOD)
   for symmetric operators, else LU (UMFPACK); MUMPS on all ranks of the `PC` for A_0. CHOLMOD
   gets one ordering, METIS nested dissection of the node graph ("gdsw_nodes", registered with
   `MatOrderingRegister()` and usable by any factorisation as -pc_factor_mat_ordering_type
   gdsw_nodes); -pc_gdsw_sub_pc_factor_mat_ordering_type external gives CHOLMOD its own choice back.

   `PCApplyTranspose()` applies the transpose of each component (transposed local and coarse
   solves; for the restricted first level the restriction and prolongation exchange roles), so
   `KSPSolveTranspose()` works with every variant.

   References:
+  * - C. R. Dohrmann, A. Klawonn, O. B. Widlund. Domain decomposition for less regular subdomains: overlapping Schwarz in two dimensions. SIAM J. Numer. Anal. 46(4), 2008 [DKW08].
.  * - C. R. Dohrmann, O. B. Widlund. On the design of small coarse spaces for domain decomposition algorithms. SIAM J. Sci. Comput. 39(4), 2017 [DW17] (RGDSW).
.  * - A. Heinlein, A. Klawonn, O. Rheinbach, O. B. Widlund. Improving the parallel performance of overlapping Schwarz methods by using a smaller energy minimizing coarse space. Domain Decomposition Methods in Science and Engineering XXIV, Lect. Notes Comput. Sci. Eng. 125, Springer, 2018 (RGDSW in parallel).
.  * - A. Heinlein, A. Klawonn, O. Rheinbach. A parallel implementation of a two-level overlapping Schwarz method with energy-minimizing coarse space based on Trilinos. SIAM J. Sci. Comput. 38(6), 2016 [HKR16a].
.  * - A. Heinlein, A. Klawonn, O. Rheinbach. Parallel two-level overlapping Schwarz methods in fluid-structure interaction. Numerical Mathematics and Advanced Applications ENUMATH 2015, Lect. Notes Comput. Sci. Eng. 112, Springer, 2016 [HKR16b].
.  * - J. Mandel. Balancing domain decomposition. Commun. Numer. Methods Eng. 9(3), 1993 [Man93] (the balanced combination).
.  * - A. Toselli, O. B. Widlund. Domain Decomposition Methods: Algorithms and Theory. Springer, 2005 [TW05].
-  * - J. M. Tang, R. Nabben, C. Vuik, Y. A. Erlangga. Comparison of two-level preconditioners derived from deflation, domain decomposition and multigrid methods. J. Sci. Comput. 39(3), 2009 [TNVE09].

   Level: intermediate

.seealso: `PCCreate()`, `PCSetType()`, `PCType`, `PC`, `PCASM`, `PCBDDC`, `PCGDSWRegister()`, `PCGDSWSetSubdomains()`, `PCGDSWGetCoarseBasis()`,
          `PCGDSWGetCoarseKSP()`, `PCSetCoordinates()`, `MatSetNearNullSpace()`
M*/
PETSC_EXTERN PetscErrorCode PCCreate_GDSW(PC pc)
{
  PC_GDSW *gd;

  PetscFunctionBegin;
  PetscCall(PetscNew(&gd));
  pc->data             = gd;
  gd->configuration    = PC_GDSW_CONFIGURATION_ROBUST;
  gd->nsubPerRank      = PETSC_DECIDE;
  gd->repartition      = PETSC_FALSE;
  gd->subdomainSize    = PETSC_DECIDE;
  gd->localSolver      = PC_GDSW_LOCAL_EXACT;
  gd->conditionMax     = 25;
  gd->localPrecision   = PC_GDSW_LOCAL_PRECISION_DOUBLE;
  gd->overlap          = 1;
  gd->coarseType       = PC_GDSW_COARSE_GDSW;
  gd->combination      = PC_COMPOSITE_SYMMETRIC_MULTIPLICATIVE;
  gd->firstLevel       = PC_GDSW_FIRST_LEVEL_ADDITIVE;
  gd->rotations        = PETSC_TRUE;
  gd->rgdswWeights     = PC_GDSW_RGDSW_WEIGHTS_DISTANCE;
  gd->reuseCoarseBasis = PETSC_FALSE;
  gd->hugePages        = PETSC_TRUE;
  gd->nUser            = -1;
  gd->sub              = new std::vector<gdsw::Subdomain>();
  gd->sets             = new std::vector<std::vector<PetscInt>>();
  gd->dirichletMask    = new std::vector<PetscInt>();

  pc->ops->setup          = PCSetUp_GDSW;
  pc->ops->apply          = PCApply_GDSW;
  pc->ops->applytranspose = PCApplyTranspose_GDSW;
  pc->ops->presolve       = PCPreSolve_GDSW;
  pc->ops->reset          = PCReset_GDSW;
  pc->ops->destroy        = PCDestroy_GDSW;
  pc->ops->setfromoptions = GDSWSetFromOptions;
  pc->ops->view           = PCView_GDSW;
  PetscCall(GDSWComposeSubdomainMethods(pc, PETSC_TRUE));
  PetscCall(GDSWComposeCoarseSpaceMethods(pc, PETSC_TRUE));
  PetscCall(GDSWComposeFirstLevelMethods(pc, PETSC_TRUE));
  PetscCall(GDSWComposeConfigurationMethods(pc, PETSC_TRUE));
  PetscFunctionReturn(0);
}

static PetscBool GDSWRegistered = PETSC_FALSE;

/* PetscFinalize() empties PETSc's list of PC types: a later PetscInitialize() registers again. */
static PetscErrorCode PCGDSWFinalizePackage(void)
{
  PetscFunctionBegin;
  GDSWRegistered = PETSC_FALSE;
  PetscFunctionReturn(0);
}

/*@C
   PCGDSWRegister - Registers the preconditioner type `PCGDSW` ("gdsw") and its log events

   Not Collective

   Notes:
   Call it after `PetscInitialize()` in a program linked with the library; loading the library
   with -dll_append calls it too. Further calls do nothing until `PetscFinalize()`.

   Level: beginner

.seealso: `PCGDSW`, `PCRegister()`, `PetscDLLibraryAppend()`
@*/
PetscErrorCode PCGDSWRegister(void)
{
  PetscFunctionBegin;
  if (GDSWRegistered) PetscFunctionReturn(0);
  GDSWRegistered = PETSC_TRUE;
  PetscCall(PCRegister(PCGDSW, PCCreate_GDSW));
  PetscCall(GDSWRegisterOrdering());
  PetscCall(GDSWRegisterSingleFactor());
  PetscCall(PetscLogEventRegister("GDSWDecomp", PC_CLASSID, &GDSW_Decomposition));
  PetscCall(PetscLogEventRegister("GDSWInterface", PC_CLASSID, &GDSW_Interface));
  PetscCall(PetscLogEventRegister("GDSWBasis", PC_CLASSID, &GDSW_Basis));
  PetscCall(PetscLogEventRegister("GDSWExtension", PC_CLASSID, &GDSW_Extension));
  PetscCall(PetscLogEventRegister("GDSWCoarseSetUp", PC_CLASSID, &GDSW_CoarseSetUp));
  PetscCall(PetscLogEventRegister("GDSWLocalFactor", PC_CLASSID, &GDSW_LocalFactor));
  PetscCall(PetscLogEventRegister("GDSWApply", PC_CLASSID, &GDSW_Apply));
  PetscCall(PetscLogEventRegister("GDSWApplyLocal", PC_CLASSID, &GDSW_ApplyLocal));
  PetscCall(PetscLogEventRegister("GDSWApplyCoarse", PC_CLASSID, &GDSW_ApplyCoarse));
  PetscCall(PetscRegisterFinalize(PCGDSWFinalizePackage));
  PetscFunctionReturn(0);
}

/* what -dll_append looks up */
PETSC_EXTERN PetscErrorCode PetscDLLibraryRegister_petscgdsw(void)
{
  PetscFunctionBegin;
  PetscCall(PCGDSWRegister());
  PetscFunctionReturn(0);
}
