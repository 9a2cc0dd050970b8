// SPDX-License-Identifier: BSD-2-Clause
/* Where the Lagrange nodes of a P1/P2 field are (vertices and edge midpoints), and the
   rigid-body modes at them. Point evaluation at the nodes is the P2 Lagrange dual basis, so
   nodal values are exact interpolation. */
#pragma once

#include <petscdmplex.h>

namespace fsi {

/* Position of the node on `point` (a vertex or an edge), from the local coordinates. */
PetscErrorCode NodePosition(DM dm, PetscInt point, PetscReal x[3]);

/* The six rigid-body modes of vector field `field`, orthonormalised, as a near-null space. */
PetscErrorCode RigidBodyModes(DM dm, PetscInt field, MatNullSpace *nsp);

} // namespace fsi
