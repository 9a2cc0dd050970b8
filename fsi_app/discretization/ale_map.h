// SPDX-License-Identifier: BSD-2-Clause
/* The ALE map x = X + d(X) of a cell moved by a P2 displacement d (the fluid's mesh
   displacement d_f): at a point of the reference cell, the moved point, the volume ratio
   J = det F with F = dx/dX = I + grad_X d, and the basis gradients with respect to x,
   grad_x N = F^-T grad_X N. The moved cell is a curved (isoparametric P2) tetrahedron. */
#pragma once

#include "discretization/cells.h"
#include "discretization/p2tet.h"

namespace fsi {

struct MovedPoint {
  PetscReal x[3];
  PetscReal J;          /* dx = J dX */
  PetscReal Finv[3][3]; /* (dx/dX)^-1: the normal of a moved face is J F^-T N (Nanson) */
  PetscReal dN[10][3];  /* P2 basis gradients in x */
  PetscReal dL[4][3];   /* P1 (barycentric) basis gradients in x */
};

/* F = I + grad d at a point from the nodal displacements de (10 nodes x 3) and reference
   gradients dN; returns det F. */
PetscReal DeformationGradient(const PetscReal de[30], const PetscReal dN[10][3], PetscReal F[9]);

/* The point l (barycentric) of cell g moved by de, from the straight cell: a curved cell's bend
   is added to de (the map is X + bend + de); de == nullptr: the cell does not move (J = 1,
   F = I for a straight cell; the bend's J and F for a curved one). An integral over the moved
   cell is sum_q w_q f detE J. Returns the point's J: the caller decides what J <= 0 means. */
PetscReal MovePoint(const CellGeometry &g, const PetscReal *de, const PetscReal l[4], const PetscReal N[10], MovedPoint &m);

/* At point q of `rule` in cell g, unmoved: the basis gradients in its coordinates, the point X
   (if asked) and its weight w_q |dX/dl| (affine for a straight cell, through the bend for a
   curved one, whose J > 0 FieldCellsCreate checked). */
PetscReal ReferenceGradients(const CellGeometry &g, const P2Rule &rule, PetscInt q, PetscReal dN[10][3], PetscReal X[3] = nullptr);

/* Each point of `rule` on face f of cell g moved by de (nullptr: fixed): body(N, x, n, w) with
   the basis values, the moved point, the outward unit normal and the area weight; n da =
   J F^-T N dA (Nanson). The face's integrals of the fluid's tractions and fluxes. */
template <class Body>
void ForEachFacePoint(const CellGeometry &g, const FaceRule &rule, const CellFace &f, const PetscReal *de, Body body)
{
  PetscReal e1[3], e2[3], N0[3];
  for (int d = 0; d < 3; d++) e1[d] = g.x[f.slot[1]][d] - g.x[f.slot[0]][d], e2[d] = g.x[f.slot[2]][d] - g.x[f.slot[0]][d];
  N0[0] = e1[1] * e2[2] - e1[2] * e2[1], N0[1] = e1[2] * e2[0] - e1[0] * e2[2], N0[2] = e1[0] * e2[1] - e1[1] * e2[0];
  const PetscReal area2 = PetscSqrtReal(N0[0] * N0[0] + N0[1] * N0[1] + N0[2] * N0[2]); /* twice the reference face's area */
  for (int d = 0; d < 3; d++) N0[d] *= f.sign / area2;
  for (PetscInt q = 0; q < rule.nq; q++) {
    PetscReal  l[4] = {0, 0, 0, 0}, N[10], n[3];
    MovedPoint m;
    for (int a = 0; a < 3; a++) l[f.slot[a]] = rule.mu[3 * q + a];
    P2Values(l, N);
    MovePoint(g, de, l, N, m);
    for (int j = 0; j < 3; j++) n[j] = m.J * (m.Finv[0][j] * N0[0] + m.Finv[1][j] * N0[1] + m.Finv[2][j] * N0[2]);
    const PetscReal ratio = PetscSqrtReal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]); /* da / dA */
    for (int d = 0; d < 3; d++) n[d] /= ratio;
    body(N, m.x, n, rule.w[q] * area2 * ratio);
  }
}

} // namespace fsi
