// SPDX-License-Identifier: BSD-2-Clause
#include "harmonic.h"
#include "discretization/ale_map.h"

namespace fsi {

/* R(d)(v) = int grad d : grad v, component by component (the residual of a linear problem is
   its operator applied: Newton converges in one step). */
PetscErrorCode GeometryResidual(const GeometryForms &gb, const PetscScalar *x, PetscScalar *f)
{
  PetscFunctionBegin;
  for (PetscInt k = 0; k < gb.cells.Size(); k++) {
    const CellGeometry &g = gb.cells.geom[k];
    PetscReal           de[30], re[30] = {0};
    Gather(gb.cells, k, x, de);
    for (PetscInt q = 0; q < gb.rule.nq; q++) {
      PetscReal       dN[10][3], G[3][3] = {{0}};
      const PetscReal w = ReferenceGradients(g, gb.rule, q, dN);
      for (int a = 0; a < 10; a++)
        for (int i = 0; i < 3; i++)
          for (int j = 0; j < 3; j++) G[i][j] += de[3 * a + i] * dN[a][j];
      for (int a = 0; a < 10; a++)
        for (int i = 0; i < 3; i++) re[3 * a + i] += w * (G[i][0] * dN[a][0] + G[i][1] * dN[a][1] + G[i][2] * dN[a][2]);
    }
    Scatter(gb.cells, k, re, f);
  }
  PetscFunctionReturn(0);
}

/* The stiffness acts on each component alone: one 10 x 10 block per component, so the
   matrix stores no cross-component zeros (two thirds of a 30 x 30 cell block). */
static void ComponentIndices(const PetscInt *idx, int i, PetscInt out[10])
{
  for (int a = 0; a < 10; a++) out[a] = idx[3 * a + i];
}

PetscErrorCode GeometryJacobian(const GeometryForms &gb, const PetscScalar *, Mat P)
{
  PetscFunctionBegin;
  for (PetscInt k = 0; k < gb.cells.Size(); k++) {
    const CellGeometry &g = gb.cells.geom[k];
    PetscReal           K[100] = {0};
    for (PetscInt q = 0; q < gb.rule.nq; q++) {
      PetscReal       dN[10][3];
      const PetscReal w = ReferenceGradients(g, gb.rule, q, dN);
      for (int a = 0; a < 10; a++)
        for (int b = 0; b < 10; b++) K[10 * a + b] += w * (dN[a][0] * dN[b][0] + dN[a][1] * dN[b][1] + dN[a][2] * dN[b][2]);
    }
    for (int i = 0; i < 3; i++) {
      PetscInt rows[10], cols[10];
      ComponentIndices(&gb.cells.rows[30 * k], i, rows);
      ComponentIndices(&gb.cells.global[30 * k], i, cols);
      PetscCall(AddElementMatrix(P, 10, rows, 10, cols, K));
    }
  }
  PetscFunctionReturn(0);
}

void GeometryCouplings(const GeometryForms &gb, Sparsity &s)
{
  for (PetscInt k = 0; k < gb.cells.Size(); k++)
    for (int i = 0; i < 3; i++) {
      PetscInt rows[10], cols[10];
      ComponentIndices(&gb.cells.rows[30 * k], i, rows);
      ComponentIndices(&gb.cells.global[30 * k], i, cols);
      s.Couple(10, rows, 10, cols);
    }
}

} // namespace fsi
