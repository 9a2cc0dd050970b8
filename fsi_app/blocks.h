/* The blocks a scene names, on one DM: their fields, their conditions, their cells, and the
   nonlinear system they sum to. A field of a block the scene does not solve is -1 and allocates
   nothing: a structure scene has no fluid unknowns, a fluid scene on a fixed mesh no geometry. */
#pragma once

#include "fluid/setup.h"
#include "geometry/harmonic.h"
#include "solver/system.h"
#include "structure/setup.h"

namespace fsi {

struct Fields {
  PetscInt displacement = -1, velocity = -1, pressure = -1, geometry = -1;
};

struct Blocks {
  Fields           fields;
  StructureBlock   structure;
  FluidBlock       fluid;
  GeometryBlock    geometry;
  PrescribedMotion motion; /* prescribed data the conditions point to */
  FlowMMS          flow;
  System           system;
};

/* Fields, then every block's conditions (they fix the numbering), then each block's cells;
   the system becomes dm's residual and Jacobian. `sc` and `b` must outlive dm. The caller
   hands the blocks the SNES (told of inverted cells) and the time history. */
PetscErrorCode CreateBlocks(const Scene &sc, DM dm, Blocks &b);

} // namespace fsi
