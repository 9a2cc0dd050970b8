// SPDX-License-Identifier: BSD-2-Clause
/* The ALE map x = X + d(X) of a cell moved by a P2 displacement d (the fluid's mesh
   displacement d_f): at a point of the reference cell, the moved point, the volume ratio
   J = det F with F = dx/dX = I + grad_X d, and the basis gradients with respect to x,
   grad_x N = F^-T grad_X N. The moved cell is a curved (isoparametric P2) tetrahedron. */
#pragma once

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

} // namespace fsi
