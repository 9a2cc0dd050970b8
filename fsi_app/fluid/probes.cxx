#include "probes.h"

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

PetscErrorCode PressureProbesCreate(MPI_Comm comm, const FieldCells &pressure, const std::vector<PetscReal> &X, const char *option, PressureProbes &probes)
{
  PetscMPIInt rank;
  const size_t n = X.size() / 3;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  probes    = PressureProbes();
  probes.X  = X;
  probes.cell.assign(n, -1), probes.owner.assign(n, -1), probes.lambda.assign(4 * n, 0);
  for (size_t i = 0; i < n; i++) {
    PetscInt found = -1;
    for (PetscInt k = 0; k < pressure.Size() && found < 0; k++) {
      PetscReal l[4];
      Barycentric(pressure.geom[k], &X[3 * i], l);
      if (l[0] >= -1e-10 && l[1] >= -1e-10 && l[2] >= -1e-10 && l[3] >= -1e-10) {
        found = k;
        for (int c = 0; c < 4; c++) probes.lambda[4 * i + c] = l[c];
      }
    }
    PetscInt mine = found >= 0 ? rank : -1, owner;
    PetscCallMPI(MPIU_Allreduce(&mine, &owner, 1, MPIU_INT, MPI_MAX, comm)); /* one rank evaluates a point on a shared face */
    PetscCheck(owner >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "%s: the point (%g, %g, %g) is not in the fluid region", option, (double)X[3 * i], (double)X[3 * i + 1], (double)X[3 * i + 2]);
    probes.owner[i] = owner;
    if (owner == rank) probes.cell[i] = found;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode PressureProbesRecord(MPI_Comm comm, const FieldCells &pressure, const PetscScalar *x, PetscReal t, PressureProbes &probes)
{
  const size_t           n = probes.cell.size();
  std::vector<PetscReal> p(n, 0.0);

  PetscFunctionBegin;
  for (size_t i = 0; i < n; i++)
    if (probes.cell[i] >= 0) {
      PetscReal pe[4];
      Gather(pressure, probes.cell[i], x, pe);
      for (int c = 0; c < 4; c++) p[i] += probes.lambda[4 * i + c] * pe[c];
    }
  PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, p.data(), (PetscMPIInt)n, MPIU_REAL, MPIU_SUM, comm));
  probes.t.push_back(t);
  probes.p.insert(probes.p.end(), p.begin(), p.end());
  PetscFunctionReturn(0);
}

std::vector<PetscReal> PressureProbesArrival(const PressureProbes &probes, PetscReal level)
{
  const size_t           n = probes.cell.size();
  std::vector<PetscReal> arrival(n, -1);
  for (size_t i = 0; i < n; i++) {
    PetscReal tb = 0, pb = 0; /* the state before the first record: at rest */
    for (size_t k = 0; k < probes.t.size() && arrival[i] < 0; k++) {
      const PetscReal pk = probes.p[n * k + i];
      if (pb < level && pk >= level) arrival[i] = tb + (level - pb) / (pk - pb) * (probes.t[k] - tb);
      tb = probes.t[k], pb = pk;
    }
  }
  return arrival;
}

} // namespace fsi
