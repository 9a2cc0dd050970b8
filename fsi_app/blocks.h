// SPDX-License-Identifier: BSD-2-Clause
/* A scene's blocks: the ones it names (-blocks, or -physics as a shorthand), made from the
   registry of block types, wired to each other and each reading its own options; then on one
   DM every block's fields, every block's conditions (they build the section's constraints),
   and each block's cells. The blocks' rows sum to the scene's system. */
#pragma once

#include "scene.h"
#include "solver/block.h"
#include "solver/splits.h"
#include "solver/system.h"
#include <memory>

namespace fsi {

struct Blocks {
  std::vector<std::unique_ptr<Block>> owned;
  std::vector<Block *>                list; /* in the registry's order: the order of their fields */
  Conditions                          conditions;
  System                              system;

  /* The named splits of PCFIELDSPLIT (solver/splits.h), in their blocks' places. */
  fsi::Splits Splits() const;
};

/* The blocks the scene names, wired and with their options read (before the mesh exists:
   they name the groups it must have); sc.problem gets their problem-defining options. */
PetscErrorCode CreateBlocks(Scene &sc, Blocks &b);

/* Fields, conditions, the section, cells; the system becomes dm's residual and Jacobian.
   `sc` and `b` must outlive dm. */
PetscErrorCode SetUpBlocks(DM dm, Blocks &b);

} // namespace fsi
