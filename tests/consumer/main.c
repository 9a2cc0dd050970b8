/* SPDX-License-Identifier: BSD-2-Clause */
/* An outside C program built against the installed library with pkg-config: links it, calls
   PCGDSWRegister() and solves the 2D 5-point Laplacian with -pc_type gdsw. */
#include <petscgdsw.h>
#include <petscdmda.h>

int main(int argc, char **argv)
{
  DM       da;
  Mat      A;
  Vec      x, b;
  KSP      ksp;
  PetscInt its, i, j, xs, ys, xm, ym, M = 64;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(PCGDSWRegister());
  PetscCall(DMDACreate2d(PETSC_COMM_WORLD, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DMDA_STENCIL_STAR, M, M, PETSC_DECIDE, PETSC_DECIDE, 1, 1, NULL, NULL, &da));
  PetscCall(DMSetUp(da));
  PetscCall(DMCreateMatrix(da, &A));
  PetscCall(DMDAGetCorners(da, &xs, &ys, NULL, &xm, &ym, NULL));
  for (j = ys; j < ys + ym; j++)
    for (i = xs; i < xs + xm; i++) {
      MatStencil  row = {0, j, i, 0}, col[5];
      PetscScalar v[5];
      PetscInt    n = 0;
      if (i == 0 || j == 0 || i == M - 1 || j == M - 1) {
        v[0] = 1.0;
        PetscCall(MatSetValuesStencil(A, 1, &row, 1, &row, v, INSERT_VALUES));
        continue;
      }
      col[n].i = i, col[n].j = j, v[n++] = 4.0;
      col[n].i = i - 1, col[n].j = j, v[n++] = (i - 1 == 0) ? 0.0 : -1.0;
      col[n].i = i + 1, col[n].j = j, v[n++] = (i + 1 == M - 1) ? 0.0 : -1.0;
      col[n].i = i, col[n].j = j - 1, v[n++] = (j - 1 == 0) ? 0.0 : -1.0;
      col[n].i = i, col[n].j = j + 1, v[n++] = (j + 1 == M - 1) ? 0.0 : -1.0;
      PetscCall(MatSetValuesStencil(A, 1, &row, n, col, v, INSERT_VALUES));
    }
  PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatCreateVecs(A, &x, &b));
  PetscCall(VecSet(b, 1.0));
  PetscCall(KSPCreate(PETSC_COMM_WORLD, &ksp));
  PetscCall(KSPSetOperators(ksp, A, A));
  PetscCall(KSPSetType(ksp, KSPCG));
  PetscCall(KSPSetTolerances(ksp, 1e-8, PETSC_DEFAULT, PETSC_DEFAULT, 500));
  PetscCall(KSPSetFromOptions(ksp));
  PetscCall(KSPSolve(ksp, b, x));
  PetscCall(KSPGetIterationNumber(ksp, &its));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "iterations %" PetscInt_FMT "\n", its));
  PetscCall(KSPDestroy(&ksp));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  PetscCall(MatDestroy(&A));
  PetscCall(DMDestroy(&da));
  PetscCall(PetscFinalize());
  return 0;
}
