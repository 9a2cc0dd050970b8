// SPDX-License-Identifier: BSD-2-Clause
#include "errors.h"
#include "discretization/ale_map.h"
#include "discretization/conditions.h"

namespace fsi {

void ZeroSolution(const PetscReal[3], PetscReal, const void *, PetscReal u[3], PetscReal G[9])
{
  for (int i = 0; i < 3; i++) u[i] = 0;
  for (int i = 0; i < 9; i++) G[i] = 0;
}

PetscErrorCode ComputeErrors(DM dm, const FieldCells &cells, Vec X, PetscReal t, ExactSolution exact, const void *ctx, Errors &e, const FieldCells *mesh)
{
  P2Rule         rule;
  Vec            Xl;
  PetscReal      sum[4] = {0, 0, 0, 0};
  const PetscInt nc = cells.nc, p2 = cells.nodes == 10;

  PetscFunctionBegin;
  PetscCall(CreateP2Rule(8, rule)); /* smooth exact solutions: beyond the P2 error's order */
  PetscCall(DMGetLocalVector(dm, &Xl));
  PetscCall(DMGlobalToLocal(dm, X, INSERT_VALUES, Xl));
  PetscCall(InsertEssentialValues(dm, t, Xl));
  const PetscScalar *xa;
  PetscCall(VecGetArrayRead(Xl, &xa));
  for (PetscInt k = 0; k < cells.Size(); k++) {
    const CellGeometry &g = cells.geom[k];
    PetscReal           ve[30], de[30];
    Gather(cells, k, xa, ve);
    if (mesh) Gather(*mesh, k, xa, de);
    for (PetscInt q = 0; q < rule.nq; q++) {
      const PetscReal *l = &rule.lambda[4 * q], *N = &rule.N[10 * q];
      MovedPoint       m;
      PetscReal        u[3], G[9], uh[3] = {0, 0, 0}, Gh[9] = {0};
      PetscCheck(MovePoint(g, mesh ? de : nullptr, l, N, m) > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "the moved mesh is inverted in cell %" PetscInt_FMT, cells.cell[k]);
      const PetscReal w = rule.w[q] * g.detE * m.J;
      exact(m.x, t, ctx, u, G);
      for (PetscInt a = 0; a < cells.nodes; a++) {
        const PetscReal  Na = p2 ? N[a] : l[a];
        const PetscReal *dN = p2 ? m.dN[a] : m.dL[a];
        for (PetscInt i = 0; i < nc; i++) {
          uh[i] += Na * ve[nc * a + i];
          for (int j = 0; j < 3; j++) Gh[i * 3 + j] += dN[j] * ve[nc * a + i];
        }
      }
      for (PetscInt i = 0; i < nc; i++) {
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

PetscErrorCode ReportErrors(const char *what, const Errors &e, RunReport &report)
{
  const std::string w = what[0] ? std::string(what) + "_" : "", space = what[0] ? " " : "";

  PetscFunctionBegin;
  for (const auto &n : {std::make_pair("L2", std::make_pair(e.l2, e.l2Exact)), std::make_pair("H1", std::make_pair(e.h1, e.h1Exact))}) {
    const PetscReal   err = n.second.first, exact = n.second.second;
    const std::string key = w + (n.first[0] == 'L' ? "l2" : "h1");
    if (exact > 0) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s%s%s error %.6e relative %.6e\n", what, space.c_str(), n.first, (double)err, (double)(err / exact)));
    else PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s%s%s error %.6e (the exact field is zero)\n", what, space.c_str(), n.first, (double)err));
    report.results.push_back({key + "_error", err});
    if (exact > 0) report.results.push_back({key + "_relative", err / exact});
  }
  PetscFunctionReturn(0);
}

} // namespace fsi
