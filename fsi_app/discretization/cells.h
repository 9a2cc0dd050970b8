// SPDX-License-Identifier: BSD-2-Clause
/* The cells of one field on a region, prepared once: geometry, where each node's values sit in
   a local vector, and the global indices of the cell's dofs of this field for matrix assembly
   (negative where constrained: MatSetValues skips them). Every later loop is plain array
   access: PETSc's closure queries per cell and evaluation cost more than the kernels.
   P2 fields have 10 nodes (p2tet.h order), P1 fields 4 (the vertices); dof nc a + i is
   component i of node a. */
#pragma once

#include "discretization/p2tet.h"
#include <functional>

namespace fsi {

struct FieldCells {
  PetscInt                  field = 0, nodes = 10, nc = 3;
  std::vector<PetscInt>     cell;   /* mesh cells, sorted */
  std::vector<CellGeometry> geom;
  std::vector<PetscInt>     local;  /* `nodes` per cell: local-vector offset of the node's first dof */
  std::vector<PetscInt>     global; /* nodes nc per cell */
  std::vector<PetscInt>     rows;   /* the rows the block assembles: global, but -1 at dropped nodes */
  std::vector<char>         dropped; /* per cell node: its rows belong to another block (empty: none) */
  std::vector<PetscInt>     point;  /* 10 per cell: the mesh points of the P2 nodes (vertices, edges) */

  PetscInt Size() const { return (PetscInt)cell.size(); }
  PetscInt Dofs() const { return nodes * nc; }
};

/* The cells of `region` (value 1; every cell if NULL) for field `field` of dm (P1 or P2). */
PetscErrorCode FieldCellsCreate(DM dm, DMLabel region, PetscInt field, FieldCells &cells);

/* A face of the region's boundary in a labelled group, as a face of cell k: the face is
   l[slot[0..2]] = 0 of the barycentric coordinates opposite vertex 6 - sum(slot); `sign`
   makes (x_1 - x_0) x (x_2 - x_0) of its vertices slot[0..2] point out of the cell. */
struct CellFace {
  PetscInt  k;
  int       slot[3];
  PetscReal sign;
};

/* The faces of `label` (any value) that bound one of `cells`. */
PetscErrorCode CellFacesCreate(DM dm, const FieldCells &cells, DMLabel label, std::vector<CellFace> &faces);

/* The Dofs() values of cell k from a local array. */
inline void Gather(const FieldCells &cells, PetscInt k, const PetscScalar *x, PetscReal *xe)
{
  const PetscInt *lo = &cells.local[cells.nodes * k];
  for (PetscInt a = 0; a < cells.nodes; a++)
    for (PetscInt i = 0; i < cells.nc; i++) xe[cells.nc * a + i] = PetscRealPart(x[lo[a] + i]);
}

/* Add the Dofs() values of cell k into a local array (not at dropped nodes). */
inline void Scatter(const FieldCells &cells, PetscInt k, const PetscReal *re, PetscScalar *f)
{
  const PetscInt *lo = &cells.local[cells.nodes * k];
  const char     *drop = cells.dropped.empty() ? nullptr : &cells.dropped[cells.nodes * k];
  for (PetscInt a = 0; a < cells.nodes; a++)
    if (!drop || !drop[a])
      for (PetscInt i = 0; i < cells.nc; i++) f[lo[a] + i] += re[cells.nc * a + i];
}

/* Leave the rows of the nodes on `points` (sorted mesh points) to another block: Scatter skips
   them and rows[] is -1 there (MatSetValues skips negative rows). */
void FieldCellsDropRows(FieldCells &cells, const std::vector<PetscInt> &points);

/* Set the field's values at its nodes in a local array: value(X, v) at each node's reference
   position X (an initial state). */
void SetNodalValues(const FieldCells &cells, const std::function<void(const PetscReal X[3], PetscScalar *v)> &value, PetscScalar *x);

/* P += K, an element matrix (nr x nc, row-major, nc <= 64) at rows x cols, its columns sorted:
   straight into P's storage while a CsrAdd is open on it (discretization/csr_add.h), else
   through MatSetValues() (negative indices stay skipped). */
PetscErrorCode AddElementMatrix(Mat P, PetscInt nr, const PetscInt rows[], PetscInt nc, const PetscInt cols[], const PetscScalar K[]);

/* Final assembly of the preconditioning matrix P and, if it is another matrix, of J. */
PetscErrorCode AssembleOperators(Mat J, Mat P);

} // namespace fsi
