// SPDX-License-Identifier: BSD-2-Clause
/* The P2 tetrahedron of the application's own element loops: barycentric basis (4 vertex and
   6 edge nodes), an exact quadrature, affine geometry, and where each node's dofs sit in a
   DMPlex cell closure. PETSc's PetscFE defines the dof layout (the PetscSection); the loops
   are ours because PETSc 3.18's generic Jacobian integration is too slow for vector P2 in 3D
   (measured: 32 s for 1000 Q2 hexahedra in snes ex17, 29 s for 6464 P2 tetrahedra). */
#pragma once

#include <petscdmplex.h>
#include <vector>

namespace fsi {

/* Node k < 4: vertex k; node 4 + e: edge e = (EdgeVertex[e][0], EdgeVertex[e][1]). */
extern const int EdgeVertex[6][2];

struct P2Rule {
  PetscInt               nq = 0;
  std::vector<PetscReal> w;      /* weights on the reference tetrahedron of volume 1/6 */
  std::vector<PetscReal> lambda; /* barycentric coordinates, 4 per point */
  std::vector<PetscReal> N;      /* basis values, 10 per point */
};

/* A rule exact for polynomials of `degree` (PETSc's simplex quadrature). */
PetscErrorCode CreateP2Rule(PetscInt degree, P2Rule &rule);

/* M[a*10+b] = int N_a N_b over the reference tetrahedron (volume 1/6): times |det E| per cell. */
PetscErrorCode CreateP2Mass(PetscReal M[100]);

/* The same on a triangle: weights for area 1/2, 3 barycentric coordinates per point. */
struct FaceRule {
  PetscInt               nq = 0;
  std::vector<PetscReal> w, mu;
};
PetscErrorCode CreateFaceRule(PetscInt degree, FaceRule &rule);

/* Basis values at barycentric point l of the cell. */
void P2Values(const PetscReal l[4], PetscReal N[10]);

/* One cell: vertex coordinates, barycentric gradients, |det E| with E = [x1-x0, x2-x0, x3-x0].
   A curved (isoparametric P2) cell is the straight one whose edge nodes are moved by `bend`:
   X(l) = sum_k l_k x_k + sum_a N_a(l) bend_a, the same map as a P2 displacement of the straight
   cell (ale_map.h), so every loop that moves cells curves them too. */
struct CellGeometry {
  PetscReal x[4][3];
  PetscReal gradLambda[4][3]; /* physical gradients of the barycentric coordinates of the straight cell */
  PetscReal detE;             /* |det E|: an integral over a straight cell is sum_q w_q f(x_q) detE */
  PetscBool curved = PETSC_FALSE;
  PetscReal bend[30];         /* curved: edge node a = 4..9 sits at the straight cell's midpoint + bend[3a..3a+2]; vertices 0 */
};

/* Geometry of `cell` and the mesh point (vertex or edge) of each of its 10 P2 nodes; where a
   field's dofs sit is discretization/cells.h's business. The cell is curved where the mesh was
   read from a second-order gmsh file and an edge's node is off its midpoint (MeshEdgeNode). */
PetscErrorCode CellP2(DM dm, PetscInt cell, CellGeometry &g, PetscInt nodePoint[10]);

/* Physical basis gradients at one point: dN[a][d]. */
void P2Gradients(const CellGeometry &g, const PetscReal lambda[4], PetscReal dN[10][3]);

} // namespace fsi
