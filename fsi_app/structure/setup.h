/* The structure block of a scene on its displacement field (the wall's region): the material,
   the loads and the Dirichlet conditions. */
#pragma once

#include "scene.h"
#include "structure/assembly.h"

namespace fsi {

/* The Dirichlet conditions on field `field` (before any block creates its cells: they decide
   the global numbering); `sc` must outlive dm (the manufactured solution's values point into it). */
PetscErrorCode StructureConditions(const Scene &sc, DM dm, PetscInt field);
PetscErrorCode SetUpStructure(const Scene &sc, DM dm, PetscInt field, StructureBlock &sb);

/* The factor of every load (pressure, traction, body force) at time t (dynamics: the pulse and
   its ramp) or load fraction t (statics). */
PetscReal StructureLoadFactor(const Scene &sc, PetscReal t);

} // namespace fsi
