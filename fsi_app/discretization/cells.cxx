// SPDX-License-Identifier: BSD-2-Clause
#include "cells.h"
#include "discretization/ale_map.h"
#include "discretization/csr_add.h"
#include "base/files.h"
#include "mesh/mesh.h"
#include <algorithm>
#include <cstdio>

namespace fsi {

/* Why a curved cell's map does not keep its orientation (J <= 0 at one of its ten nodes or
   its centroid), or "" if it does. */
static std::string Folded(const CellGeometry &g)
{
  const PetscReal at[11][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}, {.5, .5, 0, 0}, {.5, 0, .5, 0}, {.5, 0, 0, .5}, {0, .5, .5, 0}, {0, .5, 0, .5}, {0, 0, .5, .5}, {.25, .25, .25, .25}};
  for (const auto &l : at) {
    PetscReal  N[10];
    MovedPoint m;
    char       s[512];
    P2Values(l, N);
    const PetscReal J = MovePoint(g, nullptr, l, N, m);
    if (J > 0) continue;
    std::snprintf(s, sizeof(s), "the curved tetrahedron with vertices (%g, %g, %g), (%g, %g, %g), (%g, %g, %g), (%g, %g, %g) is folded by its second-order nodes (J = %g at (%g, %g, %g)); mesh with smaller cells where the boundary curves, or read the file with -mesh_order 1",
                  (double)g.x[0][0], (double)g.x[0][1], (double)g.x[0][2], (double)g.x[1][0], (double)g.x[1][1], (double)g.x[1][2], (double)g.x[2][0], (double)g.x[2][1], (double)g.x[2][2], (double)g.x[3][0], (double)g.x[3][1], (double)g.x[3][2], (double)J, (double)m.x[0], (double)m.x[1], (double)m.x[2]);
    return s;
  }
  return "";
}

PetscErrorCode FieldCellsCreate(DM dm, DMLabel region, PetscInt field, FieldCells &cells)
{
  PetscSection local, global;
  PetscInt     cStart, cEnd, nf;
  std::string  folded; /* the first curved cell of this rank that its nodes fold */

  PetscFunctionBegin;
  PetscCall(DMGetLocalSection(dm, &local));
  PetscCall(DMGetGlobalSection(dm, &global));
  PetscCall(PetscSectionGetNumFields(local, &nf));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  cells       = FieldCells();
  cells.field = field;
  PetscCall(PetscSectionGetFieldComponents(local, field, &cells.nc));
  for (PetscInt c = cStart; c < cEnd; c++) {
    PetscInt v = 1;
    if (region) PetscCall(DMLabelGetValue(region, c, &v));
    if (v != 1) continue;
    CellGeometry g;
    PetscInt     pt[10], n, *idx, ncl, *closure = nullptr;
    PetscCall(CellP2(dm, c, g, pt));
    if (g.curved && folded.empty()) folded = Folded(g);
    /* closure indices are field-major: field f's block starts after the other fields' dofs of
       the whole closure; within it, each point's dofs of f in closure order */
    std::vector<PetscInt> start(nf + 1, 0);
    std::vector<std::pair<PetscInt, PetscInt>> within; /* (point, offset in field's block) */
    PetscCall(DMPlexGetTransitiveClosure(dm, c, PETSC_TRUE, &ncl, &closure));
    for (PetscInt j = 0; j < ncl; j++)
      for (PetscInt f = 0; f < nf; f++) {
        PetscInt dof;
        PetscCall(PetscSectionGetFieldDof(local, closure[2 * j], f, &dof));
        if (f == field) within.push_back({closure[2 * j], start[f + 1]});
        start[f + 1] += dof;
      }
    PetscCall(DMPlexRestoreTransitiveClosure(dm, c, PETSC_TRUE, &ncl, &closure));
    for (PetscInt f = 0; f < nf; f++) start[f + 1] += start[f];
    PetscInt edgeDofs;
    PetscCall(PetscSectionGetFieldDof(local, pt[4], field, &edgeDofs));
    cells.nodes = edgeDofs ? 10 : 4;
    PetscCall(DMPlexGetClosureIndices(dm, local, global, c, PETSC_TRUE, &n, &idx, nullptr, nullptr));
    for (PetscInt a = 0; a < cells.nodes; a++) {
      PetscInt lo, at = -1;
      PetscCall(PetscSectionGetFieldOffset(local, pt[a], field, &lo));
      for (const auto &w : within)
        if (w.first == pt[a]) at = start[field] + w.second;
      cells.local.push_back(lo);
      for (PetscInt i = 0; i < cells.nc; i++) cells.global.push_back(idx[at + i]);
    }
    PetscCall(DMPlexRestoreClosureIndices(dm, local, global, c, PETSC_TRUE, &n, &idx, nullptr, nullptr));
    cells.point.insert(cells.point.end(), pt, pt + 10);
    cells.cell.push_back(c), cells.geom.push_back(g);
  }
  cells.rows = cells.global;
  PetscCall(CheckOnAnyRank(PetscObjectComm((PetscObject)dm), PETSC_ERR_ARG_WRONG, folded));
  PetscFunctionReturn(0);
}

void FieldCellsDropRows(FieldCells &cells, const std::vector<PetscInt> &points)
{
  cells.dropped.assign(cells.nodes * cells.Size(), 0);
  for (PetscInt k = 0; k < cells.Size(); k++)
    for (PetscInt a = 0; a < cells.nodes; a++)
      if (std::binary_search(points.begin(), points.end(), cells.point[10 * k + a])) {
        cells.dropped[cells.nodes * k + a] = 1;
        for (PetscInt i = 0; i < cells.nc; i++) cells.rows[cells.nc * (cells.nodes * k + a) + i] = -1;
      }
}

PetscErrorCode CellFacesCreate(DM dm, const FieldCells &cells, DMLabel label, std::vector<CellFace> &faces)
{
  PetscInt vStart, vEnd;

  PetscFunctionBegin;
  faces.clear();
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(ForEachLabelPoint(label, {}, [&](PetscInt face) -> PetscErrorCode {
    const PetscInt *support;
    PetscInt        ns, k = -1, *closure = nullptr, ncl, fv[3], nfv = 0;
    PetscFunctionBegin;
    PetscCall(DMPlexGetSupportSize(dm, face, &ns));
    PetscCall(DMPlexGetSupport(dm, face, &support));
    for (PetscInt s = 0; s < ns; s++) {
      auto it = std::lower_bound(cells.cell.begin(), cells.cell.end(), support[s]);
      if (it != cells.cell.end() && *it == support[s]) k = it - cells.cell.begin();
    }
    if (k < 0) PetscFunctionReturn(0); /* not a face of the region, or not a face at all */
    PetscCall(DMPlexGetTransitiveClosure(dm, face, PETSC_TRUE, &ncl, &closure));
    for (PetscInt j = 0; j < ncl; j++)
      if (closure[2 * j] >= vStart && closure[2 * j] < vEnd) fv[nfv++] = closure[2 * j];
    PetscCall(DMPlexRestoreTransitiveClosure(dm, face, PETSC_TRUE, &ncl, &closure));
    CellFace           f{k, {0, 0, 0}, 1};
    const PetscInt  *pt = &cells.point[10 * k];
    const auto      &x  = cells.geom[k].x;
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 4; b++)
        if (pt[b] == fv[a]) f.slot[a] = b;
    const int opposite = 6 - f.slot[0] - f.slot[1] - f.slot[2];
    PetscReal e1[3], e2[3], out[3];
    for (int d = 0; d < 3; d++) e1[d] = x[f.slot[1]][d] - x[f.slot[0]][d], e2[d] = x[f.slot[2]][d] - x[f.slot[0]][d], out[d] = x[f.slot[0]][d] - x[opposite][d];
    const PetscReal n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    f.sign               = n[0] * out[0] + n[1] * out[1] + n[2] * out[2] > 0 ? 1 : -1;
    faces.push_back(f);
    PetscFunctionReturn(0);
  }));
  PetscFunctionReturn(0);
}

void SetNodalValues(const FieldCells &cells, const std::function<void(const PetscReal X[3], PetscScalar *v)> &value, PetscScalar *x)
{
  for (PetscInt k = 0; k < cells.Size(); k++) {
    const CellGeometry &g = cells.geom[k];
    for (PetscInt a = 0; a < cells.nodes; a++) {
      PetscReal X[3];
      for (int d = 0; d < 3; d++) X[d] = a < 4 ? g.x[a][d] : (g.x[EdgeVertex[a - 4][0]][d] + g.x[EdgeVertex[a - 4][1]][d]) / 2 + (g.curved ? g.bend[3 * a + d] : 0.0);
      value(X, &x[cells.local[cells.nodes * k + a]]);
    }
  }
}

PetscErrorCode AddElementMatrix(Mat P, PetscInt nr, const PetscInt rows[], PetscInt nc, const PetscInt cols[], const PetscScalar K[])
{
  constexpr PetscInt Max = 64;
  PetscInt           order[Max], sorted[Max];
  PetscScalar        Ks[Max * Max];

  PetscFunctionBegin;
  PetscCheck(nr <= Max && nc <= Max, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "an element matrix of %" PetscInt_FMT " x %" PetscInt_FMT ", more than %" PetscInt_FMT, nr, nc, Max);
  for (PetscInt j = 0; j < nc; j++) order[j] = j;
  std::sort(order, order + nc, [&](PetscInt a, PetscInt b) { return cols[a] < cols[b]; });
  for (PetscInt j = 0; j < nc; j++) sorted[j] = cols[order[j]];
  for (PetscInt i = 0; i < nr; i++)
    for (PetscInt j = 0; j < nc; j++) Ks[i * nc + j] = K[i * nc + order[j]];
  if (const CsrAdd *csr = CsrAdd::Of(P)) PetscCall(csr->Add(nr, rows, nc, sorted, Ks));
  else PetscCall(MatSetValues(P, nr, rows, nc, sorted, Ks, ADD_VALUES));
  PetscFunctionReturn(0);
}

PetscErrorCode AssembleOperators(Mat J, Mat P)
{
  PetscFunctionBegin;
  PetscCall(MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY));
  if (J != P) {
    PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  }
  PetscFunctionReturn(0);
}

} // namespace fsi
