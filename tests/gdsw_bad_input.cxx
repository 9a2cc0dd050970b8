// SPDX-License-Identifier: BSD-2-Clause
static const char help[] = "Feeds PCGDSW one kind of bad input (-case <name>) so that tests can check its error message.\n"
                           "Cases: nonsquare, unassembled, coordinates, nullspace_length, singular, zero_row_2d, floating, partial_node, uncovered, index_negative, index_large,\n"
                           "coordinates_nan, coordinates_2d, nullspace_nan, nullspace_zero, matrix_nan, matrix_inf, empty_subdomain.\n";

/* A block-diagonal operator kron(L, I_bs), L the 1D Laplacian with n nodes (Dirichlet rows at
   both ends unless -case floating), is enough to reach each check. */
#include <petscgdsw.h>
#include <limits>
#include <string>
#include <vector>

static PetscErrorCode Laplacian(PetscInt n, PetscInt bs, PetscBool dirichlet, Mat *A)
{
  PetscInt rstart, rend;

  PetscFunctionBegin;
  PetscCall(MatCreateAIJ(PETSC_COMM_WORLD, PETSC_DECIDE, PETSC_DECIDE, n * bs, n * bs, 3, nullptr, 3, nullptr, A));
  PetscCall(MatSetBlockSize(*A, bs));
  PetscCall(MatGetOwnershipRange(*A, &rstart, &rend));
  auto fixed = [&](PetscInt i) { return dirichlet && (i == 0 || i == n - 1); };
  for (PetscInt r = rstart; r < rend; r++) {
    const PetscInt i = r / bs;
    PetscInt       deg = 0;
    for (PetscInt j : {i - 1, i + 1}) {
      if (j < 0 || j >= n) continue;
      deg++;
      if (!fixed(i) && !fixed(j)) PetscCall(MatSetValue(*A, r, r + (j - i) * bs, -1.0, INSERT_VALUES));
    }
    PetscCall(MatSetValue(*A, r, r, fixed(i) ? 1.0 : (dirichlet ? 2.0 : (PetscReal)deg), INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*A, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

/* PETSc's ksp tutorial ex2: the 5-point Laplacian on an m x m grid, Dirichlet boundary eliminated. */
static PetscErrorCode Laplacian2D(PetscInt m, Mat *A)
{
  PetscInt rstart, rend;

  PetscFunctionBegin;
  PetscCall(MatCreateAIJ(PETSC_COMM_WORLD, PETSC_DECIDE, PETSC_DECIDE, m * m, m * m, 5, nullptr, 5, nullptr, A));
  PetscCall(MatGetOwnershipRange(*A, &rstart, &rend));
  for (PetscInt r = rstart; r < rend; r++) {
    const PetscInt i = r / m, j = r % m;
    if (i > 0) PetscCall(MatSetValue(*A, r, r - m, -1.0, INSERT_VALUES));
    if (i < m - 1) PetscCall(MatSetValue(*A, r, r + m, -1.0, INSERT_VALUES));
    if (j > 0) PetscCall(MatSetValue(*A, r, r - 1, -1.0, INSERT_VALUES));
    if (j < m - 1) PetscCall(MatSetValue(*A, r, r + 1, -1.0, INSERT_VALUES));
    PetscCall(MatSetValue(*A, r, r, 4.0, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*A, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  char     name[64] = "";
  PetscInt n = 40;
  Mat      A = nullptr;
  KSP      ksp;
  PC       pc;
  Vec      x, b;

  PetscCall(PetscInitialize(&argc, &argv, nullptr, help));
  PetscCall(PCGDSWRegister());
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-case", name, sizeof(name), nullptr));
  const std::string c = name;
  PetscCall(KSPCreate(PETSC_COMM_WORLD, &ksp));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCGDSW));
  PetscCall(PCGDSWSetSubdomainsPerRank(pc, 4));

  if (c == "nonsquare") {
    PetscCall(MatCreateAIJ(PETSC_COMM_WORLD, PETSC_DECIDE, PETSC_DECIDE, 12, 10, 1, nullptr, 1, nullptr, &A));
    PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
    PetscCall(PCSetOperators(pc, A, A));
    PetscCall(PCSetUp(pc));
  } else if (c == "unassembled") {
    PetscCall(MatCreateAIJ(PETSC_COMM_WORLD, PETSC_DECIDE, PETSC_DECIDE, n, n, 3, nullptr, 3, nullptr, &A));
    PetscCall(PCSetOperators(pc, A, A));
    PetscCall(PCSetUp(pc));
  } else if (c == "coordinates") { /* 3 coordinates per node, but a number of nodes that does not divide the rows */
    PetscInt m;
    PetscCall(Laplacian(n, 1, PETSC_TRUE, &A));
    PetscCall(MatGetLocalSize(A, &m, nullptr));
    std::vector<PetscReal> xyz(3 * (m + 1), 0.0);
    PetscCall(PCSetOperators(pc, A, A));
    PetscCall(PCSetCoordinates(pc, 3, m + 1, xyz.data()));
    PetscCall(PCSetUp(pc));
  } else if (c == "nullspace_length") {
    Vec          v;
    MatNullSpace nsp;
    PetscCall(Laplacian(n, 1, PETSC_TRUE, &A));
    PetscCall(VecCreateMPI(PETSC_COMM_WORLD, PETSC_DECIDE, n + 3, &v));
    PetscCall(VecSet(v, 1.0));
    PetscCall(MatNullSpaceCreate(PETSC_COMM_WORLD, PETSC_FALSE, 1, &v, &nsp));
    PetscCall(MatSetNearNullSpace(A, nsp));
    PetscCall(PCSetOperators(pc, A, A));
    PetscCall(PCSetUp(pc));
  } else if (c == "coordinates_nan" || c == "coordinates_2d") { /* a NaN coordinate; 2-D coordinates on 3 dofs per node */
    PetscInt m;
    PetscCall(Laplacian(n, 3, PETSC_TRUE, &A));
    PetscCall(MatGetLocalSize(A, &m, nullptr));
    const PetscInt dim = c == "coordinates_2d" ? 2 : 3;
    std::vector<PetscReal> xyz(dim * (m / 3), 0.0);
    if (c == "coordinates_nan") xyz[1] = std::numeric_limits<PetscReal>::quiet_NaN();
    PetscCall(PCSetOperators(pc, A, A));
    PetscCall(PCSetCoordinates(pc, dim, m / 3, xyz.data()));
    PetscCall(PCSetUp(pc));
  } else if (c == "nullspace_zero") { /* the constant, then a zero vector */
    Vec          v[2];
    MatNullSpace nsp;
    PetscCall(Laplacian(n, 1, PETSC_TRUE, &A));
    PetscCall(MatCreateVecs(A, &v[0], &v[1]));
    PetscCall(VecSet(v[0], 1.0 / PetscSqrtReal((PetscReal)n)));
    PetscCall(VecSet(v[1], 0.0));
    PetscCall(MatNullSpaceCreate(PETSC_COMM_WORLD, PETSC_FALSE, 2, v, &nsp));
    PetscCall(MatSetNearNullSpace(A, nsp));
    PetscCall(MatNullSpaceDestroy(&nsp));
    PetscCall(VecDestroy(&v[0]));
    PetscCall(VecDestroy(&v[1]));
    PetscCall(PCSetOperators(pc, A, A));
    PetscCall(PCSetUp(pc));
  } else if (c == "nullspace_nan") {
    Vec          v;
    MatNullSpace nsp;
    PetscInt     rstart;
    PetscCall(Laplacian(n, 1, PETSC_TRUE, &A));
    PetscCall(MatCreateVecs(A, &v, nullptr));
    PetscCall(VecSet(v, 1.0 / PetscSqrtReal((PetscReal)n)));
    PetscCall(VecGetOwnershipRange(v, &rstart, nullptr));
    PetscCall(VecSetValue(v, rstart, std::numeric_limits<PetscReal>::quiet_NaN(), INSERT_VALUES));
    PetscCall(VecAssemblyBegin(v));
    PetscCall(VecAssemblyEnd(v));
    PetscCall(MatNullSpaceCreate(PETSC_COMM_WORLD, PETSC_FALSE, 1, &v, &nsp));
    PetscCall(MatSetNearNullSpace(A, nsp));
    PetscCall(MatNullSpaceDestroy(&nsp));
    PetscCall(VecDestroy(&v));
    PetscCall(PCSetOperators(pc, A, A));
    PetscCall(PCSetUp(pc));
  } else if (c == "matrix_nan" || c == "matrix_inf") { /* the diagonal of row 25 (rank 1 of 2) not finite */
    PetscInt    row = 25;
    PetscScalar v   = c == "matrix_nan" ? std::numeric_limits<PetscReal>::quiet_NaN() : std::numeric_limits<PetscReal>::infinity();
    PetscCall(Laplacian(n, 1, PETSC_TRUE, &A));
    PetscCall(MatSetValue(A, row, row, v, INSERT_VALUES));
    PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
    PetscCall(PCSetOperators(pc, A, A));
    PetscCall(PCSetUp(pc));
  } else if (c == "singular") { /* one dof with an all-zero row and column */
    PetscInt mid = n / 2;
    PetscCall(Laplacian(n, 1, PETSC_TRUE, &A));
    PetscCall(MatZeroRowsColumns(A, 1, &mid, 0.0, nullptr, nullptr));
    PetscCall(PCSetOperators(pc, A, A));
    PetscCall(PCSetUp(pc));
  } else if (c == "zero_row_2d") { /* row and column 100 of a 20 x 20 grid zeroed, diagonal too; GMRES */
    PetscInt zero = 100;
    PetscCall(Laplacian2D(20, &A));
    PetscCall(MatZeroRowsColumns(A, 1, &zero, 0.0, nullptr, nullptr));
    PetscCall(KSPSetOperators(ksp, A, A));
    PetscCall(KSPSetType(ksp, KSPGMRES));
    PetscCall(KSPSetFromOptions(ksp));
    PetscCall(MatCreateVecs(A, &x, &b));
    PetscCall(VecSet(b, 1.0));
    PetscCall(KSPSolve(ksp, b, x));
    PetscCall(VecDestroy(&x));
    PetscCall(VecDestroy(&b));
  } else if (c == "floating") {
    PetscCall(Laplacian(n, 1, PETSC_FALSE, &A));
    PetscCall(PCSetOperators(pc, A, A));
    PetscCall(PCSetUp(pc));
  } else if (c == "partial_node" || c == "uncovered" || c == "empty_subdomain" || c == "index_negative" || c == "index_large") {
    PetscInt rstart, rend;
    PetscCall(Laplacian(n, 3, PETSC_TRUE, &A));
    PetscCall(MatGetOwnershipRange(A, &rstart, &rend));
    std::vector<PetscInt> all;
    for (PetscInt r = rstart; r < rend; r++) all.push_back(r);
    if (c == "partial_node") all.pop_back();                     /* drops one dof of the last node */
    if (c == "uncovered") all.resize(all.size() - 3);            /* drops the last node */
    if (rend < n * 3) /* the closure of this rank's cells reaches the next rank's first node */
      for (PetscInt d = 0; d < 3; d++) all.push_back(rend + d);
    if (c == "index_negative") all.push_back(-1);
    if (c == "index_large") all.push_back(3 * n);
    IS is[2];
    PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)all.size(), all.data(), PETSC_COPY_VALUES, &is[0]));
    PetscCall(ISCreateGeneral(PETSC_COMM_SELF, 0, nullptr, PETSC_COPY_VALUES, &is[1]));
    PetscCall(KSPSetOperators(ksp, A, A));
    PetscCall(PCGDSWSetSubdomains(pc, 2, is, nullptr));
    PetscCall(ISDestroy(&is[0]));
    PetscCall(ISDestroy(&is[1]));
    PetscCall(KSPSetFromOptions(ksp));
    PetscCall(MatCreateVecs(A, &x, &b));
    PetscCall(VecSet(b, 1.0));
    PetscCall(KSPSolve(ksp, b, x));
    PetscInt its;
    PetscCall(KSPGetIterationNumber(ksp, &its));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "iterations %" PetscInt_FMT "\n", its));
    PetscCall(VecDestroy(&x));
    PetscCall(VecDestroy(&b));
  } else SETERRQ(PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-case %s is not one of the cases listed by -help", name);

  PetscCall(MatDestroy(&A));
  PetscCall(KSPDestroy(&ksp));
  PetscCall(PetscFinalize());
  return 0;
}

/*TEST

   # PETSc test-harness format (config/testparse.py); run with scripts/petsc-harness.
   # The one case that must converge: an empty subdomain given by the application is dropped.
   test:
      suffix: empty_subdomain
      nsize: 2
      args: -case empty_subdomain -ksp_type cg

TEST*/
