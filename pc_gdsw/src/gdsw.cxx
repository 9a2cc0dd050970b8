/* PCGDSW: two-level overlapping Schwarz with the GDSW coarse space (Dohrmann, Klawonn,
   Widlund 2008; Heinlein, Klawonn, Rheinbach 2015, eq. 1):
       M^{-1} = Phi (Phi^T A Phi)^{-1} Phi^T + sum_i R_i^T A_i^{-1} R_i.
   This file holds the PC object: options, the order of the setup modules, apply and view. */
#include "gdswimpl.h"
#include <string>

const char *const PCGDSWCoarseSpaceTypes[] = {"gdsw", "rgdsw", "none", "PCGDSWCoarseSpaceType", "PC_GDSW_COARSE_", nullptr};
const char *const PCGDSWCombinationTypes[] = {"additive", "multiplicative", "PCGDSWCombinationType", "PC_GDSW_", nullptr};
const char *const PCGDSWFirstLevelTypes[]  = {"additive", "restricted", "PCGDSWFirstLevelType", "PC_GDSW_FIRST_LEVEL_", nullptr};
const char *const PCGDSWRGDSWWeightTypes[] = {"equal", "distance", "PCGDSWRGDSWWeightType", "PC_GDSW_RGDSW_WEIGHTS_", nullptr};

PetscLogEvent GDSW_Decomposition, GDSW_Interface, GDSW_Basis, GDSW_Extension, GDSW_CoarseSetUp, GDSW_LocalFactor, GDSW_Apply;

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
   overlap every entry a_ij lies in some overlapping subdomain matrix with both i and j, so the
   sequential subdomain matrices decide it: MatIsSymmetric() on the parallel operator gathers
   its transposed off-process blocks (measured: 4 of 9 s of the set-up on a 100 k-dof wall). */
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
  for (auto &s : *gd->sub) {
    PetscCall(MatNorm(s.Aovl, NORM_INFINITY, &norm));
    PetscCall(MatIsSymmetric(s.Aovl, 1e-12 * norm, &flg));
    all = (PetscBool)(all && flg);
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
    PetscCall(ISDestroy(&s.isI));
    PetscCall(ISDestroy(&s.isG));
    PetscCall(ISDestroy(&s.nonInOvl));
    PetscCall(MatDestroy(&s.Anon));
    PetscCall(MatDestroy(&s.AII));
    PetscCall(MatDestroy(&s.AIG));
    PetscCall(MatDestroy(&s.PhiG));
    PetscCall(MatDestroy(&s.PhiI));
    PetscCall(KSPDestroy(&s.ksp));
    PetscCall(VecDestroy(&s.x));
    PetscCall(VecDestroy(&s.y));
  }
  const PetscInt n = (PetscInt)gd->sub->size();
  if (gd->AovlArr) PetscCall(MatDestroySubMatrices(n, &gd->AovlArr));
  gd->sub->clear();
  gd->sets->clear();
  PetscCall(PetscSFDestroy(&gd->nodeSF));
  PetscCall(MatDestroy(&gd->A));
  PetscCall(MatDestroy(&gd->Phi));
  PetscCall(MatDestroy(&gd->PhiFull));
  PetscCall(ISDestroy(&gd->keptCols));
  PetscCall(MatDestroy(&gd->A0));
  PetscCall(KSPDestroy(&gd->coarseKsp));
  PetscCall(VecDestroy(&gd->r0));
  PetscCall(VecDestroy(&gd->x0));
  PetscCall(VecDestroy(&gd->work));
  PetscCall(VecDestroy(&gd->workOut));
  PetscCall(VecScatterDestroy(&gd->restrictTo));
  PetscCall(VecScatterDestroy(&gd->prolongFrom));
  PetscCall(VecDestroy(&gd->tmp1));
  gd->coarseDim = 0;
  gd->counts[0] = gd->counts[1] = gd->counts[2] = 0;
  PetscFunctionReturn(0);
}

static PetscErrorCode DestroyUserSubdomains(PC_GDSW *gd)
{
  PetscFunctionBegin;
  for (PetscInt i = 0; i < gd->nUser; i++) {
    PetscCall(ISDestroy(&gd->userNon[i]));
    if (gd->userOvl) PetscCall(ISDestroy(&gd->userOvl[i]));
  }
  PetscCall(PetscFree(gd->userNon));
  PetscCall(PetscFree(gd->userOvl));
  gd->nUser = -1;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCDestroy_GDSW(PC pc)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCall(PCReset_GDSW(pc));
  PetscCall(DestroyUserSubdomains(gd));
  PetscCall(PetscFree(gd->coords));
  delete gd->sub;
  delete gd->sets;
  PetscCall(PetscObjectComposeFunction((PetscObject)pc, "PCSetCoordinates_C", nullptr));
  PetscCall(PetscFree(pc->data));
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

static PetscErrorCode PCSetUp_GDSW(PC pc)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  const PetscBool fresh = (PetscBool)(!pc->setupcalled || pc->flag == DIFFERENT_NONZERO_PATTERN);
  if (fresh) {
    PetscCall(PCReset_GDSW(pc));
    PetscCall(GetAIJOperator(pc, MAT_INITIAL_MATRIX));
    PetscCall(PetscLogEventBegin(GDSW_Decomposition, pc, 0, 0, 0));
    PetscCall(GDSWBuildDecomposition(pc));
    PetscCall(GDSWExtractSubdomainMatrices(pc, MAT_INITIAL_MATRIX));
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
    PetscCall(GDSWSetUpFirstLevel(pc, MAT_INITIAL_MATRIX));
    if (gd->coarseActive && gd->combination == PC_GDSW_MULTIPLICATIVE) PetscCall(MatCreateVecs(gd->A, &gd->tmp1, nullptr)); /* residual after the coarse correction */
  } else {
    /* same pattern, new values (Newton, time stepping): numeric refactorisations only */
    PetscCall(GetAIJOperator(pc, MAT_REUSE_MATRIX));
    PetscCall(GDSWExtractSubdomainMatrices(pc, MAT_REUSE_MATRIX));
    if (gd->coarseActive) {
      if (!gd->reuseCoarseBasis) PetscCall(GDSWUpdateCoarseBasis(pc));
      PetscCall(GDSWSetUpCoarseSolver(pc, (PetscBool)!gd->reuseCoarseBasis));
    }
    PetscCall(GDSWSetUpFirstLevel(pc, MAT_REUSE_MATRIX));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode PCApply_GDSW(PC pc, Vec x, Vec y)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(GDSW_Apply, pc, x, y, 0));
  PetscCall(VecSet(y, 0.0));
  const PetscBool coarse = gd->coarseActive;
  if (coarse && gd->combination == PC_GDSW_MULTIPLICATIVE) {
    /* y = Q0 x + M1 (x - A Q0 x) */
    PetscCall(GDSWApplyCoarse(pc, x, y));
    PetscCall(MatMult(pc->pmat, y, gd->tmp1));
    PetscCall(VecAYPX(gd->tmp1, -1.0, x));
    PetscCall(GDSWApplyFirstLevel(pc, gd->tmp1, y));
  } else {
    PetscCall(GDSWApplyFirstLevel(pc, x, y));
    if (coarse) PetscCall(GDSWApplyCoarse(pc, x, y));
  }
  PetscCall(PetscLogEventEnd(GDSW_Apply, pc, x, y, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCSetFromOptions_GDSW(PC pc, PetscOptionItems *PetscOptionsObject)
{
  PC_GDSW  *gd = (PC_GDSW *)pc->data;
  PetscBool flg;
  PetscInt  n;

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "GDSW two-level overlapping Schwarz options");
  n = gd->nsubPerRank;
  PetscCall(PetscOptionsInt("-pc_gdsw_subdomains", "Subdomains per MPI rank (METIS on the rank's node graph); -1 (PETSC_DECIDE): about -pc_gdsw_subdomain_size dofs each", "PCGDSWSetSubdomainsPerRank", n, &n, &flg));
  if (flg) PetscCall(PCGDSWSetSubdomainsPerRank(pc, n));
  n = gd->subdomainSize;
  PetscCall(PetscOptionsInt("-pc_gdsw_subdomain_size", "Target dofs per subdomain when -pc_gdsw_subdomains is not given (the fastest on 3D elasticity here)", "", n, &n, &flg));
  PetscCheck(n >= 1, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE, "PCGDSW: -pc_gdsw_subdomain_size %" PetscInt_FMT " is out of range: give the target number of dofs per subdomain, at least 1", n);
  gd->subdomainSize = n;
  n = gd->overlap;
  PetscCall(PetscOptionsInt("-pc_gdsw_overlap", "Overlap in layers of the matrix graph (used when the caller gives no overlapping subdomains)", "PCGDSWSetOverlap", n, &n, &flg));
  if (flg) PetscCall(PCGDSWSetOverlap(pc, n));
  PetscCall(PetscOptionsEnum("-pc_gdsw_coarse_space", "Coarse space", "PCGDSWSetCoarseSpaceType", PCGDSWCoarseSpaceTypes, (PetscEnum)gd->coarseType, (PetscEnum *)&gd->coarseType, nullptr));
  PetscCall(PetscOptionsEnum("-pc_gdsw_rgdsw_weights", "RGDSW partition of unity: equal (option 1) or by inverse distance to the coarse nodes (option 2.2, needs coordinates)", "", PCGDSWRGDSWWeightTypes, (PetscEnum)gd->rgdswWeights, (PetscEnum *)&gd->rgdswWeights, nullptr));
  PetscCall(PetscOptionsBool("-pc_gdsw_rotations", "Use the rotations of the null space (false: GDSW-nr, translations only)", "PCGDSWSetRotations", gd->rotations, &gd->rotations, nullptr));
  PetscCall(PetscOptionsEnum("-pc_gdsw_combination", "How the coarse and local corrections are combined", "", PCGDSWCombinationTypes, (PetscEnum)gd->combination, (PetscEnum *)&gd->combination, nullptr));
  PetscCall(PetscOptionsEnum("-pc_gdsw_first_level_type", "Plain additive (symmetric) or restricted (RAS) prolongation of the local corrections", "", PCGDSWFirstLevelTypes, (PetscEnum)gd->firstLevel, (PetscEnum *)&gd->firstLevel, nullptr));
  PetscCall(PetscOptionsBool("-pc_gdsw_reuse_coarse_basis", "Keep Phi when the operator's values change; recompute only A_0 = Phi^T A Phi", "", gd->reuseCoarseBasis, &gd->reuseCoarseBasis, nullptr));
  PetscOptionsHeadEnd();
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
                                   gd->coarseType != PC_GDSW_COARSE_NONE && !gd->rotations ? " without rotations" : "", PCGDSWCombinationTypes[gd->combination], PCGDSWFirstLevelTypes[gd->firstLevel]));
  if (!pc->setupcalled) {
    if (gd->nsubPerRank == PETSC_DECIDE) PetscCall(PetscViewerASCIIPrintf(viewer, "  subdomains per rank: chosen at setup for about %" PetscInt_FMT " dofs each, overlap %" PetscInt_FMT " (not set up yet)\n", gd->subdomainSize, gd->overlap));
    else PetscCall(PetscViewerASCIIPrintf(viewer, "  subdomains per rank %" PetscInt_FMT ", overlap %" PetscInt_FMT " (not set up yet)\n", gd->nsubPerRank, gd->overlap));
    PetscFunctionReturn(0);
  }
  const char *source = gd->nUser >= 0 ? "given by the application" : "from the matrix graph";
  PetscBool   isIS;
  PetscCall(PetscObjectTypeCompare((PetscObject)pc->pmat, MATIS, &isIS));
  if (isIS && gd->nUser < 0) source = "from the MATIS local-to-global map";
  if (gd->nUser < 0) {
    if (gd->nsubPerRank == PETSC_DECIDE) PetscCall(PetscViewerASCIIPrintf(viewer, "  subdomains per rank: chosen by the size rule, about %" PetscInt_FMT " dofs each (-pc_gdsw_subdomain_size): %" PetscInt_FMT " on rank 0\n", gd->subdomainSize, gd->nsubRank0));
    else PetscCall(PetscViewerASCIIPrintf(viewer, "  subdomains per rank: %" PetscInt_FMT ", given (-pc_gdsw_subdomains)\n", gd->nsubPerRank));
  }
  PetscCall(PetscViewerASCIIPrintf(viewer, "  %" PetscInt_FMT " subdomains (%s), overlap %s, %" PetscInt_FMT " dofs per node, %" PetscInt_FMT " null-space vectors%s\n", gd->nGlobalSubdomains, source,
                                   gd->nUser >= 0 && gd->userOvl ? "given by the application" : (std::to_string(gd->overlap) + " graph layers").c_str(), gd->bs, gd->nz, gd->haveCoords ? " (rigid modes from coordinates)" : ""));
  PetscCall(PetscViewerASCIIPrintf(viewer, "  interface components: %" PetscInt_FMT " faces, %" PetscInt_FMT " edges, %" PetscInt_FMT " vertices; %" PetscInt_FMT " Dirichlet dofs excluded\n", gd->counts[0], gd->counts[1], gd->counts[2], gd->nDirichletRows));
  if (gd->coarseType != PC_GDSW_COARSE_NONE && !gd->coarseActive) PetscCall(PetscViewerASCIIPrintf(viewer, "  no interface, hence no coarse level\n"));
  if (gd->coarseActive) {
    PetscCall(PetscViewerASCIIPrintf(viewer, "  coarse dimension %" PetscInt_FMT "%s\n", gd->coarseDim, gd->reuseCoarseBasis ? " (basis reused across setups)" : ""));
    PetscCall(PetscViewerASCIIPrintf(viewer, "  coarse solver (prefix -%spc_gdsw_coarse_):\n", ((PetscObject)pc)->prefix ? ((PetscObject)pc)->prefix : ""));
    PetscCall(PetscViewerASCIIPushTab(viewer));
    PetscCall(KSPView(gd->coarseKsp, viewer));
    PetscCall(PetscViewerASCIIPopTab(viewer));
  }
  PetscCall(GDSWViewLocalSolvers(pc, viewer));
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

static PetscErrorCode PCSetCoordinates_GDSW(PC pc, PetscInt dim, PetscInt n, PetscReal *coords)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCheck(dim >= 1 && dim <= 3, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE, "PCGDSW: PCSetCoordinates() dimension %" PetscInt_FMT " must be 1, 2 or 3", dim);
  PetscCall(PetscFree(gd->coords));
  PetscCall(PetscMalloc1(dim * n, &gd->coords));
  PetscCall(PetscArraycpy(gd->coords, coords, dim * n));
  gd->coordDim = dim, gd->nCoordNodes = n;
  PetscFunctionReturn(0);
}

static PC_GDSW *Data(PC pc)
{
  PetscBool same;
  PetscObjectTypeCompare((PetscObject)pc, PCGDSW, &same);
  return same ? (PC_GDSW *)pc->data : nullptr;
}

PetscErrorCode PCGDSWSetSubdomains(PC pc, PetscInt n, IS non[], IS ovl[])
{
  PC_GDSW *gd = Data(pc);

  PetscFunctionBegin;
  if (!gd) PetscFunctionReturn(0);
  PetscCheck(n >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "PCGDSWSetSubdomains: the number of subdomains %" PetscInt_FMT " must be >= 0", n);
  for (PetscInt i = 0; i < n; i++) PetscCall(PetscObjectReference((PetscObject)non[i]));
  if (ovl)
    for (PetscInt i = 0; i < n; i++) PetscCall(PetscObjectReference((PetscObject)ovl[i]));
  PetscCall(DestroyUserSubdomains(gd));
  PetscCall(PetscMalloc1(n, &gd->userNon));
  for (PetscInt i = 0; i < n; i++) gd->userNon[i] = non[i];
  if (ovl) {
    PetscCall(PetscMalloc1(n, &gd->userOvl));
    for (PetscInt i = 0; i < n; i++) gd->userOvl[i] = ovl[i];
  }
  gd->nUser       = n;
  pc->setupcalled = 0;
  PetscFunctionReturn(0);
}

PetscErrorCode PCGDSWSetSubdomainsPerRank(PC pc, PetscInt n)
{
  PC_GDSW *gd = Data(pc);

  PetscFunctionBegin;
  if (!gd) PetscFunctionReturn(0);
  PetscCheck(n >= 1 || n == PETSC_DECIDE, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE, "PCGDSW: -pc_gdsw_subdomains %" PetscInt_FMT " is out of range: give the number of subdomains per MPI rank, at least 1, or -1 (PETSC_DECIDE) for about -pc_gdsw_subdomain_size dofs each", n);
  gd->nsubPerRank = n;
  PetscFunctionReturn(0);
}

PetscErrorCode PCGDSWSetOverlap(PC pc, PetscInt k)
{
  PC_GDSW *gd = Data(pc);

  PetscFunctionBegin;
  if (!gd) PetscFunctionReturn(0);
  PetscCheck(k >= 0, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE, "PCGDSW: -pc_gdsw_overlap %" PetscInt_FMT " is out of range: give the number of layers, 0 or more", k);
  gd->overlap = k;
  PetscFunctionReturn(0);
}

PetscErrorCode PCGDSWSetCoarseSpaceType(PC pc, PCGDSWCoarseSpaceType t)
{
  PC_GDSW *gd = Data(pc);

  PetscFunctionBegin;
  if (gd) gd->coarseType = t;
  PetscFunctionReturn(0);
}

PetscErrorCode PCGDSWSetRotations(PC pc, PetscBool r)
{
  PC_GDSW *gd = Data(pc);

  PetscFunctionBegin;
  if (gd) gd->rotations = r;
  PetscFunctionReturn(0);
}

#define GDSW_REQUIRE_SETUP(pc, gd) \
  PetscCheck((gd) && (pc)->setupcalled, PetscObjectComm((PetscObject)(pc)), PETSC_ERR_ARG_WRONGSTATE, "PCGDSW: call PCSetUp() on a PC of type gdsw first")

PetscErrorCode PCGDSWGetCoarseBasis(PC pc, Mat *Phi)
{
  PC_GDSW *gd = Data(pc);

  PetscFunctionBegin;
  GDSW_REQUIRE_SETUP(pc, gd);
  *Phi = gd->Phi;
  PetscFunctionReturn(0);
}

PetscErrorCode PCGDSWGetCoarseOperator(PC pc, Mat *A0)
{
  PC_GDSW *gd = Data(pc);

  PetscFunctionBegin;
  GDSW_REQUIRE_SETUP(pc, gd);
  *A0 = gd->A0;
  PetscFunctionReturn(0);
}

PetscErrorCode PCGDSWGetCoarseKSP(PC pc, KSP *ksp)
{
  PC_GDSW *gd = Data(pc);

  PetscFunctionBegin;
  GDSW_REQUIRE_SETUP(pc, gd);
  *ksp = gd->coarseKsp;
  PetscFunctionReturn(0);
}

PetscErrorCode PCGDSWGetInterfaceCounts(PC pc, PetscInt *faces, PetscInt *edges, PetscInt *vertices)
{
  PC_GDSW *gd = Data(pc);

  PetscFunctionBegin;
  GDSW_REQUIRE_SETUP(pc, gd);
  if (faces) *faces = gd->counts[0];
  if (edges) *edges = gd->counts[1];
  if (vertices) *vertices = gd->counts[2];
  PetscFunctionReturn(0);
}

/*MC
   PCGDSW - two-level overlapping Schwarz with an energy-minimising (GDSW or RGDSW) coarse space.

   Options Database Keys:
+  -pc_gdsw_subdomains <-1> - subdomains per MPI rank (METIS on the rank's node graph); -1 (PETSC_DECIDE): the size rule
.  -pc_gdsw_subdomain_size <12000> - the size rule's target dofs per subdomain
.  -pc_gdsw_overlap <1> - overlap in layers of the matrix graph
.  -pc_gdsw_coarse_space <gdsw,rgdsw,none> - coarse space
.  -pc_gdsw_rgdsw_weights <distance,equal> - RGDSW partition of unity (equal without coordinates)
.  -pc_gdsw_rotations <true> - false gives GDSW-nr (translations only)
.  -pc_gdsw_combination <additive,multiplicative> - combination of the two levels
.  -pc_gdsw_first_level_type <additive,restricted> - prolongation of local corrections
-  -pc_gdsw_reuse_coarse_basis <false> - keep Phi across setups with new values

   Subsolvers: -pc_gdsw_sub_ (overlapping subdomains), -pc_gdsw_extension_ (interiors, for the
   harmonic extension), -pc_gdsw_coarse_ (A_0).
M*/
PETSC_EXTERN PetscErrorCode PCCreate_GDSW(PC pc)
{
  PC_GDSW *gd;

  PetscFunctionBegin;
  PetscCall(PetscNew(&gd));
  pc->data             = gd;
  gd->nsubPerRank      = PETSC_DECIDE;
  gd->subdomainSize    = 12000;
  gd->overlap          = 1;
  gd->coarseType       = PC_GDSW_COARSE_GDSW;
  gd->combination      = PC_GDSW_ADDITIVE;
  gd->firstLevel       = PC_GDSW_FIRST_LEVEL_ADDITIVE;
  gd->rotations        = PETSC_TRUE;
  gd->rgdswWeights     = PC_GDSW_RGDSW_WEIGHTS_DISTANCE;
  gd->reuseCoarseBasis = PETSC_FALSE;
  gd->nUser            = -1;
  gd->sub              = new std::vector<gdsw::Subdomain>();
  gd->sets             = new std::vector<std::vector<PetscInt>>();

  pc->ops->setup          = PCSetUp_GDSW;
  pc->ops->apply          = PCApply_GDSW;
  pc->ops->reset          = PCReset_GDSW;
  pc->ops->destroy        = PCDestroy_GDSW;
  pc->ops->setfromoptions = PCSetFromOptions_GDSW;
  pc->ops->view           = PCView_GDSW;
  PetscCall(PetscObjectComposeFunction((PetscObject)pc, "PCSetCoordinates_C", PCSetCoordinates_GDSW));
  PetscFunctionReturn(0);
}

PetscErrorCode PCGDSWRegister(void)
{
  static PetscBool registered = PETSC_FALSE;

  PetscFunctionBegin;
  if (registered) PetscFunctionReturn(0);
  registered = PETSC_TRUE;
  PetscCall(PCRegister(PCGDSW, PCCreate_GDSW));
  PetscCall(PetscLogEventRegister("GDSWDecomp", PC_CLASSID, &GDSW_Decomposition));
  PetscCall(PetscLogEventRegister("GDSWInterface", PC_CLASSID, &GDSW_Interface));
  PetscCall(PetscLogEventRegister("GDSWBasis", PC_CLASSID, &GDSW_Basis));
  PetscCall(PetscLogEventRegister("GDSWExtension", PC_CLASSID, &GDSW_Extension));
  PetscCall(PetscLogEventRegister("GDSWCoarseSetUp", PC_CLASSID, &GDSW_CoarseSetUp));
  PetscCall(PetscLogEventRegister("GDSWLocalFactor", PC_CLASSID, &GDSW_LocalFactor));
  PetscCall(PetscLogEventRegister("GDSWApply", PC_CLASSID, &GDSW_Apply));
  PetscFunctionReturn(0);
}

/* what -dll_append looks up */
PETSC_EXTERN PetscErrorCode PetscDLLibraryRegister_petscgdsw(void)
{
  PetscFunctionBegin;
  PetscCall(PCGDSWRegister());
  PetscFunctionReturn(0);
}
