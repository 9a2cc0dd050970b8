// SPDX-License-Identifier: BSD-2-Clause
/* PCGDSW: two-level overlapping Schwarz with the GDSW coarse space (Dohrmann, Klawonn,
   Widlund 2008; Heinlein, Klawonn, Rheinbach 2015, eq. 1):
       M^{-1} = Phi (Phi^T A Phi)^{-1} Phi^T + sum_i R_i^T A_i^{-1} R_i.
   This file holds the PC object: options, the order of the setup modules, apply and its
   transpose, view, the composed methods and the registration; api.cxx the public functions. */
#include "gdswimpl.h"
#include <string>

const char *const PCGDSWCoarseSpaceTypes[] = {"gdsw", "rgdsw", "none", "PCGDSWCoarseSpaceType", "PC_GDSW_COARSE_", nullptr};
const char *const PCGDSWFirstLevelTypes[]  = {"additive", "restricted", "PCGDSWFirstLevelType", "PC_GDSW_FIRST_LEVEL_", nullptr};
const char *const PCGDSWRGDSWWeightTypes[] = {"equal", "distance", "PCGDSWRGDSWWeightType", "PC_GDSW_RGDSW_WEIGHTS_", nullptr};
const char *const PCGDSWLocalSolverTypes[] = {"exact", "incomplete", "adaptive", "PCGDSWLocalSolverType", "PC_GDSW_LOCAL_", nullptr};
const char *const PCGDSWLocalPrecisions[]  = {"double", "single", "PCGDSWLocalPrecision", "PC_GDSW_LOCAL_PRECISION_", nullptr};
/* the PCCompositeType values PCGDSW takes, in their order in PCCompositeTypes[] */
static const char *const CombinationTypes[] = {"additive", "multiplicative", "symmetric_multiplicative", "PCCompositeType", "PC_COMPOSITE_", nullptr};

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
    PetscCall(GDSWDirichletRowsChanged(pc, &fresh));
    if (fresh) PetscCall(PetscInfo(pc, "the operator's Dirichlet rows changed with the same pattern: the decomposition and the coarse space are rebuilt\n"));
  }
  if (fresh) {
    PetscCall(PCReset_GDSW(pc));
    PetscCall(GetAIJOperator(pc, MAT_INITIAL_MATRIX));
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

/* What each integer option takes: the end of its error messages. */
static const char SubdomainsRange[]    = "give the number of subdomains per MPI rank, at least 1, or -1 (PETSC_DECIDE) for about -pc_gdsw_subdomain_size dofs each";
static const char SubdomainSizeRange[] = "give the target number of dofs per subdomain, at least 1";
static const char OverlapRange[]       = "give the number of layers, 0 or more";
static const char ConditionRange[]     = "give the largest condition number estimate at which a subdomain keeps its incomplete factor, a finite number of at least 1";

/* PETSc's parsers reject a malformed value on every rank, each printing a message that names
   neither the option nor (for numbers) what it takes: check the value first, once for the PC
   (kind: OPTION_INT, OPTION_REAL, OPTION_BOOL, or OPTION_ELIST with the enum's list). */
static PetscErrorCode CheckOptionValue(PC pc, const char name[], PetscOptionType kind, const char *const *list, const char range[])
{
  const char    *prefix = ((PetscObject)pc)->prefix;
  char           value[256];
  PetscBool      set, ok = PETSC_TRUE;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscCall(PetscOptionsGetString(((PetscObject)pc)->options, prefix, name, value, sizeof(value), &set));
  if (!set) PetscFunctionReturn(0);
  std::string allowed;
  if (kind == OPTION_ELIST) {
    PetscEnum e;
    PetscCall(PetscEnumFind(list, value, &e, &ok));
    allowed = "one of:";
    for (PetscInt i = 0; list[i + 2]; i++) allowed += std::string(i ? ", " : " ") + list[i]; /* the list ends with its type name, prefix, NULL */
  } else if (kind != OPTION_BOOL || value[0]) { /* a logical option without a value is true */
    PetscInt  i;
    PetscReal r = 0;
    PetscBool b;
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
    ierr = kind == OPTION_INT ? PetscOptionsStringToInt(value, &i) : kind == OPTION_REAL ? PetscOptionsStringToReal(value, &r) : PetscOptionsStringToBool(value, &b);
    PetscCall(PetscPopErrorHandler());
    ok      = (PetscBool)(!ierr && !PetscIsInfOrNanReal(r));
    allowed = kind == OPTION_INT ? std::string("an integer: ") + range : kind == OPTION_REAL ? std::string("a number: ") + range : "true or false";
  }
  PetscCheck(ok, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_WRONG, "PCGDSW: -%s%s %s is not %s", prefix ? prefix : "", name + 1, value[0] ? value : "(no value)", allowed.c_str());
  PetscFunctionReturn(0);
}

static PetscErrorCode PCSetFromOptions_GDSW(PC pc, PetscOptionItems *PetscOptionsObject)
{
  PC_GDSW              *gd = (PC_GDSW *)pc->data;
  PetscBool             flg, b;
  PetscInt              n;
  PCGDSWCoarseSpaceType coarse;
  PCGDSWRGDSWWeightType weights;
  PCCompositeType       combination;
  PCGDSWFirstLevelType  firstLevel;
  PCGDSWLocalSolverType local;
  PCGDSWLocalPrecision  precision;
  PetscReal             r;

  PetscFunctionBegin;
  PetscCall(CheckOptionValue(pc, "-pc_gdsw_subdomains", OPTION_INT, nullptr, SubdomainsRange));
  PetscCall(CheckOptionValue(pc, "-pc_gdsw_subdomain_size", OPTION_INT, nullptr, SubdomainSizeRange));
  PetscCall(CheckOptionValue(pc, "-pc_gdsw_overlap", OPTION_INT, nullptr, OverlapRange));
  PetscCall(CheckOptionValue(pc, "-pc_gdsw_coarse_space", OPTION_ELIST, PCGDSWCoarseSpaceTypes, nullptr));
  PetscCall(CheckOptionValue(pc, "-pc_gdsw_rgdsw_weights", OPTION_ELIST, PCGDSWRGDSWWeightTypes, nullptr));
  PetscCall(CheckOptionValue(pc, "-pc_gdsw_rotations", OPTION_BOOL, nullptr, nullptr));
  PetscCall(CheckOptionValue(pc, "-pc_gdsw_repartition", OPTION_BOOL, nullptr, nullptr));
  PetscCall(CheckOptionValue(pc, "-pc_gdsw_combination", OPTION_ELIST, CombinationTypes, nullptr));
  PetscCall(CheckOptionValue(pc, "-pc_gdsw_first_level_type", OPTION_ELIST, PCGDSWFirstLevelTypes, nullptr));
  PetscCall(CheckOptionValue(pc, "-pc_gdsw_reuse_coarse_basis", OPTION_BOOL, nullptr, nullptr));
  PetscCall(CheckOptionValue(pc, "-pc_gdsw_huge_pages", OPTION_BOOL, nullptr, nullptr));
  PetscCall(CheckOptionValue(pc, "-pc_gdsw_local_solver", OPTION_ELIST, PCGDSWLocalSolverTypes, nullptr));
  PetscCall(CheckOptionValue(pc, "-pc_gdsw_local_condition_max", OPTION_REAL, nullptr, ConditionRange));
  PetscCall(CheckOptionValue(pc, "-pc_gdsw_local_precision", OPTION_ELIST, PCGDSWLocalPrecisions, nullptr));
  PetscOptionsHeadBegin(PetscOptionsObject, "GDSW two-level overlapping Schwarz options");
  /* first: the size rule's default target depends on it */
  PetscCall(PetscOptionsEnum("-pc_gdsw_local_solver", "First level's local solvers: exact factorisations, incomplete ones (ICC(0)/ILU(0)), or adaptive: incomplete where its condition estimate is at most -pc_gdsw_local_condition_max, exact elsewhere", "PCGDSWSetLocalSolverType", PCGDSWLocalSolverTypes, (PetscEnum)gd->localSolver, (PetscEnum *)&local, &flg));
  if (flg) PetscCall(PCGDSWSetLocalSolverType(pc, local));
  PetscCall(PetscOptionsReal("-pc_gdsw_local_condition_max", "Adaptive local solvers: the largest condition estimate of an incomplete factor's preconditioned subdomain matrix that keeps it", "PCGDSWSetLocalConditionMax", gd->conditionMax, &r, &flg));
  if (flg) PetscCall(PCGDSWSetLocalConditionMax(pc, r));
  PetscCall(PetscOptionsEnum("-pc_gdsw_local_precision", "Precision the first level's Cholesky factors are kept and applied in: double, or single where that solves to within 1e-3 of double (MATSOLVERCHOLMODSINGLE; for CG and FGMRES: GMRES then stalls, near a relative residual of 1e-5 on elasticity)", "PCGDSWSetLocalPrecision", PCGDSWLocalPrecisions, (PetscEnum)gd->localPrecision, (PetscEnum *)&precision, &flg));
  if (flg) PetscCall(PCGDSWSetLocalPrecision(pc, precision));
  PetscCall(PetscOptionsInt("-pc_gdsw_subdomains", "Subdomains per MPI rank (METIS on the rank's node graph); -1 (PETSC_DECIDE): about -pc_gdsw_subdomain_size dofs each", "PCGDSWSetSubdomainsPerRank", gd->nsubPerRank, &n, &flg));
  if (flg) PetscCall(PCGDSWSetSubdomainsPerRank(pc, n));
  PetscCall(PetscOptionsBool("-pc_gdsw_repartition", "Subdomains from a parallel partition of the whole matrix graph (MatPartitioning, options -pc_gdsw_mat_partitioning_*) instead of METIS within each rank's rows", "PCGDSWSetRepartition", gd->repartition, &b, &flg));
  if (flg) PetscCall(PCGDSWSetRepartition(pc, b));
  PetscCall(PetscOptionsInt("-pc_gdsw_subdomain_size", "Target dofs per subdomain when -pc_gdsw_subdomains is not given (the fastest on 3D elasticity here: 12000 with exact local solvers, 3000 with incomplete or adaptive ones)", "PCGDSWSetSubdomainSize", GDSWSubdomainSizeTarget(gd), &n, &flg));
  if (flg) PetscCall(PCGDSWSetSubdomainSize(pc, n));
  PetscCall(PetscOptionsInt("-pc_gdsw_overlap", "Overlap in layers of the matrix graph (used when the caller gives no overlapping subdomains)", "PCGDSWSetOverlap", gd->overlap, &n, &flg));
  if (flg) PetscCall(PCGDSWSetOverlap(pc, n));
  PetscCall(PetscOptionsEnum("-pc_gdsw_coarse_space", "Coarse space", "PCGDSWSetCoarseSpaceType", PCGDSWCoarseSpaceTypes, (PetscEnum)gd->coarseType, (PetscEnum *)&coarse, &flg));
  if (flg) PetscCall(PCGDSWSetCoarseSpaceType(pc, coarse));
  PetscCall(PetscOptionsEnum("-pc_gdsw_rgdsw_weights", "RGDSW partition of unity: equal (option 1) or by inverse distance to the coarse nodes (option 2.2, needs coordinates)", "PCGDSWSetRGDSWWeightType", PCGDSWRGDSWWeightTypes, (PetscEnum)gd->rgdswWeights, (PetscEnum *)&weights, &flg));
  if (flg) PetscCall(PCGDSWSetRGDSWWeightType(pc, weights));
  PetscCall(PetscOptionsBool("-pc_gdsw_rotations", "Use the rotations of the null space (false: GDSW-nr, translations only)", "PCGDSWSetRotations", gd->rotations, &b, &flg));
  if (flg) PetscCall(PCGDSWSetRotations(pc, b));
  PetscCall(PetscOptionsEnum("-pc_gdsw_combination", "How the coarse and local corrections are combined", "PCGDSWSetCombinationType", CombinationTypes, (PetscEnum)gd->combination, (PetscEnum *)&combination, &flg));
  if (flg) PetscCall(PCGDSWSetCombinationType(pc, combination));
  PetscCall(PetscOptionsEnum("-pc_gdsw_first_level_type", "Plain additive (symmetric) or restricted (RAS) prolongation of the local corrections", "PCGDSWSetFirstLevelType", PCGDSWFirstLevelTypes, (PetscEnum)gd->firstLevel, (PetscEnum *)&firstLevel, &flg));
  if (flg) PetscCall(PCGDSWSetFirstLevelType(pc, firstLevel));
  PetscCall(PetscOptionsBool("-pc_gdsw_reuse_coarse_basis", "Keep Phi when the operator's values change; recompute only A_0 = Phi^T A Phi", "PCGDSWSetReuseCoarseBasis", gd->reuseCoarseBasis, &b, &flg));
  if (flg) PetscCall(PCGDSWSetReuseCoarseBasis(pc, b));
  PetscCall(PetscOptionsBool("-pc_gdsw_huge_pages", "During set-up, the blocks of 2 MiB or more it keeps (local factors, subdomain matrices) on transparent huge pages where the kernel gives them on request (mode madvise)", "PCGDSWSetHugePages", gd->hugePages, &b, &flg));
  if (flg) PetscCall(PCGDSWSetHugePages(pc, b));
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
                                   gd->coarseType != PC_GDSW_COARSE_NONE && !gd->rotations ? " without rotations" : "", CombinationTypes[gd->combination], PCGDSWFirstLevelTypes[gd->firstLevel]));
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

/* Coordinates change the coarse space: the next PCSetUp() starts afresh. */
static PetscErrorCode PCSetCoordinates_GDSW(PC pc, PetscInt dim, PetscInt n, PetscReal *coords)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCheck(dim >= 1 && dim <= 3, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE, "PCGDSW: PCSetCoordinates() dimension %" PetscInt_FMT " must be 1, 2 or 3", dim);
  for (PetscInt k = 0; k < dim * n; k++)
    PetscCheck(!PetscIsInfOrNanReal(coords[k]), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "PCGDSW: PCSetCoordinates() coordinate %" PetscInt_FMT " of local node %" PetscInt_FMT " is not finite (NaN or Inf): the rigid-body modes need finite coordinates", k % dim, k / dim);
  PetscCall(PetscFree(gd->coords));
  PetscCall(PetscMalloc1(dim * n, &gd->coords));
  PetscCall(PetscArraycpy(gd->coords, coords, dim * n));
  gd->coordDim = dim, gd->nCoordNodes = n;
  pc->setupcalled = 0;
  PetscFunctionReturn(0);
}

/* ---- the implementations of the public functions (their manual pages are further down) ---- */

static PetscErrorCode PCGDSWSetSubdomains_GDSW(PC pc, PetscInt n, IS non[], IS ovl[])
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
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

#define GDSW_REQUIRE_SETUP(pc) PetscCheck((pc)->setupcalled, PetscObjectComm((PetscObject)(pc)), PETSC_ERR_ARG_WRONGSTATE, "PCGDSW: call PCSetUp() first")

static PetscErrorCode PCGDSWGetSubdomains_GDSW(PC pc, PetscInt *n, IS *non[], IS *ovl[])
{
  PC_GDSW       *gd   = (PC_GDSW *)pc->data;
  const PetscInt nsub = (PetscInt)gd->sub->size();

  PetscFunctionBegin;
  GDSW_REQUIRE_SETUP(pc);
  if (!gd->nonArr && nsub) {
    PetscCall(PetscMalloc1(nsub, &gd->nonArr));
    PetscCall(PetscMalloc1(nsub, &gd->ovlArr));
    for (PetscInt i = 0; i < nsub; i++) gd->nonArr[i] = (*gd->sub)[i].nonoverlap, gd->ovlArr[i] = (*gd->sub)[i].overlap;
  }
  if (n) *n = nsub;
  if (non) *non = gd->nonArr;
  if (ovl) *ovl = gd->ovlArr;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetSubdomainsPerRank_GDSW(PC pc, PetscInt n)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCheck(n >= 1 || n == PETSC_DECIDE, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE, "PCGDSW: -pc_gdsw_subdomains %" PetscInt_FMT " is out of range: %s", n, SubdomainsRange);
  if (n != gd->nsubPerRank) pc->setupcalled = 0;
  gd->nsubPerRank = n;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetSubdomainsPerRank_GDSW(PC pc, PetscInt *n)
{
  PetscFunctionBegin;
  *n = ((PC_GDSW *)pc->data)->nsubPerRank;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetRepartition_GDSW(PC pc, PetscBool flg)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  if (flg != gd->repartition) pc->setupcalled = 0;
  gd->repartition = flg;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetRepartition_GDSW(PC pc, PetscBool *flg)
{
  PetscFunctionBegin;
  *flg = ((PC_GDSW *)pc->data)->repartition;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetSubdomainSize_GDSW(PC pc, PetscInt n)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCheck(n >= 1 || n == PETSC_DECIDE, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE, "PCGDSW: -pc_gdsw_subdomain_size %" PetscInt_FMT " is out of range: %s", n, SubdomainSizeRange);
  if (n != gd->subdomainSize) pc->setupcalled = 0;
  gd->subdomainSize = n;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetSubdomainSize_GDSW(PC pc, PetscInt *n)
{
  PetscFunctionBegin;
  *n = GDSWSubdomainSizeTarget((PC_GDSW *)pc->data);
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetOverlap_GDSW(PC pc, PetscInt k)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCheck(k >= 0, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE, "PCGDSW: -pc_gdsw_overlap %" PetscInt_FMT " is out of range: %s", k, OverlapRange);
  if (k != gd->overlap) pc->setupcalled = 0;
  gd->overlap = k;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetOverlap_GDSW(PC pc, PetscInt *k)
{
  PetscFunctionBegin;
  *k = ((PC_GDSW *)pc->data)->overlap;
  PetscFunctionReturn(0);
}

/* An enum value from the API (options are checked by name in CheckOptionValue()). */
#define GDSW_CHECK_ENUM(pc, t, last, list) \
  PetscCheck((t) >= 0 && (t) <= (last), PetscObjectComm((PetscObject)(pc)), PETSC_ERR_ARG_OUTOFRANGE, "PCGDSW: %d is not a valid %s", (int)(t), (list)[(last) + 1])

static PetscErrorCode PCGDSWSetLocalSolverType_GDSW(PC pc, PCGDSWLocalSolverType t)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  GDSW_CHECK_ENUM(pc, t, PC_GDSW_LOCAL_ADAPTIVE, PCGDSWLocalSolverTypes);
  if (t != gd->localSolver) pc->setupcalled = 0; /* new local solvers, and the size rule's target may change */
  gd->localSolver = t;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetLocalSolverType_GDSW(PC pc, PCGDSWLocalSolverType *t)
{
  PetscFunctionBegin;
  *t = ((PC_GDSW *)pc->data)->localSolver;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetLocalConditionMax_GDSW(PC pc, PetscReal c)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCheck(c >= 1 && !PetscIsInfOrNanReal(c), PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE, "PCGDSW: -pc_gdsw_local_condition_max %g is out of range: %s", (double)c, ConditionRange);
  if (c != gd->conditionMax) pc->setupcalled = 0;
  gd->conditionMax = c;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetLocalConditionMax_GDSW(PC pc, PetscReal *c)
{
  PetscFunctionBegin;
  *c = ((PC_GDSW *)pc->data)->conditionMax;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetCoarseSpaceType_GDSW(PC pc, PCGDSWCoarseSpaceType t)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  GDSW_CHECK_ENUM(pc, t, PC_GDSW_COARSE_NONE, PCGDSWCoarseSpaceTypes);
  if (t != gd->coarseType) pc->setupcalled = 0;
  gd->coarseType = t;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetCoarseSpaceType_GDSW(PC pc, PCGDSWCoarseSpaceType *t)
{
  PetscFunctionBegin;
  *t = ((PC_GDSW *)pc->data)->coarseType;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetRGDSWWeightType_GDSW(PC pc, PCGDSWRGDSWWeightType t)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  GDSW_CHECK_ENUM(pc, t, PC_GDSW_RGDSW_WEIGHTS_DISTANCE, PCGDSWRGDSWWeightTypes);
  if (t != gd->rgdswWeights) pc->setupcalled = 0;
  gd->rgdswWeights = t;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetRGDSWWeightType_GDSW(PC pc, PCGDSWRGDSWWeightType *t)
{
  PetscFunctionBegin;
  *t = ((PC_GDSW *)pc->data)->rgdswWeights;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetRotations_GDSW(PC pc, PetscBool flg)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  if (flg != gd->rotations) pc->setupcalled = 0;
  gd->rotations = flg;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetRotations_GDSW(PC pc, PetscBool *flg)
{
  PetscFunctionBegin;
  *flg = ((PC_GDSW *)pc->data)->rotations;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetCombinationType_GDSW(PC pc, PCCompositeType t)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCheck(t == PC_COMPOSITE_ADDITIVE || t == PC_COMPOSITE_MULTIPLICATIVE || t == PC_COMPOSITE_SYMMETRIC_MULTIPLICATIVE, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE,
             "PCGDSW: the combination %s is not one PCGDSW does: use PC_COMPOSITE_ADDITIVE, PC_COMPOSITE_MULTIPLICATIVE or PC_COMPOSITE_SYMMETRIC_MULTIPLICATIVE", t >= 0 && t <= PC_COMPOSITE_GKB ? PCCompositeTypes[t] : "(out of range)");
  if (t != gd->combination) pc->setupcalled = 0; /* the multiplicative and balanced ones have work vectors, the balanced one W */
  gd->combination = t;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetCombinationType_GDSW(PC pc, PCCompositeType *t)
{
  PetscFunctionBegin;
  *t = ((PC_GDSW *)pc->data)->combination;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetFirstLevelType_GDSW(PC pc, PCGDSWFirstLevelType t)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  GDSW_CHECK_ENUM(pc, t, PC_GDSW_FIRST_LEVEL_RESTRICTED, PCGDSWFirstLevelTypes);
  if (t != gd->firstLevel) pc->setupcalled = 0; /* the restricted prolongation has its own scatter */
  gd->firstLevel = t;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetFirstLevelType_GDSW(PC pc, PCGDSWFirstLevelType *t)
{
  PetscFunctionBegin;
  *t = ((PC_GDSW *)pc->data)->firstLevel;
  PetscFunctionReturn(0);
}

/* Read at the next setup with new values: nothing to rebuild. */
static PetscErrorCode PCGDSWSetReuseCoarseBasis_GDSW(PC pc, PetscBool flg)
{
  PetscFunctionBegin;
  ((PC_GDSW *)pc->data)->reuseCoarseBasis = flg;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetLocalPrecision_GDSW(PC pc, PCGDSWLocalPrecision p)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  GDSW_CHECK_ENUM(pc, p, PC_GDSW_LOCAL_PRECISION_SINGLE, PCGDSWLocalPrecisions);
  if (p != gd->localPrecision) pc->setupcalled = 0; /* new local factors */
  gd->localPrecision = p;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetLocalPrecision_GDSW(PC pc, PCGDSWLocalPrecision *p)
{
  PetscFunctionBegin;
  *p = ((PC_GDSW *)pc->data)->localPrecision;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetHugePages_GDSW(PC pc, PetscBool flg)
{
  PetscFunctionBegin;
  ((PC_GDSW *)pc->data)->hugePages = flg;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetHugePages_GDSW(PC pc, PetscBool *flg)
{
  PetscFunctionBegin;
  *flg = ((PC_GDSW *)pc->data)->hugePages;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetReuseCoarseBasis_GDSW(PC pc, PetscBool *flg)
{
  PetscFunctionBegin;
  *flg = ((PC_GDSW *)pc->data)->reuseCoarseBasis;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetCoarseBasis_GDSW(PC pc, Mat *Phi)
{
  PetscFunctionBegin;
  GDSW_REQUIRE_SETUP(pc);
  PC_GDSW *gd = (PC_GDSW *)pc->data;
  if (gd->Phi) PetscCall(GDSWAssemblePhiMatrix(pc));
  *Phi = gd->PhiAssembled;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetCoarseOperator_GDSW(PC pc, Mat *A0)
{
  PetscFunctionBegin;
  GDSW_REQUIRE_SETUP(pc);
  *A0 = ((PC_GDSW *)pc->data)->A0;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetCoarseKSP_GDSW(PC pc, KSP *ksp)
{
  PetscFunctionBegin;
  GDSW_REQUIRE_SETUP(pc);
  *ksp = ((PC_GDSW *)pc->data)->coarseKsp;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetInterfaceCounts_GDSW(PC pc, PetscInt *faces, PetscInt *edges, PetscInt *vertices)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  GDSW_REQUIRE_SETUP(pc);
  if (faces) *faces = gd->counts[0];
  if (edges) *edges = gd->counts[1];
  if (vertices) *vertices = gd->counts[2];
  PetscFunctionReturn(0);
}

/* The composed methods, added in PCCreate_GDSW() and removed in PCDestroy_GDSW(). */
static PetscErrorCode ComposeMethods(PC pc, PetscBool add)
{
  PetscObject o = (PetscObject)pc;

  PetscFunctionBegin;
#define GDSW_COMPOSE(name) PetscCall(PetscObjectComposeFunction(o, #name "_C", add ? name##_GDSW : nullptr))
  GDSW_COMPOSE(PCSetCoordinates);
  GDSW_COMPOSE(PCGDSWSetSubdomains);
  GDSW_COMPOSE(PCGDSWGetSubdomains);
  GDSW_COMPOSE(PCGDSWSetSubdomainsPerRank);
  GDSW_COMPOSE(PCGDSWGetSubdomainsPerRank);
  GDSW_COMPOSE(PCGDSWSetRepartition);
  GDSW_COMPOSE(PCGDSWGetRepartition);
  GDSW_COMPOSE(PCGDSWSetSubdomainSize);
  GDSW_COMPOSE(PCGDSWGetSubdomainSize);
  GDSW_COMPOSE(PCGDSWSetOverlap);
  GDSW_COMPOSE(PCGDSWGetOverlap);
  GDSW_COMPOSE(PCGDSWSetLocalSolverType);
  GDSW_COMPOSE(PCGDSWGetLocalSolverType);
  GDSW_COMPOSE(PCGDSWSetLocalConditionMax);
  GDSW_COMPOSE(PCGDSWGetLocalConditionMax);
  GDSW_COMPOSE(PCGDSWSetLocalPrecision);
  GDSW_COMPOSE(PCGDSWGetLocalPrecision);
  GDSW_COMPOSE(PCGDSWSetCoarseSpaceType);
  GDSW_COMPOSE(PCGDSWGetCoarseSpaceType);
  GDSW_COMPOSE(PCGDSWSetRGDSWWeightType);
  GDSW_COMPOSE(PCGDSWGetRGDSWWeightType);
  GDSW_COMPOSE(PCGDSWSetRotations);
  GDSW_COMPOSE(PCGDSWGetRotations);
  GDSW_COMPOSE(PCGDSWSetCombinationType);
  GDSW_COMPOSE(PCGDSWGetCombinationType);
  GDSW_COMPOSE(PCGDSWSetFirstLevelType);
  GDSW_COMPOSE(PCGDSWGetFirstLevelType);
  GDSW_COMPOSE(PCGDSWSetReuseCoarseBasis);
  GDSW_COMPOSE(PCGDSWGetReuseCoarseBasis);
  GDSW_COMPOSE(PCGDSWSetHugePages);
  GDSW_COMPOSE(PCGDSWGetHugePages);
  GDSW_COMPOSE(PCGDSWGetCoarseBasis);
  GDSW_COMPOSE(PCGDSWGetCoarseOperator);
  GDSW_COMPOSE(PCGDSWGetCoarseKSP);
  GDSW_COMPOSE(PCGDSWGetInterfaceCounts);
#undef GDSW_COMPOSE
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
  delete gd->dirichletMask;
  PetscCall(ComposeMethods(pc, PETSC_FALSE));
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
+  -pc_gdsw_subdomains <-1> - subdomains per MPI rank, METIS on the rank's node graph; -1 (`PETSC_DECIDE`): about -pc_gdsw_subdomain_size dofs each (see `PCGDSWSetSubdomainsPerRank()`)
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
-  -pc_gdsw_local_precision <double> - single: the first level's Cholesky factors kept in single precision where that solves to within 1e-3 of double, for CG and FGMRES (see `PCGDSWSetLocalPrecision()`)

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
  pc->ops->reset          = PCReset_GDSW;
  pc->ops->destroy        = PCDestroy_GDSW;
  pc->ops->setfromoptions = PCSetFromOptions_GDSW;
  pc->ops->view           = PCView_GDSW;
  PetscCall(ComposeMethods(pc, PETSC_TRUE));
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
