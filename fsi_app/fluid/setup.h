/* The fluid block of a scene: velocity and pressure on the fluid region, no-slip groups, the
   inflow traction (or the exact tractions of the Poiseuille verification), and its residual
   and Jacobian on the DM. */
#pragma once

#include "fluid/assembly.h"
#include "scene.h"

namespace fsi {

/* Fields `velocity` and `pressure`; `sc` must outlive the block. */
PetscErrorCode SetUpFluid(const Scene &sc, DM dm, FluidBlock &fb, PetscInt *velocity, PetscInt *pressure);

} // namespace fsi
