/* The structure block of a scene: its displacement field on the wall's region, the material,
   the loads and the Dirichlet conditions, and its residual and Jacobian on the DM. */
#pragma once

#include "scene.h"
#include "structure/assembly.h"

namespace fsi {

/* `sc` must outlive the block (the manufactured solution's boundary values point into it). */
PetscErrorCode SetUpStructure(const Scene &sc, DM dm, StructureBlock &sb, PetscInt *field);

/* The pressure on the loaded faces at time t (dynamics) or load fraction t (statics). */
PetscReal StructurePressure(const Scene &sc, PetscReal t);

} // namespace fsi
