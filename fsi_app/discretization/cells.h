/* The cells of one P2 vector field on a region, prepared once: geometry, where each node's
   three values sit in a local vector, and the global indices of the cell's 30 dofs for matrix
   assembly (negative where constrained: MatSetValues skips them). Every later loop is plain
   array access: PETSc's closure queries per cell and evaluation cost more than the kernels.
   Dof 3a + i is component i of node a (node order of p2tet.h). */
#pragma once

#include "discretization/p2tet.h"

namespace fsi {

struct P2Cells {
  PetscInt                  field = 0;
  std::vector<PetscInt>     cell;   /* mesh cells, sorted */
  std::vector<CellGeometry> geom;
  std::vector<PetscInt>     local;  /* 10 per cell: local-vector offset of node a's first dof */
  std::vector<PetscInt>     global; /* 30 per cell */
  std::vector<PetscInt>     point;  /* 10 per cell: the node's mesh point (vertex or edge) */

  PetscInt Size() const { return (PetscInt)cell.size(); }
};

/* The cells of `region` (value 1; every cell if NULL) for field `field` of dm. */
PetscErrorCode P2CellsCreate(DM dm, DMLabel region, PetscInt field, P2Cells &cells);

/* A face of the region's boundary in a labelled group, as a face of cell k: the face is
   l[slot[0..2]] = 0 of the barycentric coordinates opposite vertex 6 - sum(slot); `sign`
   makes (x_1 - x_0) x (x_2 - x_0) of its vertices slot[0..2] point out of the cell. */
struct P2Face {
  PetscInt  k;
  int       slot[3];
  PetscReal sign;
};

/* The faces of `label` (any value) that bound one of `cells`. */
PetscErrorCode P2FacesCreate(DM dm, const P2Cells &cells, DMLabel label, std::vector<P2Face> &faces);

/* The 30 values of cell k from a local array, node-major. */
inline void P2Gather(const P2Cells &cells, PetscInt k, const PetscScalar *x, PetscReal xe[30])
{
  const PetscInt *lo = &cells.local[10 * k];
  for (int a = 0; a < 10; a++)
    for (int i = 0; i < 3; i++) xe[3 * a + i] = PetscRealPart(x[lo[a] + i]);
}

/* Add the 30 values of cell k into a local array. */
inline void P2Scatter(const P2Cells &cells, PetscInt k, const PetscReal re[30], PetscScalar *f)
{
  const PetscInt *lo = &cells.local[10 * k];
  for (int a = 0; a < 10; a++)
    for (int i = 0; i < 3; i++) f[lo[a] + i] += re[3 * a + i];
}

} // namespace fsi
