// SPDX-License-Identifier: BSD-2-Clause
#include "wall_shear.h"
#include "discretization/fields.h"
#include "discretization/ale_map.h"
#include "mesh/mesh.h"
#include <petscsf.h>

namespace fsi {

PetscErrorCode WallShearSetUp(DM dm, const FluidForms &fb, const std::string &groups, PetscReal from, WallShear &w)
{
  PetscInt pStart, pEnd;

  PetscFunctionBegin;
  for (const auto &g : SplitList(groups.c_str())) {
    DMLabel               label;
    std::vector<CellFace> f;
    PetscCall(DMGetLabel(dm, g.substr(0, g.find(':')).c_str(), &label));
    PetscCall(CellFacesCreate(dm, fb.velocity, label, f));
    w.faces.insert(w.faces.end(), f.begin(), f.end());
  }
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCall(OwnedPoints(dm, w.owned));
  w.weight.assign(pEnd, 0), w.position.assign(3 * pEnd, 0), w.tau.assign(3 * pEnd, 0);
  w.tawss.assign(pEnd, 0), w.osi.assign(pEnd, 0), w.sums.assign(4 * pEnd + 1, 0);
  w.from = from;
  PetscFunctionReturn(0);
}

/* The cell node of face f's node j: its vertices, then the edges 01, 12, 02 of its slots. */
static int FaceNode(const CellFace &f, int j)
{
  static const int ends[3][2] = {{0, 1}, {1, 2}, {0, 2}};
  if (j < 3) return f.slot[j];
  const int a = f.slot[ends[j - 3][0]], b = f.slot[ends[j - 3][1]];
  for (int e = 0; e < 6; e++)
    if ((EdgeVertex[e][0] == a && EdgeVertex[e][1] == b) || (EdgeVertex[e][0] == b && EdgeVertex[e][1] == a)) return 4 + e;
  return -1;
}

/* Per point: the area-weighted sums of tau (3), the area (1) and the position (3) over the
   rank's faces; the point SF adds the ghosts' sums to their owners'. */
static PetscErrorCode Accumulate(DM dm, const FluidForms &fb, const PetscScalar *x, const WallShear &w, std::vector<PetscReal> &sum)
{
  PetscSF      sf;
  MPI_Datatype unit;

  PetscFunctionBegin;
  std::fill(sum.begin(), sum.end(), 0.0);
  for (const CellFace &f : w.faces) {
    const CellGeometry &g = fb.velocity.geom[f.k];
    PetscReal           ue[30], de[30], e1[3], e2[3], N0[3];
    Gather(fb.velocity, f.k, x, ue);
    if (fb.mesh) Gather(*fb.mesh, f.k, x, de);
    for (int d = 0; d < 3; d++) e1[d] = g.x[f.slot[1]][d] - g.x[f.slot[0]][d], e2[d] = g.x[f.slot[2]][d] - g.x[f.slot[0]][d];
    N0[0] = e1[1] * e2[2] - e1[2] * e2[1], N0[1] = e1[2] * e2[0] - e1[0] * e2[2], N0[2] = e1[0] * e2[1] - e1[1] * e2[0];
    const PetscReal area2 = PetscSqrtReal(N0[0] * N0[0] + N0[1] * N0[1] + N0[2] * N0[2]);
    for (int d = 0; d < 3; d++) N0[d] *= f.sign / area2;
    for (int j = 0; j < 6; j++) {
      const int  a    = FaceNode(f, j);
      PetscReal  l[4] = {0, 0, 0, 0}, N[10], n[3], G[9] = {0}, sn[3], nsn = 0;
      MovedPoint m;
      l[a < 4 ? a : EdgeVertex[a - 4][0]] += a < 4 ? 1.0 : 0.5;
      if (a >= 4) l[EdgeVertex[a - 4][1]] += 0.5;
      P2Values(l, N);
      MovePoint(g, fb.mesh ? de : nullptr, l, N, m);
      for (int i = 0; i < 3; i++) n[i] = m.J * (m.Finv[0][i] * N0[0] + m.Finv[1][i] * N0[1] + m.Finv[2][i] * N0[2]);
      const PetscReal ratio = PetscSqrtReal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), area = area2 / 2 * ratio;
      for (int i = 0; i < 3; i++) n[i] /= ratio;
      for (int b = 0; b < 10; b++)
        for (int i = 0; i < 3; i++)
          for (int k = 0; k < 3; k++) G[3 * i + k] += ue[3 * b + i] * m.dN[b][k];
      for (int i = 0; i < 3; i++) sn[i] = fb.mu * ((G[3 * i] + G[i]) * n[0] + (G[3 * i + 1] + G[3 + i]) * n[1] + (G[3 * i + 2] + G[6 + i]) * n[2]), nsn += sn[i] * n[i];
      PetscReal *s = &sum[7 * fb.velocity.point[10 * f.k + a]];
      for (int i = 0; i < 3; i++) s[i] -= area * (sn[i] - nsn * n[i]), s[4 + i] += area * m.x[i];
      s[3] += area;
    }
  }
  std::vector<PetscReal> ghosts(sum);
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCallMPI(MPI_Type_contiguous(7, MPIU_REAL, &unit));
  PetscCallMPI(MPI_Type_commit(&unit));
  PetscCall(PetscSFReduceBegin(sf, unit, ghosts.data(), sum.data(), MPI_SUM));
  PetscCall(PetscSFReduceEnd(sf, unit, ghosts.data(), sum.data(), MPI_SUM));
  PetscCallMPI(MPI_Type_free(&unit));
  PetscFunctionReturn(0);
}

PetscErrorCode WallShearCompute(DM dm, const FluidForms &fb, const PetscScalar *x, PetscReal t, PetscReal dt, WallShear &w)
{
  std::vector<PetscReal> sum(7 * w.weight.size());
  const bool             averaged = t > w.from + 1e-12 * (1 + PetscAbsReal(w.from));

  PetscFunctionBegin;
  PetscCall(Accumulate(dm, fb, x, w, sum));
  PetscReal &span = w.sums.back();
  if (averaged) span += dt;
  for (size_t p = 0; p < w.weight.size(); p++) {
    const PetscReal *s = &sum[7 * p];
    w.weight[p]        = w.owned[p] ? s[3] : 0.0;
    if (w.weight[p] <= 0) continue;
    PetscReal *tau = &w.tau[3 * p], *I = &w.sums[4 * p];
    for (int i = 0; i < 3; i++) tau[i] = s[i] / s[3], w.position[3 * p + i] = s[4 + i] / s[3];
    const PetscReal mag = PetscSqrtReal(tau[0] * tau[0] + tau[1] * tau[1] + tau[2] * tau[2]);
    if (averaged) {
      for (int i = 0; i < 3; i++) I[i] += dt * tau[i];
      I[3] += dt * mag;
    }
    if (span > 0) w.tawss[p] = I[3] / span;
    w.osi[p] = I[3] > 0 ? (1 - PetscSqrtReal(I[0] * I[0] + I[1] * I[1] + I[2] * I[2]) / I[3]) / 2 : 0.0;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode WallShearError(DM dm, const WallShear &w, ExactShear exact, const void *ctx, PetscReal t, PetscReal *error, PetscReal *norm)
{
  PetscReal s[2] = {0, 0};

  PetscFunctionBegin;
  for (size_t p = 0; p < w.weight.size(); p++) {
    if (w.weight[p] <= 0) continue;
    PetscReal e[3];
    exact(&w.position[3 * p], t, ctx, e);
    for (int i = 0; i < 3; i++) s[0] += w.weight[p] * PetscSqr(w.tau[3 * p + i] - e[i]), s[1] += w.weight[p] * e[i] * e[i];
  }
  PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, s, 2, MPIU_REAL, MPIU_SUM, PetscObjectComm((PetscObject)dm)));
  *error = PetscSqrtReal(s[0]), *norm = PetscSqrtReal(s[1]);
  PetscFunctionReturn(0);
}

PetscErrorCode WallShearSummarize(DM dm, const WallShear &w, WallShearSummary &s)
{
  PetscReal m[3] = {0, -1, 0}, a[2] = {0, 0}; /* max |tau|, max -OSI, max OSI; sums of a TAWSS, a */

  PetscFunctionBegin;
  for (size_t p = 0; p < w.weight.size(); p++) {
    if (w.weight[p] <= 0) continue;
    const PetscReal *tau = &w.tau[3 * p];
    m[0] = PetscMax(m[0], PetscSqrtReal(tau[0] * tau[0] + tau[1] * tau[1] + tau[2] * tau[2]));
    m[1] = PetscMax(m[1], -w.osi[p]), m[2] = PetscMax(m[2], w.osi[p]);
    a[0] += w.weight[p] * w.tawss[p], a[1] += w.weight[p];
  }
  PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, m, 3, MPIU_REAL, MPIU_MAX, PetscObjectComm((PetscObject)dm)));
  PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, a, 2, MPIU_REAL, MPIU_SUM, PetscObjectComm((PetscObject)dm)));
  s = {m[0], a[1] > 0 ? a[0] / a[1] : 0.0, -m[1], m[2]};
  PetscFunctionReturn(0);
}

} // namespace fsi
