/* Where the Lagrange nodes of a P1/P2 field are (vertices and edge midpoints), and what lives
   there: essential boundary values and the rigid-body modes. Point evaluation at the nodes is
   the P2 Lagrange dual basis, so nodal values are exact interpolation. */
#pragma once

#include <petscdmplex.h>

namespace fsi {

/* Position of the node on `point` (a vertex or an edge), from the local coordinates. */
PetscErrorCode NodePosition(DM dm, PetscInt point, PetscReal x[3]);

/* Set the constrained dofs of `local` from the essential conditions registered with
   DMAddBoundary(): each condition's function evaluated at the nodes in the closure of its
   label's points. (DMPlexInsertBoundaryValues() projects through every cell's PetscFE and fails
   for fields that live on a region.) The nodes are found on the first call and kept on the DM:
   add every boundary condition before. */
PetscErrorCode InsertEssentialValues(DM dm, PetscReal t, Vec local);

/* The six rigid-body modes of vector field `field`, orthonormalised, as a near-null space. */
PetscErrorCode RigidBodyModes(DM dm, PetscInt field, MatNullSpace *nsp);

} // namespace fsi
