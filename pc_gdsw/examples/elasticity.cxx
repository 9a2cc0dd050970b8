static const char help[] = "Q1 linear elasticity on the unit cube, clamped at x = 0, under gravity,\n"
                           "solved with any PETSc KSP/PC; with -pc_type gdsw it can hand the PC an element-based box\n"
                           "decomposition. Prints one summary line: iterations, coarse dimension, times.\n"
                           "Options:\n"
                           "  -n <8>             elements per direction\n"
                           "  -boxes <0>         give the PC b x b x b element boxes as subdomains (0: let the PC decide)\n"
                           "  -E <1> -nu <0.3>   Young's modulus and Poisson ratio\n"
                           "  -jump <1>          Young's modulus of every other box (checkerboard of -jump_boxes boxes)\n"
                           "  -jump_boxes <2>    boxes per direction of the coefficient checkerboard\n"
                           "  -nullspace <near>  near: MatSetNearNullSpace(rigid modes); coords: PCSetCoordinates; none\n"
                           "  -floating          no Dirichlet condition (the null space is attached to the operator)\n"
                           "  -check_phi         report how well the coarse basis reproduces the rigid-body modes\n"
                           "  -resolve_jump <0>  then reassemble with this -jump (same pattern) and solve again\n"
                           "  -mat_type <aij>    any assembled type (aij, baij, sbaij), or is (MATIS: each rank's element layers are its subdomain, for PCBDDC)\n";

#include <petscgdsw.h>
#include <petscksp.h>
#include <vector>

struct Problem {
  PetscInt  n = 8, boxes = 0, jumpBoxes = 2;
  PetscReal E = 1.0, nu = 0.3, jump = 1.0;
  PetscBool floating = PETSC_FALSE;
  PetscInt  k0, k1; /* node layers (z) owned by this rank */
};

static PetscInt Node(const Problem &p, PetscInt i, PetscInt j, PetscInt k) { return i + (p.n + 1) * (j + (p.n + 1) * k); }

/* Stiffness of the reference cube [0,h]^3 for unit E: 2x2x2 Gauss, exact for Q1. */
static void ElementStiffness(PetscReal h, PetscReal nu, PetscReal K[24][24])
{
  const PetscReal lam = nu / ((1 + nu) * (1 - 2 * nu)), mu = 1.0 / (2 * (1 + nu));
  const PetscReal g = 1.0 / std::sqrt(3.0);
  for (int a = 0; a < 24; a++)
    for (int b = 0; b < 24; b++) K[a][b] = 0;
  for (int q = 0; q < 8; q++) {
    const PetscReal xi[3] = {(q & 1) ? g : -g, (q & 2) ? g : -g, (q & 4) ? g : -g};
    PetscReal       dN[8][3];
    for (int a = 0; a < 8; a++) {
      const PetscReal s[3] = {(a & 1) ? 1.0 : -1.0, (a & 2) ? 1.0 : -1.0, (a & 4) ? 1.0 : -1.0};
      for (int d = 0; d < 3; d++) {
        PetscReal v = s[d] / 8.0;
        for (int e = 0; e < 3; e++)
          if (e != d) v *= 1 + s[e] * xi[e];
        dN[a][d] = v * 2.0 / h;
      }
    }
    const PetscReal w = h * h * h / 8.0;
    for (int a = 0; a < 8; a++)
      for (int b = 0; b < 8; b++) {
        PetscReal dot = 0;
        for (int d = 0; d < 3; d++) dot += dN[a][d] * dN[b][d];
        for (int i = 0; i < 3; i++)
          for (int j = 0; j < 3; j++) K[3 * a + i][3 * b + j] += w * (lam * dN[a][i] * dN[b][j] + mu * dN[a][j] * dN[b][i] + (i == j ? mu * dot : 0));
      }
  }
}

static PetscErrorCode Assemble(const Problem &p, Mat A, Vec b)
{
  const PetscReal h = 1.0 / p.n;
  PetscReal       K[24][24], Ke[24 * 24], fe[24];

  PetscFunctionBegin;
  ElementStiffness(h, p.nu, K);
  const PetscInt kEnd = std::min(p.k1, p.n); /* element layers whose lower nodes this rank owns */
  for (PetscInt k = p.k0; k < kEnd; k++)
    for (PetscInt j = 0; j < p.n; j++)
      for (PetscInt i = 0; i < p.n; i++) {
        const PetscInt c = p.jumpBoxes * i / p.n + p.jumpBoxes * j / p.n + p.jumpBoxes * k / p.n;
        const PetscReal E = p.E * (c % 2 ? p.jump : 1.0);
        PetscInt        rows[24];
        for (int a = 0; a < 8; a++) {
          const PetscInt nd = Node(p, i + (a & 1), j + ((a >> 1) & 1), k + ((a >> 2) & 1));
          for (int d = 0; d < 3; d++) rows[3 * a + d] = 3 * nd + d, fe[3 * a + d] = d == 2 ? -h * h * h / 8.0 : 0.0;
        }
        for (int r = 0; r < 24; r++)
          for (int s = 0; s < 24; s++) Ke[24 * r + s] = E * K[r][s];
        PetscCall(MatSetValues(A, 24, rows, 24, rows, Ke, ADD_VALUES));
        PetscCall(VecSetValues(b, 24, rows, fe, ADD_VALUES));
      }
  PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  PetscCall(VecAssemblyBegin(b));
  PetscCall(VecAssemblyEnd(b));
  PetscFunctionReturn(0);
}

/* MATIS: the local matrix of a rank is assembled from its own element layers, whose nodes
   (layers k0 .. min(k1, n)) are its local-to-global map. Other types need nothing here. */
static PetscErrorCode SubassembledLayout(const Problem &p, Mat A)
{
  PetscBool isIS;

  PetscFunctionBegin;
  PetscCall(PetscObjectTypeCompare((PetscObject)A, MATIS, &isIS));
  if (!isIS) PetscFunctionReturn(0);
  const PetscInt        kEnd = std::min(p.k1, p.n), plane = (p.n + 1) * (p.n + 1);
  std::vector<PetscInt> nodes;
  for (PetscInt k = p.k0; p.k0 < kEnd && k <= kEnd; k++) /* a rank without elements holds no nodes */
    for (PetscInt q = 0; q < plane; q++) nodes.push_back(k * plane + q);
  ISLocalToGlobalMapping l2g;
  PetscCall(ISLocalToGlobalMappingCreate(PETSC_COMM_WORLD, 3, (PetscInt)nodes.size(), nodes.data(), PETSC_COPY_VALUES, &l2g));
  PetscCall(MatSetLocalToGlobalMapping(A, l2g, l2g));
  PetscCall(ISLocalToGlobalMappingDestroy(&l2g));
  PetscCall(MatISSetPreallocation(A, 81, nullptr, 0, nullptr));
  PetscFunctionReturn(0);
}

/* Dirichlet condition on x = 0 (symmetric elimination), or, floating, a consistent load. */
static PetscErrorCode Constrain(const Problem &p, Mat A, Vec b, Vec x, MatNullSpace rigid)
{
  PetscFunctionBegin;
  if (p.floating) {
    PetscCall(MatNullSpaceRemove(rigid, b));
    PetscFunctionReturn(0);
  }
  std::vector<PetscInt> rows;
  for (PetscInt k = p.k0; k < p.k1; k++)
    for (PetscInt j = 0; j <= p.n; j++)
      for (int d = 0; d < 3; d++) rows.push_back(3 * Node(p, 0, j, k) + d);
  PetscCall(VecSet(x, 0.0));
  PetscCall(MatZeroRowsColumns(A, (PetscInt)rows.size(), rows.data(), 1.0, x, b));
  PetscFunctionReturn(0);
}

/* Element boxes b x b x b, dealt to ranks in order: the closure of each box's cells. */
static PetscErrorCode BoxSubdomains(const Problem &p, std::vector<IS> &boxes)
{
  PetscMPIInt rank, size;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  const PetscInt nb = p.boxes * p.boxes * p.boxes;
  for (PetscInt q = nb * rank / size; q < nb * (rank + 1) / size; q++) {
    const PetscInt bi = q % p.boxes, bj = (q / p.boxes) % p.boxes, bk = q / (p.boxes * p.boxes);
    auto lo = [&](PetscInt b) { return b * p.n / p.boxes; };
    std::vector<PetscInt> nodes;
    for (PetscInt k = lo(bk); k <= lo(bk + 1); k++)
      for (PetscInt j = lo(bj); j <= lo(bj + 1); j++)
        for (PetscInt i = lo(bi); i <= lo(bi + 1); i++) nodes.push_back(Node(p, i, j, k));
    IS is;
    PetscCall(ISCreateBlock(PETSC_COMM_SELF, 3, (PetscInt)nodes.size(), nodes.data(), PETSC_COPY_VALUES, &is));
    boxes.push_back(is);
  }
  PetscFunctionReturn(0);
}

/* max over rigid modes z of |Phi c - z| / |z| with c the least-squares coefficients */
static PetscErrorCode CheckPhi(PC pc, MatNullSpace rigid)
{
  Mat        Phi, PtP;
  KSP        ksp;
  PetscInt   nv;
  const Vec *z;
  PetscBool  hasConst;
  Vec        c, Ptz, r;
  PetscReal  worst = 0;

  PetscFunctionBegin;
  PetscCall(PCGDSWGetCoarseBasis(pc, &Phi));
  PetscCall(MatTransposeMatMult(Phi, Phi, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &PtP));
  PetscCall(KSPCreate(PETSC_COMM_WORLD, &ksp));
  PetscCall(KSPSetOperators(ksp, PtP, PtP));
  PetscCall(KSPSetType(ksp, KSPCG));
  PetscCall(KSPSetTolerances(ksp, 1e-14, 1e-30, PETSC_DEFAULT, 2000));
  PetscCall(MatCreateVecs(Phi, &c, &r));
  PetscCall(VecDuplicate(c, &Ptz));
  PetscCall(MatNullSpaceGetVecs(rigid, &hasConst, &nv, &z));
  for (PetscInt k = 0; k < nv; k++) {
    PetscReal nr, nz;
    PetscCall(MatMultTranspose(Phi, z[k], Ptz));
    PetscCall(KSPSolve(ksp, Ptz, c));
    PetscCall(MatMult(Phi, c, r));
    PetscCall(VecAXPY(r, -1.0, z[k]));
    PetscCall(VecNorm(r, NORM_2, &nr));
    PetscCall(VecNorm(z[k], NORM_2, &nz));
    worst = std::max(worst, nr / nz);
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "rigid-body modes reproduced by Phi: max relative error %.3e\n", (double)worst));
  PetscCall(VecDestroy(&c));
  PetscCall(VecDestroy(&Ptz));
  PetscCall(VecDestroy(&r));
  PetscCall(KSPDestroy(&ksp));
  PetscCall(MatDestroy(&PtP));
  PetscFunctionReturn(0);
}

/* One summary line per solve: what the tests and benchmarks read. */
static PetscErrorCode Report(KSP ksp, Mat A, PetscLogDouble setup, PetscLogDouble solve)
{
  PetscInt           its, M, coarse = 0, faces = 0, edges = 0, vertices = 0;
  KSPConvergedReason reason;
  PetscBool          isGDSW;
  PetscMPIInt        size;
  PC                 pc;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(KSPGetIterationNumber(ksp, &its));
  PetscCall(KSPGetConvergedReason(ksp, &reason));
  PetscCall(MatGetSize(A, &M, nullptr));
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCGDSW, &isGDSW));
  if (isGDSW) {
    Mat Phi;
    PetscCall(PCGDSWGetInterfaceCounts(pc, &faces, &edges, &vertices));
    PetscCall(PCGDSWGetCoarseBasis(pc, &Phi));
    if (Phi) PetscCall(MatGetSize(Phi, nullptr, &coarse));
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "dofs %" PetscInt_FMT " ranks %d iterations %" PetscInt_FMT " reason %s coarse %" PetscInt_FMT " faces %" PetscInt_FMT " edges %" PetscInt_FMT " vertices %" PetscInt_FMT " setup %.3f s solve %.3f s\n",
                        M, size, its, KSPConvergedReasons[reason], coarse, faces, edges, vertices, setup, solve));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  Problem     p;
  PetscMPIInt rank, size;
  char        nsp[16] = "near";
  PetscBool   checkPhi = PETSC_FALSE;
  PetscReal   resolveJump = 0;

  PetscCall(PetscInitialize(&argc, &argv, nullptr, help));
  PetscCall(PCGDSWRegister());
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  PetscOptionsBegin(PETSC_COMM_WORLD, nullptr, "Elasticity test problem", nullptr);
  PetscCall(PetscOptionsInt("-n", "elements per direction", nullptr, p.n, &p.n, nullptr));
  PetscCall(PetscOptionsInt("-boxes", "element boxes per direction given to PCGDSW (0: none)", nullptr, p.boxes, &p.boxes, nullptr));
  PetscCall(PetscOptionsReal("-E", "Young's modulus", nullptr, p.E, &p.E, nullptr));
  PetscCall(PetscOptionsReal("-nu", "Poisson ratio", nullptr, p.nu, &p.nu, nullptr));
  PetscCall(PetscOptionsReal("-jump", "Young's modulus factor on every other box", nullptr, p.jump, &p.jump, nullptr));
  PetscCall(PetscOptionsInt("-jump_boxes", "boxes per direction of the coefficient checkerboard", nullptr, p.jumpBoxes, &p.jumpBoxes, nullptr));
  PetscCall(PetscOptionsString("-nullspace", "near, coords or none", nullptr, nsp, nsp, sizeof(nsp), nullptr));
  PetscCall(PetscOptionsBool("-floating", "no Dirichlet condition", nullptr, p.floating, &p.floating, nullptr));
  PetscCall(PetscOptionsBool("-check_phi", "check that Phi reproduces the rigid-body modes", nullptr, checkPhi, &checkPhi, nullptr));
  PetscCall(PetscOptionsReal("-resolve_jump", "reassemble with this jump and solve again (0: no)", nullptr, resolveJump, &resolveJump, nullptr));
  PetscOptionsEnd();
  PetscCheck(p.n >= 1, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-n %" PetscInt_FMT ": need at least one element per direction", p.n);
  PetscCheck(p.boxes >= 0 && p.boxes <= p.n, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-boxes %" PetscInt_FMT ": must be between 0 and -n %" PetscInt_FMT, p.boxes, p.n);
  PetscCheck(!strcmp(nsp, "near") || !strcmp(nsp, "coords") || !strcmp(nsp, "none"), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-nullspace %s: use near, coords or none", nsp);

  /* rows: node layers in z, split evenly over the ranks */
  const PetscInt layers = p.n + 1, plane = (p.n + 1) * (p.n + 1);
  p.k0 = layers * rank / size, p.k1 = layers * (rank + 1) / size;
  const PetscInt nloc = (p.k1 - p.k0) * plane;
  Mat A;
  Vec b, x, coords;
  PetscCall(MatCreate(PETSC_COMM_WORLD, &A));
  PetscCall(MatSetSizes(A, 3 * nloc, 3 * nloc, PETSC_DETERMINE, PETSC_DETERMINE));
  PetscCall(MatSetBlockSize(A, 3));
  PetscCall(MatSetType(A, MATAIJ));
  PetscCall(MatSetFromOptions(A));
  PetscCall(SubassembledLayout(p, A));
  PetscCall(MatSeqAIJSetPreallocation(A, 81, nullptr));
  PetscCall(MatMPIAIJSetPreallocation(A, 81, nullptr, 81, nullptr));
  PetscCall(MatSeqBAIJSetPreallocation(A, 3, 27, nullptr));
  PetscCall(MatMPIBAIJSetPreallocation(A, 3, 27, nullptr, 27, nullptr));
  PetscCall(MatSeqSBAIJSetPreallocation(A, 3, 27, nullptr));
  PetscCall(MatMPISBAIJSetPreallocation(A, 3, 27, nullptr, 27, nullptr));
  {
    PetscBool sbaij;
    PetscCall(PetscObjectTypeCompareAny((PetscObject)A, &sbaij, MATSEQSBAIJ, MATMPISBAIJ, ""));
    if (sbaij) PetscCall(MatSetOption(A, MAT_IGNORE_LOWER_TRIANGULAR, PETSC_TRUE));
  }
  PetscCall(MatCreateVecs(A, &x, &b));
  PetscCall(Assemble(p, A, b));

  /* coordinates of the owned nodes */
  PetscCall(VecCreate(PETSC_COMM_WORLD, &coords));
  PetscCall(VecSetSizes(coords, 3 * nloc, PETSC_DECIDE));
  PetscCall(VecSetBlockSize(coords, 3));
  PetscCall(VecSetFromOptions(coords));
  {
    PetscScalar *c;
    PetscCall(VecGetArray(coords, &c));
    for (PetscInt q = 0; q < nloc; q++) {
      const PetscInt g = p.k0 * plane + q;
      c[3 * q + 0] = (g % (p.n + 1)) / (PetscReal)p.n;
      c[3 * q + 1] = ((g / (p.n + 1)) % (p.n + 1)) / (PetscReal)p.n;
      c[3 * q + 2] = (g / plane) / (PetscReal)p.n;
    }
    PetscCall(VecRestoreArray(coords, &c));
  }
  MatNullSpace rigid;
  PetscCall(MatNullSpaceCreateRigidBody(coords, &rigid));
  if (!strcmp(nsp, "near")) PetscCall(MatSetNearNullSpace(A, rigid));

  if (p.floating) PetscCall(MatSetNullSpace(A, rigid));
  PetscCall(Constrain(p, A, b, x, rigid));

  KSP ksp;
  PC  pc;
  PetscCall(KSPCreate(PETSC_COMM_WORLD, &ksp));
  PetscCall(KSPSetOperators(ksp, A, A));
  PetscCall(KSPSetType(ksp, KSPCG));
  PetscCall(KSPSetTolerances(ksp, 1e-8, PETSC_DEFAULT, PETSC_DEFAULT, 1000));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCGDSW));
  PetscCall(KSPSetFromOptions(ksp));
  if (!strcmp(nsp, "coords")) {
    const PetscScalar *c;
    std::vector<PetscReal> xyz(3 * nloc);
    PetscCall(VecGetArrayRead(coords, &c));
    for (PetscInt q = 0; q < 3 * nloc; q++) xyz[q] = PetscRealPart(c[q]);
    PetscCall(VecRestoreArrayRead(coords, &c));
    PetscCall(PCSetCoordinates(pc, 3, nloc, xyz.data()));
  }
  std::vector<IS> boxes;
  if (p.boxes) {
    PetscCall(BoxSubdomains(p, boxes));
    PetscCall(PCGDSWSetSubdomains(pc, (PetscInt)boxes.size(), boxes.data(), nullptr));
  }

  PetscLogDouble t0, t1, t2;
  PetscCall(PetscTime(&t0));
  PetscCall(KSPSetUp(ksp));
  PetscCall(PetscTime(&t1));
  PetscCall(KSPSolve(ksp, b, x));
  PetscCall(PetscTime(&t2));

  PetscCall(Report(ksp, A, t1 - t0, t2 - t1));
  if (checkPhi) PetscCall(CheckPhi(pc, rigid));
  if (resolveJump > 0) { /* new values, same pattern: the PC refactors and re-extends */
    p.jump = resolveJump;
    PetscCall(MatZeroEntries(A));
    PetscCall(VecZeroEntries(b));
    PetscCall(Assemble(p, A, b));
    PetscCall(Constrain(p, A, b, x, rigid));
    PetscCall(PetscTime(&t0));
    PetscCall(PCSetUp(pc));
    PetscCall(PetscTime(&t1));
    PetscCall(KSPSolve(ksp, b, x));
    PetscCall(PetscTime(&t2));
    PetscCall(Report(ksp, A, t1 - t0, t2 - t1));
  }

  for (IS &is : boxes) PetscCall(ISDestroy(&is));
  PetscCall(MatNullSpaceDestroy(&rigid));
  PetscCall(KSPDestroy(&ksp));
  PetscCall(VecDestroy(&coords));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  PetscCall(MatDestroy(&A));
  PetscCall(PetscFinalize());
  return 0;
}

/*TEST

   # PETSc test-harness format (config/testparse.py); run with scripts/petsc-harness.
   # No reference output: the summary line carries timings, so the harness checks that the
   # solve ran and converged instead of diffing.
   test:
      suffix: boxes
      nsize: {{1 2}}
      args: -n 8 -boxes 2

   test:
      suffix: metis
      args: -n 16 -pc_gdsw_subdomains 8

   test:
      suffix: rgdsw
      args: -n 8 -boxes 2 -pc_gdsw_coarse_space rgdsw

TEST*/
