// SPDX-License-Identifier: BSD-2-Clause
static const char help[] = "Exercises PCGDSW's API on a nonsymmetric problem: upwind convection-diffusion\n"
                           "-Laplace(u) + beta (1, 1/2) . grad(u) = 1 on the unit square, zero on its boundary, n x n interior nodes.\n"
                           "  -case transpose  <P^T x, y> = <x, P y> for random x, y; GMRES with KSPSolve and KSPSolveTranspose\n"
                           "  -case coarse_exact  |P A Phi c - Phi c| / |Phi c| and |P^T A^T Phi c - Phi c| / |Phi c| for random c\n"
                           "  -case setters    a solve, then the setter named by -set changes its parameter, and a second solve\n"
                           "  -case threads    the process's threads and OpenMP max-active-levels (set to 2) before and after the set-up\n"
                           "  -set <overlap>   subdomains (4 per rank), repartition (true), subdomain_size (200), overlap (2),\n"
                           "                   coarse_space (none), combination (additive), first_level_type (restricted)\n"
                           "                   or local_solver (incomplete)\n"
                           "  -n <32> -beta <20>  grid and wind speed\n"
                           "  -rounds <1>      run the case this many times, each between its own PetscInitialize() and PetscFinalize()\n"
                           "Every case prints the PC's settings as its getters return them.\n";

#include <petscgdsw.h>
#include <fstream>
#include <omp.h>
#include <string>

/* h^2 times the upwind difference operator (wind beta (1, 1/2) > 0: backward differences). */
static PetscErrorCode ConvectionDiffusion(PetscInt n, PetscReal beta, Mat *A)
{
  const PetscReal h = 1.0 / (n + 1), bx = beta * h, by = 0.5 * beta * h;
  PetscInt        rstart, rend;

  PetscFunctionBegin;
  PetscCall(MatCreateAIJ(PETSC_COMM_WORLD, PETSC_DECIDE, PETSC_DECIDE, n * n, n * n, 5, nullptr, 4, nullptr, A));
  PetscCall(MatGetOwnershipRange(*A, &rstart, &rend));
  for (PetscInt r = rstart; r < rend; r++) {
    const PetscInt i = r % n, j = r / n;
    PetscCall(MatSetValue(*A, r, r, 4.0 + bx + by, INSERT_VALUES));
    if (i > 0) PetscCall(MatSetValue(*A, r, r - 1, -1.0 - bx, INSERT_VALUES));
    if (i < n - 1) PetscCall(MatSetValue(*A, r, r + 1, -1.0, INSERT_VALUES));
    if (j > 0) PetscCall(MatSetValue(*A, r, r - n, -1.0 - by, INSERT_VALUES));
    if (j < n - 1) PetscCall(MatSetValue(*A, r, r + n, -1.0, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*A, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

/* The settings as the getters see them. */
static PetscErrorCode PrintSettings(PC pc)
{
  PetscInt              nsub, size, overlap;
  PCGDSWCoarseSpaceType coarse;
  PCGDSWRGDSWWeightType weights;
  PCCompositeType       combination;
  PCGDSWFirstLevelType  first;
  PCGDSWLocalSolverType local;
  PCGDSWLocalPrecision  precision;
  PCGDSWConfiguration   configuration;
  PetscReal             conditionMax;
  PetscBool             rotations, reuse, repartition, huge;

  PetscFunctionBegin;
  PetscCall(PCGDSWGetSubdomainsPerRank(pc, &nsub));
  PetscCall(PCGDSWGetRepartition(pc, &repartition));
  PetscCall(PCGDSWGetSubdomainSize(pc, &size));
  PetscCall(PCGDSWGetOverlap(pc, &overlap));
  PetscCall(PCGDSWGetCoarseSpaceType(pc, &coarse));
  PetscCall(PCGDSWGetRGDSWWeightType(pc, &weights));
  PetscCall(PCGDSWGetRotations(pc, &rotations));
  PetscCall(PCGDSWGetCombinationType(pc, &combination));
  PetscCall(PCGDSWGetFirstLevelType(pc, &first));
  PetscCall(PCGDSWGetReuseCoarseBasis(pc, &reuse));
  PetscCall(PCGDSWGetLocalSolverType(pc, &local));
  PetscCall(PCGDSWGetLocalConditionMax(pc, &conditionMax));
  PetscCall(PCGDSWGetHugePages(pc, &huge));
  PetscCall(PCGDSWGetLocalPrecision(pc, &precision));
  PetscCall(PCGDSWGetConfiguration(pc, &configuration));
  const char *const combinationName = combination == PC_COMPOSITE_ADDITIVE ? "additive" : combination == PC_COMPOSITE_MULTIPLICATIVE ? "multiplicative" : "symmetric_multiplicative";
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "settings: subdomains %" PetscInt_FMT " repartition %d subdomain_size %" PetscInt_FMT " overlap %" PetscInt_FMT " coarse_space %s rgdsw_weights %s rotations %d combination %s first_level_type %s reuse_coarse_basis %d local_solver %s local_condition_max %g local_precision %s huge_pages %d configuration %s\n",
                        nsub, (int)repartition, size, overlap, PCGDSWCoarseSpaceTypes[coarse], PCGDSWRGDSWWeightTypes[weights], (int)rotations, combinationName, PCGDSWFirstLevelTypes[first], (int)reuse, PCGDSWLocalSolverTypes[local], (double)conditionMax, PCGDSWLocalPrecisions[precision], (int)huge, PCGDSWConfigurations[configuration]));
  PetscFunctionReturn(0);
}

/* One line per solve: iterations, reason, the true residual of A x = b (or A^T x = b), and the
   size of the decomposition (dofs of all overlapping subdomains) and of the coarse space. */
static PetscErrorCode Solve(KSP ksp, PetscBool transpose, const char *what)
{
  Mat                A, A0;
  PC                 pc;
  Vec                b, x, r;
  PetscInt           its, nsub, ovlDofs = 0, total, coarse = 0;
  IS                *ovl;
  PetscReal          nr, nb;
  KSPConvergedReason reason;

  PetscFunctionBegin;
  PetscCall(KSPGetOperators(ksp, &A, nullptr));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(MatCreateVecs(A, &x, &b));
  PetscCall(VecDuplicate(b, &r));
  PetscCall(VecSet(b, 1.0));
  if (transpose) PetscCall(KSPSolveTranspose(ksp, b, x));
  else PetscCall(KSPSolve(ksp, b, x));
  PetscCall(KSPGetIterationNumber(ksp, &its));
  PetscCall(KSPGetConvergedReason(ksp, &reason));
  if (transpose) PetscCall(MatMultTranspose(A, x, r));
  else PetscCall(MatMult(A, x, r));
  PetscCall(VecAYPX(r, -1.0, b));
  PetscCall(VecNorm(r, NORM_2, &nr));
  PetscCall(VecNorm(b, NORM_2, &nb));
  PetscCall(PCGDSWGetSubdomains(pc, &nsub, nullptr, &ovl));
  for (PetscInt i = 0; i < nsub; i++) {
    PetscInt m;
    PetscCall(ISGetLocalSize(ovl[i], &m));
    ovlDofs += m;
  }
  PetscCallMPI(MPIU_Allreduce(&ovlDofs, &total, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCall(PCGDSWGetCoarseOperator(pc, &A0));
  if (A0) PetscCall(MatGetSize(A0, nullptr, &coarse));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s: iterations %" PetscInt_FMT " reason %s residual %.3e overlap_dofs %" PetscInt_FMT " coarse %" PetscInt_FMT "\n", what, its, KSPConvergedReasons[reason], (double)(nr / nb), total, coarse));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  PetscCall(VecDestroy(&r));
  PetscFunctionReturn(0);
}

/* max over random pairs of |<P^T x, y> - <x, P y>| / (|x| |P y|), and how far P is from
   symmetric (|P^T x - P x| / |P x|), so that the first is not trivially small. */
static PetscErrorCode CheckAdjoint(PC pc, Mat A)
{
  Vec         x, y, Py, PTx, Px;
  PetscRandom rnd;
  PetscReal   worst = 0, asym = 0;

  PetscFunctionBegin;
  PetscCall(MatCreateVecs(A, &x, &y));
  PetscCall(VecDuplicate(x, &Py));
  PetscCall(VecDuplicate(x, &PTx));
  PetscCall(VecDuplicate(x, &Px));
  PetscCall(PetscRandomCreate(PETSC_COMM_WORLD, &rnd));
  PetscCall(PetscRandomSetInterval(rnd, -1.0, 1.0));
  for (int k = 0; k < 3; k++) {
    PetscScalar a, b;
    PetscReal   nx, nPy, nPx, nd;
    PetscCall(VecSetRandom(x, rnd));
    PetscCall(VecSetRandom(y, rnd));
    PetscCall(PCApply(pc, y, Py));
    PetscCall(PCApplyTranspose(pc, x, PTx));
    PetscCall(VecDot(PTx, y, &a));
    PetscCall(VecDot(x, Py, &b));
    PetscCall(VecNorm(x, NORM_2, &nx));
    PetscCall(VecNorm(Py, NORM_2, &nPy));
    worst = PetscMax(worst, PetscAbsScalar(a - b) / (nx * nPy));
    PetscCall(PCApply(pc, x, Px));
    PetscCall(VecNorm(Px, NORM_2, &nPx));
    PetscCall(VecAXPY(Px, -1.0, PTx));
    PetscCall(VecNorm(Px, NORM_2, &nd));
    asym = PetscMax(asym, nd / nPx);
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "adjoint: max relative error %.3e asymmetry %.3e\n", (double)worst, (double)asym));
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&y));
  PetscCall(VecDestroy(&Py));
  PetscCall(VecDestroy(&PTx));
  PetscCall(VecDestroy(&Px));
  PetscFunctionReturn(0);
}

/* The symmetric multiplicative (balanced) combination solves the coarse space exactly: P A Phi = Phi and P^T A^T Phi = Phi,
   what neither the additive nor the multiplicative one does. Worst of three random c. */
static PetscErrorCode CheckCoarseExact(PC pc, Mat A)
{
  Mat         Phi;
  Vec         c, v, Av, w;
  PetscRandom rnd;
  PetscReal   worst[2] = {0, 0};

  PetscFunctionBegin;
  PetscCall(PCGDSWGetCoarseBasis(pc, &Phi));
  PetscCall(MatCreateVecs(Phi, &c, &v));
  PetscCall(VecDuplicate(v, &Av));
  PetscCall(VecDuplicate(v, &w));
  PetscCall(PetscRandomCreate(PETSC_COMM_WORLD, &rnd));
  PetscCall(PetscRandomSetInterval(rnd, -1.0, 1.0));
  for (int k = 0; k < 3; k++)
    for (int t = 0; t < 2; t++) {
      PetscReal nv, nd;
      PetscCall(VecSetRandom(c, rnd));
      PetscCall(MatMult(Phi, c, v));
      if (t) {
        PetscCall(MatMultTranspose(A, v, Av));
        PetscCall(PCApplyTranspose(pc, Av, w));
      } else {
        PetscCall(MatMult(A, v, Av));
        PetscCall(PCApply(pc, Av, w));
      }
      PetscCall(VecNorm(v, NORM_2, &nv));
      PetscCall(VecAXPY(w, -1.0, v));
      PetscCall(VecNorm(w, NORM_2, &nd));
      worst[t] = PetscMax(worst[t], nd / nv);
    }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "coarse: forward %.3e transpose %.3e\n", (double)worst[0], (double)worst[1]));
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(VecDestroy(&c));
  PetscCall(VecDestroy(&v));
  PetscCall(VecDestroy(&Av));
  PetscCall(VecDestroy(&w));
  PetscFunctionReturn(0);
}

/* The setter -set names, with a value other than the default. */
static PetscErrorCode ChangeOne(PC pc)
{
  char name[64] = "overlap";

  PetscFunctionBegin;
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-set", name, sizeof(name), nullptr));
  const std::string what = name;
  if (what == "subdomains") PetscCall(PCGDSWSetSubdomainsPerRank(pc, 4));
  else if (what == "repartition") PetscCall(PCGDSWSetRepartition(pc, PETSC_TRUE));
  else if (what == "subdomain_size") PetscCall(PCGDSWSetSubdomainSize(pc, 200));
  else if (what == "overlap") PetscCall(PCGDSWSetOverlap(pc, 2));
  else if (what == "coarse_space") PetscCall(PCGDSWSetCoarseSpaceType(pc, PC_GDSW_COARSE_NONE));
  else if (what == "combination") PetscCall(PCGDSWSetCombinationType(pc, PC_COMPOSITE_ADDITIVE));
  else if (what == "first_level_type") PetscCall(PCGDSWSetFirstLevelType(pc, PC_GDSW_FIRST_LEVEL_RESTRICTED));
  else if (what == "local_solver") PetscCall(PCGDSWSetLocalSolverType(pc, PC_GDSW_LOCAL_INCOMPLETE));
  else if (what == "configuration") PetscCall(PCGDSWSetConfiguration(pc, PC_GDSW_CONFIGURATION_FAST));
  else SETERRQ(PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-set %s is not one of the setters listed by -help", name);
  PetscFunctionReturn(0);
}

/* The "Threads:" line of /proc/self/status: an OpenMP team, once opened, stays in the process. */
static PetscInt ProcessThreads()
{
  std::ifstream status("/proc/self/status");
  std::string   key;
  PetscInt      n = -1;
  while (status >> key)
    if (key == "Threads:") status >> n;
  return n;
}

static PetscErrorCode Run(const std::string &c)
{
  PetscInt  n    = 32;
  PetscReal beta = 20;
  Mat       A;
  KSP       ksp;
  PC        pc;

  PetscFunctionBegin;
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-n", &n, nullptr));
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-beta", &beta, nullptr));
  PetscCall(PCGDSWRegister());
  PetscCall(ConvectionDiffusion(n, beta, &A));
  PetscCall(KSPCreate(PETSC_COMM_WORLD, &ksp));
  PetscCall(KSPSetOperators(ksp, A, A));
  PetscCall(KSPSetType(ksp, KSPGMRES));
  PetscCall(KSPSetPCSide(ksp, PC_RIGHT)); /* the convergence test sees the true residual */
  PetscCall(KSPSetTolerances(ksp, 1e-8, PETSC_DEFAULT, PETSC_DEFAULT, 500));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCGDSW));
  PetscCall(KSPSetFromOptions(ksp));
  PetscCall(PrintSettings(pc));
  omp_set_max_active_levels(2);
  const PetscInt threads = ProcessThreads();
  PetscCall(KSPSetUp(ksp));
  if (c == "threads") {
    PetscCall(PetscSynchronizedPrintf(PETSC_COMM_WORLD, "threads before %" PetscInt_FMT " after %" PetscInt_FMT " levels before 2 after %d\n", threads, ProcessThreads(), omp_get_max_active_levels()));
    PetscCall(PetscSynchronizedFlush(PETSC_COMM_WORLD, PETSC_STDOUT));
  } else if (c == "transpose") {
    PetscCall(CheckAdjoint(pc, A));
    PetscCall(Solve(ksp, PETSC_FALSE, "forward"));
    PetscCall(Solve(ksp, PETSC_TRUE, "transpose"));
  } else if (c == "coarse_exact") {
    PetscCall(CheckCoarseExact(pc, A));
  } else if (c == "setters") {
    PetscCall(Solve(ksp, PETSC_FALSE, "first"));
    PetscCall(ChangeOne(pc));
    PetscCall(PrintSettings(pc));
    PetscCall(Solve(ksp, PETSC_FALSE, "second"));
  } else SETERRQ(PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-case %s is not one of the cases listed by -help", c.c_str());
  PetscCall(KSPDestroy(&ksp));
  PetscCall(MatDestroy(&A));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  PetscInt rounds = 1;

  PetscCallMPI(MPI_Init(&argc, &argv)); /* MPI outlives each PETSc round */
  for (PetscInt round = 0; round < rounds; round++) {
    char name[64] = "transpose";
    PetscCall(PetscInitialize(&argc, &argv, nullptr, help));
    PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-rounds", &rounds, nullptr));
    PetscCall(PetscOptionsGetString(nullptr, nullptr, "-case", name, sizeof(name), nullptr));
    PetscCall(Run(name));
    PetscCall(PetscFinalize());
  }
  PetscCallMPI(MPI_Finalize());
  return 0;
}

/*TEST

   # PETSc test-harness format (config/testparse.py); run with scripts/petsc-harness.
   test:
      suffix: transpose
      nsize: 2
      args: -case transpose -pc_gdsw_subdomains 4

TEST*/
