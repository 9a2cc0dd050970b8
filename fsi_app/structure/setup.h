/* The structure block of a scene: its displacement field on the wall's region, the material,
   the loads and the Dirichlet conditions, and its residual and Jacobian on the DM. */
#pragma once

#include "scene.h"
#include "structure/assembly.h"

namespace fsi {

/* `sc` must outlive the block (the manufactured solution's boundary values point into it). */
PetscErrorCode SetUpStructure(const Scene &sc, DM dm, StructureBlock &sb, PetscInt *field);

/* The factor of every load (pressure, traction, body force) at time t (dynamics: the pulse and
   its ramp) or load fraction t (statics). */
PetscReal StructureLoadFactor(const Scene &sc, PetscReal t);

} // namespace fsi
