/* The fluid block of a scene on its velocity and pressure fields (the fluid region): no-slip
   groups, the inflow traction, or the exact data of the verification flows (Poiseuille, the
   manufactured flows of verification/mms.h). */
#pragma once

#include "fluid/assembly.h"
#include "scene.h"

namespace fsi {

/* The Dirichlet conditions on the velocity (before any block creates its cells); `flow` (the
   manufactured flow's data) must outlive dm. */
PetscErrorCode FluidConditions(const Scene &sc, DM dm, PetscInt velocity, const FlowMMS &flow);
PetscErrorCode SetUpFluid(const Scene &sc, DM dm, PetscInt velocity, PetscInt pressure, const FlowMMS &flow, FluidBlock &fb);

} // namespace fsi
