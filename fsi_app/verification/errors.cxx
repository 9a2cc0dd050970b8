#include "errors.h"
#include "discretization/nodes.h"

namespace fsi {

PetscErrorCode ComputeErrors(DM dm, const FieldCells &cells, Vec X, PetscReal t, ExactSolution exact, const void *ctx, Errors &e)
{
  P2Rule    rule;
  Vec       Xl;
  PetscReal sum[4] = {0, 0, 0, 0};

  PetscFunctionBegin;
  PetscCall(CreateP2Rule(8, rule)); /* smooth exact solutions: beyond the P2 error's order */
  PetscCall(DMGetLocalVector(dm, &Xl));
  PetscCall(DMGlobalToLocal(dm, X, INSERT_VALUES, Xl));
  PetscCall(InsertEssentialValues(dm, t, Xl));
  const PetscScalar *xa;
  PetscCall(VecGetArrayRead(Xl, &xa));
  for (PetscInt k = 0; k < cells.Size(); k++) {
    const CellGeometry &g = cells.geom[k];
    PetscReal           de[30];
    Gather(cells, k, xa, de);
    for (PetscInt q = 0; q < rule.nq; q++) {
      const PetscReal *l = &rule.lambda[4 * q], *N = &rule.N[10 * q], w = rule.w[q] * g.detE;
      PetscReal        dN[10][3], xq[3], u[3], G[9], uh[3] = {0, 0, 0}, Gh[9] = {0};
      P2Gradients(g, l, dN);
      for (int d = 0; d < 3; d++) xq[d] = l[0] * g.x[0][d] + l[1] * g.x[1][d] + l[2] * g.x[2][d] + l[3] * g.x[3][d];
      exact(xq, ctx, u, G);
      for (int a = 0; a < 10; a++)
        for (int i = 0; i < 3; i++) {
          uh[i] += N[a] * de[3 * a + i];
          for (int j = 0; j < 3; j++) Gh[i * 3 + j] += dN[a][j] * de[3 * a + i];
        }
      for (int i = 0; i < 3; i++) {
        sum[0] += w * PetscSqr(uh[i] - u[i]), sum[2] += w * u[i] * u[i];
        for (int j = 0; j < 3; j++) sum[1] += w * PetscSqr(Gh[i * 3 + j] - G[i * 3 + j]), sum[3] += w * G[i * 3 + j] * G[i * 3 + j];
      }
    }
  }
  PetscCall(VecRestoreArrayRead(Xl, &xa));
  PetscCall(DMRestoreLocalVector(dm, &Xl));
  PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, sum, 4, MPIU_REAL, MPIU_SUM, PetscObjectComm((PetscObject)dm)));
  e = {PetscSqrtReal(sum[0]), PetscSqrtReal(sum[1]), PetscSqrtReal(sum[2]), PetscSqrtReal(sum[3])};
  PetscFunctionReturn(0);
}

} // namespace fsi
