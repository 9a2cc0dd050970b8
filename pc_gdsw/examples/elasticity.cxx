// SPDX-License-Identifier: BSD-2-Clause
static const char help[] = "Q1 linear elasticity on the unit cube (or square: plane strain), clamped at x = 0, under gravity,\n"
                           "solved with any PETSc KSP/PC; with -pc_type gdsw it can hand the PC an element-based box\n"
                           "decomposition. Prints one summary line: iterations, coarse dimension, times.\n"
                           "Options:\n"
                           "  -dim <3>           2 or 3\n"
                           "  -n <8>             elements per direction\n"
                           "  -boxes <0>         give the PC b^dim element boxes as subdomains (0: let the PC decide)\n"
                           "  -box_overlap <-1>  give each box's overlapping subdomain too: the box grown by this many element layers (-1: none)\n"
                           "  -E <1> -nu <0.3>   Young's modulus and Poisson ratio\n"
                           "  -jump <1>          Young's modulus of every other box (checkerboard of -jump_boxes boxes)\n"
                           "  -jump_boxes <2>    boxes per direction of the coefficient checkerboard\n"
                           "  -nullspace <near>  near: MatSetNearNullSpace(rigid modes); coords: PCSetCoordinates; none\n"
                           "  -floating          no Dirichlet condition (the null space is attached to the operator)\n"
                           "  -clamp_both        clamp x = 1 too\n"
                           "  -mat_type <aij>    any assembled type (aij, baij, sbaij), or is (MATIS: each rank's element layers are its subdomain, for PCBDDC)\n";

#include <petscgdsw.h>
#include <petscksp.h>
#include <vector>

struct Problem {
  PetscInt  dim = 3, n = 8, boxes = 0, boxOverlap = -1, jumpBoxes = 2;
  PetscReal E = 1.0, nu = 0.3, jump = 1.0;
  PetscBool floating = PETSC_FALSE, clampBoth = PETSC_FALSE;
  char      nullspace[16] = "near"; /* near: MatSetNearNullSpace(); coords: PCSetCoordinates(); none */
  PetscInt  k0, k1; /* node layers of the last coordinate (z in 3D, y in 2D) owned by this rank */
};

/* Nodes are numbered i + (n+1) (j + (n+1) k), k = 0 in 2D: a layer of the last coordinate is contiguous. */
static PetscInt Node(const Problem &p, PetscInt i, PetscInt j, PetscInt k) { return i + (p.n + 1) * (j + (p.n + 1) * k); }
static PetscInt LayerSize(const Problem &p) { return p.dim == 3 ? (p.n + 1) * (p.n + 1) : p.n + 1; }

/* Stiffness of the reference element [0,h]^dim for unit E (plane strain in 2D): 2^dim-point
   Gauss, exact for Q1. Dofs node by node: row dim * a + i for component i of corner a. */
static std::vector<PetscReal> ElementStiffness(PetscInt dim, PetscReal h, PetscReal nu)
{
  const PetscReal lam = nu / ((1 + nu) * (1 - 2 * nu)), mu = 1.0 / (2 * (1 + nu));
  const PetscReal g = 1.0 / std::sqrt(3.0), w = std::pow(h / 2, dim);
  const PetscInt  nen = 1 << dim, ne = dim * nen;
  std::vector<PetscReal> K(ne * ne, 0.0);
  for (PetscInt q = 0; q < nen; q++) {
    PetscReal xi[3], dN[8][3];
    for (PetscInt d = 0; d < dim; d++) xi[d] = (q >> d & 1) ? g : -g;
    for (PetscInt a = 0; a < nen; a++)
      for (PetscInt d = 0; d < dim; d++) {
        PetscReal v = ((a >> d & 1) ? 1.0 : -1.0) / nen;
        for (PetscInt e = 0; e < dim; e++)
          if (e != d) v *= 1 + ((a >> e & 1) ? 1.0 : -1.0) * xi[e];
        dN[a][d] = v * 2.0 / h;
      }
    for (PetscInt a = 0; a < nen; a++)
      for (PetscInt b = 0; b < nen; b++) {
        PetscReal dot = 0;
        for (PetscInt d = 0; d < dim; d++) dot += dN[a][d] * dN[b][d];
        for (PetscInt i = 0; i < dim; i++)
          for (PetscInt j = 0; j < dim; j++) K[(dim * a + i) * ne + dim * b + j] += w * (lam * dN[a][i] * dN[b][j] + mu * dN[a][j] * dN[b][i] + (i == j ? mu * dot : 0));
      }
  }
  return K;
}

static PetscErrorCode Assemble(const Problem &p, Mat A, Vec b)
{
  const PetscReal              h = 1.0 / p.n;
  const PetscInt               nen = 1 << p.dim, ne = p.dim * nen;
  const std::vector<PetscReal> K = ElementStiffness(p.dim, h, p.nu);
  std::vector<PetscReal>       Ke(ne * ne), fe(ne);
  std::vector<PetscInt>        rows(ne);

  PetscFunctionBegin;
  const PetscInt kEnd = std::min(p.k1, p.n); /* element layers whose lower nodes this rank owns */
  for (PetscInt k = p.k0; k < kEnd; k++)
    for (PetscInt j = 0; j < (p.dim == 3 ? p.n : 1); j++)
      for (PetscInt i = 0; i < p.n; i++) {
        const PetscInt e[3] = {i, p.dim == 3 ? j : k, p.dim == 3 ? k : 0}; /* the element's lowest corner */
        PetscInt       c    = 0;
        for (PetscInt d = 0; d < p.dim; d++) c += p.jumpBoxes * e[d] / p.n;
        const PetscReal E = p.E * (c % 2 ? p.jump : 1.0);
        for (PetscInt a = 0; a < nen; a++) {
          const PetscInt nd = Node(p, e[0] + (a & 1), e[1] + (a >> 1 & 1), e[2] + (a >> 2 & 1));
          for (PetscInt d = 0; d < p.dim; d++) rows[p.dim * a + d] = p.dim * nd + d, fe[p.dim * a + d] = d == p.dim - 1 ? -std::pow(h, p.dim) / nen : 0.0;
        }
        for (PetscInt r = 0; r < ne * ne; r++) Ke[r] = E * K[r];
        PetscCall(MatSetValues(A, ne, rows.data(), ne, rows.data(), Ke.data(), ADD_VALUES));
        PetscCall(VecSetValues(b, ne, rows.data(), fe.data(), ADD_VALUES));
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
  const PetscInt        kEnd = std::min(p.k1, p.n), layer = LayerSize(p);
  std::vector<PetscInt> nodes;
  for (PetscInt k = p.k0; p.k0 < kEnd && k <= kEnd; k++) /* a rank without elements holds no nodes */
    for (PetscInt q = 0; q < layer; q++) nodes.push_back(k * layer + q);
  ISLocalToGlobalMapping l2g;
  PetscCall(ISLocalToGlobalMappingCreate(PETSC_COMM_WORLD, p.dim, (PetscInt)nodes.size(), nodes.data(), PETSC_COPY_VALUES, &l2g));
  PetscCall(MatSetLocalToGlobalMapping(A, l2g, l2g));
  PetscCall(ISLocalToGlobalMappingDestroy(&l2g));
  PetscCall(MatISSetPreallocation(A, 81, nullptr, 0, nullptr));
  PetscFunctionReturn(0);
}

/* Dirichlet condition on x = 0, and x = 1 if clampBoth (symmetric elimination), or, floating, a consistent load. */
static PetscErrorCode Constrain(const Problem &p, Mat A, Vec b, Vec x, MatNullSpace rigid)
{
  PetscFunctionBegin;
  if (p.floating) {
    PetscCall(MatNullSpaceRemove(rigid, b));
    PetscFunctionReturn(0);
  }
  std::vector<PetscInt> rows;
  for (PetscInt q = p.k0 * LayerSize(p); q < p.k1 * LayerSize(p); q++)
    if (q % (p.n + 1) == 0 || (p.clampBoth && q % (p.n + 1) == p.n))
      for (PetscInt d = 0; d < p.dim; d++) rows.push_back(p.dim * q + d);
  PetscCall(VecSet(x, 0.0));
  PetscCall(MatZeroRowsColumns(A, (PetscInt)rows.size(), rows.data(), 1.0, x, b));
  PetscFunctionReturn(0);
}

/* Nodes of element box q (boxes numbered along x first), grown by `grow` element layers and clipped to the domain. */
static std::vector<PetscInt> BoxNodes(const Problem &p, PetscInt q, PetscInt grow)
{
  PetscInt              lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  std::vector<PetscInt> nodes;
  for (PetscInt d = 0, r = q; d < p.dim; d++, r /= p.boxes) {
    const PetscInt b = r % p.boxes;
    lo[d] = std::max<PetscInt>(0, b * p.n / p.boxes - grow), hi[d] = std::min(p.n, (b + 1) * p.n / p.boxes + grow);
  }
  for (PetscInt k = lo[2]; k <= hi[2]; k++)
    for (PetscInt j = lo[1]; j <= hi[1]; j++)
      for (PetscInt i = lo[0]; i <= hi[0]; i++) nodes.push_back(Node(p, i, j, k));
  return nodes;
}

/* Element boxes, dealt to ranks in order: the closure of each box's cells, and with -box_overlap
   the box grown by that many element layers as its overlapping subdomain. */
static PetscErrorCode BoxSubdomains(const Problem &p, std::vector<IS> &boxes, std::vector<IS> &grown)
{
  PetscMPIInt rank, size;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  const PetscInt nb = p.dim == 3 ? p.boxes * p.boxes * p.boxes : p.boxes * p.boxes;
  auto add = [&](PetscInt q, PetscInt grow, std::vector<IS> &list) {
    const std::vector<PetscInt> nodes = BoxNodes(p, q, grow);
    IS                          is;
    PetscCall(ISCreateBlock(PETSC_COMM_SELF, p.dim, (PetscInt)nodes.size(), nodes.data(), PETSC_COPY_VALUES, &is));
    list.push_back(is);
    return PetscErrorCode(0);
  };
  for (PetscInt q = nb * rank / size; q < nb * (rank + 1) / size; q++) {
    PetscCall(add(q, 0, boxes));
    if (p.boxOverlap >= 0) PetscCall(add(q, p.boxOverlap, grown));
  }
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
    Mat A0; /* its size, without assembling Phi */
    PetscCall(PCGDSWGetInterfaceCounts(pc, &faces, &edges, &vertices));
    PetscCall(PCGDSWGetCoarseOperator(pc, &A0));
    if (A0) PetscCall(MatGetSize(A0, nullptr, &coarse));
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "dofs %" PetscInt_FMT " ranks %d iterations %" PetscInt_FMT " reason %s coarse %" PetscInt_FMT " faces %" PetscInt_FMT " edges %" PetscInt_FMT " vertices %" PetscInt_FMT " setup %.3f s solve %.3f s\n",
                        M, size, its, KSPConvergedReasons[reason], coarse, faces, edges, vertices, setup, solve));
  PetscFunctionReturn(0);
}

/* The problem's options: the mesh, the material, the constraint and how the null space reaches the PC. */
static PetscErrorCode ProblemSetFromOptions(Problem &p)
{
  PetscFunctionBegin;
  PetscOptionsBegin(PETSC_COMM_WORLD, nullptr, "Elasticity test problem", nullptr);
  PetscCall(PetscOptionsInt("-dim", "2 or 3", nullptr, p.dim, &p.dim, nullptr));
  PetscCall(PetscOptionsInt("-n", "elements per direction", nullptr, p.n, &p.n, nullptr));
  PetscCall(PetscOptionsInt("-boxes", "element boxes per direction given to PCGDSW (0: none)", nullptr, p.boxes, &p.boxes, nullptr));
  PetscCall(PetscOptionsInt("-box_overlap", "element layers grown around each box for its overlapping subdomain (-1: none given)", nullptr, p.boxOverlap, &p.boxOverlap, nullptr));
  PetscCall(PetscOptionsReal("-E", "Young's modulus", nullptr, p.E, &p.E, nullptr));
  PetscCall(PetscOptionsReal("-nu", "Poisson ratio", nullptr, p.nu, &p.nu, nullptr));
  PetscCall(PetscOptionsReal("-jump", "Young's modulus factor on every other box", nullptr, p.jump, &p.jump, nullptr));
  PetscCall(PetscOptionsInt("-jump_boxes", "boxes per direction of the coefficient checkerboard", nullptr, p.jumpBoxes, &p.jumpBoxes, nullptr));
  PetscCall(PetscOptionsString("-nullspace", "near, coords or none", nullptr, p.nullspace, p.nullspace, sizeof(p.nullspace), nullptr));
  PetscCall(PetscOptionsBool("-floating", "no Dirichlet condition", nullptr, p.floating, &p.floating, nullptr));
  PetscCall(PetscOptionsBool("-clamp_both", "clamp x = 1 too", nullptr, p.clampBoth, &p.clampBoth, nullptr));
  PetscOptionsEnd();
  PetscCheck(p.dim == 2 || p.dim == 3, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-dim %" PetscInt_FMT ": use 2 or 3", p.dim);
  PetscCheck(p.n >= 1, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-n %" PetscInt_FMT ": need at least one element per direction", p.n);
  PetscCheck(p.boxes >= 0 && p.boxes <= p.n, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-boxes %" PetscInt_FMT ": must be between 0 and -n %" PetscInt_FMT, p.boxes, p.n);
  PetscCheck(!strcmp(p.nullspace, "near") || !strcmp(p.nullspace, "coords") || !strcmp(p.nullspace, "none"), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-nullspace %s: use near, coords or none", p.nullspace);
  PetscFunctionReturn(0);
}

struct System {
  Mat          A;
  Vec          b, x, coords; /* coords: of the owned nodes, dim per node */
  MatNullSpace rigid;        /* the rigid-body modes */
};

/* The assembled and constrained system, its rows split over the ranks in layers of the last coordinate. */
static PetscErrorCode SystemCreate(Problem &p, System &s)
{
  PetscMPIInt rank, size;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  const PetscInt layers = p.n + 1, layer = LayerSize(p), dim = p.dim, nblocks = dim == 3 ? 27 : 9;
  p.k0 = layers * rank / size, p.k1 = layers * (rank + 1) / size;
  const PetscInt nloc = (p.k1 - p.k0) * layer;
  PetscCall(MatCreate(PETSC_COMM_WORLD, &s.A));
  PetscCall(MatSetSizes(s.A, dim * nloc, dim * nloc, PETSC_DETERMINE, PETSC_DETERMINE));
  PetscCall(MatSetBlockSize(s.A, dim));
  PetscCall(MatSetType(s.A, MATAIJ));
  PetscCall(MatSetFromOptions(s.A));
  PetscCall(SubassembledLayout(p, s.A));
  PetscCall(MatSeqAIJSetPreallocation(s.A, dim * nblocks, nullptr));
  PetscCall(MatMPIAIJSetPreallocation(s.A, dim * nblocks, nullptr, dim * nblocks, nullptr));
  PetscCall(MatSeqBAIJSetPreallocation(s.A, dim, nblocks, nullptr));
  PetscCall(MatMPIBAIJSetPreallocation(s.A, dim, nblocks, nullptr, nblocks, nullptr));
  PetscCall(MatSeqSBAIJSetPreallocation(s.A, dim, nblocks, nullptr));
  PetscCall(MatMPISBAIJSetPreallocation(s.A, dim, nblocks, nullptr, nblocks, nullptr));
  PetscBool sbaij;
  PetscCall(PetscObjectTypeCompareAny((PetscObject)s.A, &sbaij, MATSEQSBAIJ, MATMPISBAIJ, ""));
  if (sbaij) PetscCall(MatSetOption(s.A, MAT_IGNORE_LOWER_TRIANGULAR, PETSC_TRUE));
  PetscCall(MatCreateVecs(s.A, &s.x, &s.b));
  PetscCall(Assemble(p, s.A, s.b));

  PetscCall(VecCreate(PETSC_COMM_WORLD, &s.coords));
  PetscCall(VecSetSizes(s.coords, dim * nloc, PETSC_DECIDE));
  PetscCall(VecSetBlockSize(s.coords, dim));
  PetscCall(VecSetFromOptions(s.coords));
  PetscScalar *c;
  PetscCall(VecGetArray(s.coords, &c));
  for (PetscInt q = 0; q < nloc; q++)
    for (PetscInt d = 0, g = p.k0 * layer + q; d < dim; d++, g /= p.n + 1) c[dim * q + d] = (g % (p.n + 1)) / (PetscReal)p.n;
  PetscCall(VecRestoreArray(s.coords, &c));
  PetscCall(MatNullSpaceCreateRigidBody(s.coords, &s.rigid));
  /* PCGDSW builds its coarse space from the operator's near-null space, or else from the coordinates (SolverCreate()) */
  if (!strcmp(p.nullspace, "near")) PetscCall(MatSetNearNullSpace(s.A, s.rigid));
  if (p.floating) PetscCall(MatSetNullSpace(s.A, s.rigid));
  PetscCall(Constrain(p, s.A, s.b, s.x, s.rigid));
  PetscFunctionReturn(0);
}

/* CG preconditioned by PCGDSW, which the options may change. What the application knows and the
   PC cannot find in the matrix: the node coordinates, and the mesh's subdomains (element boxes). */
static PetscErrorCode SolverCreate(const Problem &p, const System &s, KSP *ksp, std::vector<IS> &boxes, std::vector<IS> &grown)
{
  PC pc;

  PetscFunctionBegin;
  PetscCall(KSPCreate(PETSC_COMM_WORLD, ksp));
  PetscCall(KSPSetOperators(*ksp, s.A, s.A));
  PetscCall(KSPSetType(*ksp, KSPCG));
  PetscCall(KSPSetTolerances(*ksp, 1e-8, PETSC_DEFAULT, PETSC_DEFAULT, 1000));
  PetscCall(KSPGetPC(*ksp, &pc));
  PetscCall(PCSetType(pc, PCGDSW));
  PetscCall(KSPSetFromOptions(*ksp));
  if (!strcmp(p.nullspace, "coords")) {
    PetscInt           n;
    const PetscScalar *c;
    PetscCall(VecGetLocalSize(s.coords, &n));
    std::vector<PetscReal> xyz(n);
    PetscCall(VecGetArrayRead(s.coords, &c));
    for (PetscInt q = 0; q < n; q++) xyz[q] = PetscRealPart(c[q]);
    PetscCall(VecRestoreArrayRead(s.coords, &c));
    PetscCall(PCSetCoordinates(pc, p.dim, n / p.dim, xyz.data()));
  }
  if (p.boxes) {
    PetscCall(BoxSubdomains(p, boxes, grown));
    PetscCall(PCGDSWSetSubdomains(pc, (PetscInt)boxes.size(), boxes.data(), p.boxOverlap >= 0 ? grown.data() : nullptr));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode SystemDestroy(System &s)
{
  PetscFunctionBegin;
  PetscCall(MatNullSpaceDestroy(&s.rigid));
  PetscCall(VecDestroy(&s.coords));
  PetscCall(VecDestroy(&s.x));
  PetscCall(VecDestroy(&s.b));
  PetscCall(MatDestroy(&s.A));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  Problem         p;
  System          s;
  KSP             ksp;
  std::vector<IS> boxes, grown;
  PetscLogDouble  t0, t1, t2;

  PetscCall(PetscInitialize(&argc, &argv, nullptr, help));
  PetscCall(PCGDSWRegister()); /* or, without linking the library, -dll_append libpetscgdsw.so */
  PetscCall(ProblemSetFromOptions(p));
  PetscCall(SystemCreate(p, s));
  PetscCall(SolverCreate(p, s, &ksp, boxes, grown));
  PetscCall(PetscTime(&t0));
  PetscCall(KSPSetUp(ksp));
  PetscCall(PetscTime(&t1));
  PetscCall(KSPSolve(ksp, s.b, s.x));
  PetscCall(PetscTime(&t2));
  PetscCall(Report(ksp, s.A, t1 - t0, t2 - t1));

  for (IS &is : boxes) PetscCall(ISDestroy(&is));
  for (IS &is : grown) PetscCall(ISDestroy(&is));
  PetscCall(KSPDestroy(&ksp));
  PetscCall(SystemDestroy(s));
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
