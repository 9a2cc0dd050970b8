// SPDX-License-Identifier: BSD-2-Clause
/* A scene's blocks: the ones it names (-blocks, or -physics as a shorthand), wired to each
   other (the fluid moves with the geometry; the coupling ties structure, fluid and geometry),
   on one DM: every block's fields, then every block's conditions (they build the section's
   constraints), then each block's cells. The blocks' rows sum to the scene's system. */
#pragma once

#include "coupling/block.h"
#include "fluid/block.h"
#include "geometry/block.h"
#include "solver/splits.h"
#include "solver/system.h"
#include "structure/block.h"
#include <memory>

namespace fsi {

struct Blocks {
  std::unique_ptr<StructureBlock> structure;
  std::unique_ptr<FluidBlock>     fluid;
  std::unique_ptr<GeometryBlock>  geometry;
  std::unique_ptr<CouplingBlock>  coupling;
  std::vector<Block *>            list; /* in the order of their fields */
  Conditions                      conditions;
  System                          system;

  /* The named splits of PCFIELDSPLIT (solver/splits.h). */
  fsi::Splits Splits() const;
};

/* The blocks of the scene, before the mesh exists (they name the groups it must have). */
PetscErrorCode CreateBlocks(const Scene &sc, Blocks &b);

/* Fields, conditions, the section, cells; the system becomes dm's residual and Jacobian.
   `sc` and `b` must outlive dm. */
PetscErrorCode SetUpBlocks(DM dm, Blocks &b);

} // namespace fsi
