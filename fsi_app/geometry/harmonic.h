/* The geometry block: the harmonic extension of the interface displacement into the fluid
   region (the seed's eq. 5), -Lap d_f = 0 on the reference fluid region with d_f given on the
   interface and d_f . n = 0 on the other fluid boundaries (for the tube's planar ends: the z
   component), P2 like the structure. The fluid's mesh moves with d_f (fluid/assembly.h). Until
   the coupling exists, the interface displacement is prescribed (PrescribedMotion). */
#pragma once

#include "discretization/cells.h"
#include "scene.h"
#include <petscsnes.h>

namespace fsi {

struct GeometryBlock {
  FieldCells cells;
  P2Rule     rule; /* degree 2: the P2 stiffness exactly */
};

/* The conditions on field `field` (call before any block creates its cells): d_f = the motion
   on -geometry_interface, the sliding ends of -geometry_slip. `motion` must outlive dm. */
PetscErrorCode GeometryConditions(const Scene &sc, DM dm, PetscInt field, const PrescribedMotion &motion);
PetscErrorCode SetUpGeometry(const Scene &sc, DM dm, PetscInt field, GeometryBlock &gb);

/* BlockOps of solver/system.h (the context is the GeometryBlock). */
PetscErrorCode GeometryResidual(void *ctx, const PetscScalar *x, PetscScalar *f);
PetscErrorCode GeometryJacobian(void *ctx, const PetscScalar *x, Mat P);

} // namespace fsi
