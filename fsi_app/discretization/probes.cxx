// SPDX-License-Identifier: BSD-2-Clause
#include "probes.h"
#include "discretization/conditions.h"

namespace fsi {

/* Barycentric coordinates of X in the straight reference cell g. */
static void Barycentric(const CellGeometry &g, const PetscReal X[3], PetscReal l[4])
{
  l[0] = 1;
  for (int k = 1; k < 4; k++) {
    l[k] = 0;
    for (int d = 0; d < 3; d++) l[k] += g.gradLambda[k][d] * (X[d] - g.x[0][d]);
    l[0] -= l[k];
  }
}

PetscErrorCode ProbesCreate(MPI_Comm comm, const FieldCells &cells, const std::vector<PetscReal> &X, const char *option, Probes &probes)
{
  PetscMPIInt rank;
  const size_t n = X.size() / 3;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  probes    = Probes();
  probes.X  = X, probes.nc = cells.nc;
  probes.cell.assign(n, -1), probes.lambda.assign(4 * n, 0);
  for (size_t i = 0; i < n; i++) {
    PetscInt found = -1;
    for (PetscInt k = 0; k < cells.Size() && found < 0; k++) {
      PetscReal l[4];
      Barycentric(cells.geom[k], &X[3 * i], l);
      if (l[0] >= -1e-10 && l[1] >= -1e-10 && l[2] >= -1e-10 && l[3] >= -1e-10) {
        found = k;
        for (int c = 0; c < 4; c++) probes.lambda[4 * i + c] = l[c];
      }
    }
    PetscInt mine = found >= 0 ? rank : -1, owner;
    PetscCallMPI(MPIU_Allreduce(&mine, &owner, 1, MPIU_INT, MPI_MAX, comm)); /* one rank evaluates a point on a shared face */
    PetscCheck(owner >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "%s: the point (%g, %g, %g) is not in the field's region", option, (double)X[3 * i], (double)X[3 * i + 1], (double)X[3 * i + 2]);
    if (owner == rank) probes.cell[i] = found;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ProbesRecord(MPI_Comm comm, const FieldCells &cells, const PetscScalar *x, PetscReal t, Probes &probes)
{
  const size_t           n = probes.cell.size(), nc = probes.nc;
  std::vector<PetscReal> v(n * nc, 0.0);

  PetscFunctionBegin;
  for (size_t i = 0; i < n; i++)
    if (probes.cell[i] >= 0) {
      PetscReal        ve[30], N[10];
      const PetscReal *l = &probes.lambda[4 * i];
      Gather(cells, probes.cell[i], x, ve);
      P2Values(l, N);
      for (PetscInt a = 0; a < cells.nodes; a++)
        for (size_t c = 0; c < nc; c++) v[nc * i + c] += (cells.nodes == 10 ? N[a] : l[a]) * ve[nc * a + c];
    }
  PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, v.data(), (PetscMPIInt)v.size(), MPIU_REAL, MPIU_SUM, comm));
  probes.t.push_back(t);
  probes.values.insert(probes.values.end(), v.begin(), v.end());
  PetscFunctionReturn(0);
}

PetscErrorCode ProbesRecordGlobal(DM dm, const FieldCells &cells, Vec x, PetscReal t, Probes &probes)
{
  Vec                xl;
  const PetscScalar *xa;

  PetscFunctionBegin;
  PetscCall(DMGetLocalVector(dm, &xl));
  PetscCall(DMGlobalToLocal(dm, x, INSERT_VALUES, xl));
  PetscCall(InsertEssentialValues(dm, t, xl));
  PetscCall(VecGetArrayRead(xl, &xa));
  PetscCall(ProbesRecord(PetscObjectComm((PetscObject)dm), cells, xa, t, probes));
  PetscCall(VecRestoreArrayRead(xl, &xa));
  PetscCall(DMRestoreLocalVector(dm, &xl));
  PetscFunctionReturn(0);
}

std::vector<PetscReal> ProbesArrival(const Probes &probes, PetscReal level)
{
  const size_t           n = probes.cell.size();
  std::vector<PetscReal> arrival(n, -1);
  for (size_t i = 0; i < n; i++) {
    PetscReal tb = 0, pb = 0; /* the state before the first record: at rest */
    for (size_t k = 0; k < probes.t.size() && arrival[i] < 0; k++) {
      const PetscReal pk = probes.values[probes.nc * (n * k + i)];
      if (pb < level && pk >= level) arrival[i] = tb + (level - pb) / (pk - pb) * (probes.t[k] - tb);
      tb = probes.t[k], pb = pk;
    }
  }
  return arrival;
}

} // namespace fsi
