// SPDX-License-Identifier: BSD-2-Clause
#include "p2tet.h"
#include "mesh/mesh.h"
#include <petscdt.h>

namespace fsi {

const int EdgeVertex[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

/* PETSc's rule on the [-1,1] simplex of dimension dim, as weights on the unit simplex and
   dim + 1 barycentric coordinates per point. */
static PetscErrorCode BarycentricRule(PetscInt dim, PetscInt degree, std::vector<PetscReal> &w, std::vector<PetscReal> &bary)
{
  PetscQuadrature  q;
  PetscInt         qdim, nc, nq;
  const PetscReal *pts, *wts;

  PetscFunctionBegin;
  PetscCall(PetscDTSimplexQuadrature(dim, degree, PETSCDTSIMPLEXQUAD_DEFAULT, &q));
  PetscCall(PetscQuadratureGetData(q, &qdim, &nc, &nq, &pts, &wts));
  w.resize(nq), bary.resize((dim + 1) * nq);
  for (PetscInt p = 0; p < nq; p++) {
    PetscReal *l = &bary[(dim + 1) * p];
    l[0]         = 1;
    for (PetscInt d = 0; d < dim; d++) l[d + 1] = (pts[dim * p + d] + 1) / 2, l[0] -= l[d + 1];
    w[p] = wts[p] / (1 << dim); /* the map from [-1,1] halves every direction */
  }
  PetscCall(PetscQuadratureDestroy(&q));
  PetscFunctionReturn(0);
}

PetscErrorCode CreateP2Rule(PetscInt degree, P2Rule &rule)
{
  PetscFunctionBegin;
  PetscCall(BarycentricRule(3, degree, rule.w, rule.lambda));
  rule.nq = (PetscInt)rule.w.size();
  rule.N.resize(10 * rule.nq);
  for (PetscInt p = 0; p < rule.nq; p++) P2Values(&rule.lambda[4 * p], &rule.N[10 * p]);
  PetscFunctionReturn(0);
}

PetscErrorCode CreateP2Mass(PetscReal M[100])
{
  P2Rule rule;

  PetscFunctionBegin;
  PetscCall(CreateP2Rule(4, rule));
  for (int k = 0; k < 100; k++) M[k] = 0;
  for (PetscInt q = 0; q < rule.nq; q++)
    for (int a = 0; a < 10; a++)
      for (int b = 0; b < 10; b++) M[a * 10 + b] += rule.w[q] * rule.N[10 * q + a] * rule.N[10 * q + b];
  PetscFunctionReturn(0);
}

void P2Values(const PetscReal l[4], PetscReal N[10])
{
  for (int a = 0; a < 4; a++) N[a] = l[a] * (2 * l[a] - 1);
  for (int e = 0; e < 6; e++) N[4 + e] = 4 * l[EdgeVertex[e][0]] * l[EdgeVertex[e][1]];
}

PetscErrorCode CreateFaceRule(PetscInt degree, FaceRule &rule)
{
  PetscFunctionBegin;
  PetscCall(BarycentricRule(2, degree, rule.w, rule.mu));
  rule.nq = (PetscInt)rule.w.size();
  PetscFunctionReturn(0);
}

PetscErrorCode CellP2(DM dm, PetscInt cell, CellGeometry &g, PetscInt nodePoint[10])
{
  PetscInt    *closure = nullptr, nclosure, vStart, vEnd, eStart, eEnd, nv = 0;
  PetscInt     vertex[4], edge[6], edgeCone[6][2], ne = 0;
  Vec          coords;
  PetscSection csec;
  DM           cdm;
  const PetscScalar *xa;

  PetscFunctionBegin;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(DMPlexGetDepthStratum(dm, 1, &eStart, &eEnd));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(DMGetCoordinateDM(dm, &cdm));
  PetscCall(DMGetLocalSection(cdm, &csec));
  PetscCall(VecGetArrayRead(coords, &xa));
  PetscCall(DMPlexGetTransitiveClosure(dm, cell, PETSC_TRUE, &nclosure, &closure));
  for (PetscInt k = 0; k < nclosure; k++) {
    const PetscInt p = closure[2 * k];
    if (p >= vStart && p < vEnd) {
      PetscInt coff;
      PetscCall(PetscSectionGetOffset(csec, p, &coff));
      for (int d = 0; d < 3; d++) g.x[nv][d] = PetscRealPart(xa[coff + d]);
      vertex[nv++] = p;
    } else if (p >= eStart && p < eEnd) {
      const PetscInt *cone;
      PetscCall(DMPlexGetCone(dm, p, &cone));
      edgeCone[ne][0] = cone[0], edgeCone[ne][1] = cone[1], edge[ne++] = p;
    }
  }
  PetscCall(DMPlexRestoreTransitiveClosure(dm, cell, PETSC_TRUE, &nclosure, &closure));
  PetscCall(VecRestoreArrayRead(coords, &xa));
  PetscCheck(nv == 4 && ne == 6, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "cell %" PetscInt_FMT " is not a tetrahedron (%" PetscInt_FMT " vertices, %" PetscInt_FMT " edges)", cell, nv, ne);
  g.curved = PETSC_FALSE;
  for (int k = 0; k < 30; k++) g.bend[k] = 0;
  for (int e = 0; e < 6; e++) { /* our edge (a, b) is the closure edge whose cone is {vertex[a], vertex[b]} */
    const int      i = EdgeVertex[e][0], j = EdgeVertex[e][1];
    const PetscInt a = vertex[i], b = vertex[j];
    for (int f = 0; f < 6; f++)
      if ((edgeCone[f][0] == a && edgeCone[f][1] == b) || (edgeCone[f][0] == b && edgeCone[f][1] == a)) {
        PetscReal node[3], off = 0, len = 0;
        nodePoint[4 + e] = edge[f];
        if (!MeshEdgeNode(dm, g.x[i], g.x[j], node)) continue;
        for (int d = 0; d < 3; d++) {
          g.bend[3 * (4 + e) + d] = node[d] - (g.x[i][d] + g.x[j][d]) / 2;
          off += PetscSqr(g.bend[3 * (4 + e) + d]), len += PetscSqr(g.x[i][d] - g.x[j][d]);
        }
        if (off > 1e-24 * len) g.curved = PETSC_TRUE; /* straight cells keep the affine loops */
      }
  }
  for (int k = 0; k < 4; k++) nodePoint[k] = vertex[k];
  /* barycentric gradients: rows of E^{-1}, E = [x1 - x0, x2 - x0, x3 - x0] */
  PetscReal E[3][3], inv[3][3];
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++) E[r][c] = g.x[c + 1][r] - g.x[0][r];
  const PetscReal det = E[0][0] * (E[1][1] * E[2][2] - E[1][2] * E[2][1]) - E[0][1] * (E[1][0] * E[2][2] - E[1][2] * E[2][0]) + E[0][2] * (E[1][0] * E[2][1] - E[1][1] * E[2][0]);
  PetscCheck(det != 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "cell %" PetscInt_FMT " is degenerate (zero volume)", cell);
  inv[0][0] = (E[1][1] * E[2][2] - E[1][2] * E[2][1]) / det, inv[0][1] = (E[0][2] * E[2][1] - E[0][1] * E[2][2]) / det, inv[0][2] = (E[0][1] * E[1][2] - E[0][2] * E[1][1]) / det;
  inv[1][0] = (E[1][2] * E[2][0] - E[1][0] * E[2][2]) / det, inv[1][1] = (E[0][0] * E[2][2] - E[0][2] * E[2][0]) / det, inv[1][2] = (E[0][2] * E[1][0] - E[0][0] * E[1][2]) / det;
  inv[2][0] = (E[1][0] * E[2][1] - E[1][1] * E[2][0]) / det, inv[2][1] = (E[0][1] * E[2][0] - E[0][0] * E[2][1]) / det, inv[2][2] = (E[0][0] * E[1][1] - E[0][1] * E[1][0]) / det;
  for (int d = 0; d < 3; d++) {
    g.gradLambda[0][d] = 0;
    for (int k = 1; k < 4; k++) g.gradLambda[k][d] = inv[k - 1][d], g.gradLambda[0][d] -= inv[k - 1][d];
  }
  g.detE = PetscAbsReal(det);
  PetscFunctionReturn(0);
}

void P2Gradients(const CellGeometry &g, const PetscReal l[4], PetscReal dN[10][3])
{
  for (int d = 0; d < 3; d++) {
    for (int a = 0; a < 4; a++) dN[a][d] = (4 * l[a] - 1) * g.gradLambda[a][d];
    for (int e = 0; e < 6; e++) {
      const int i = EdgeVertex[e][0], j = EdgeVertex[e][1];
      dN[4 + e][d] = 4 * (l[i] * g.gradLambda[j][d] + l[j] * g.gradLambda[i][d]);
    }
  }
}

} // namespace fsi
