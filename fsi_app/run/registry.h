// SPDX-License-Identifier: BSD-2-Clause
/* A scene's blocks: the ones it names (-blocks), made from the registry of block types, wired
   to each other and each reading its own options; the mesh with the groups they name; then on
   one DM every block's fields, every block's conditions (they build the section's
   constraints), and each block's cells. The blocks' rows sum to the scene's system. */
#pragma once

#include "core/scene.h"
#include "core/block.h"
#include "run/splits.h"
#include "core/system.h"
#include <memory>

namespace fsi {

struct Blocks {
  std::vector<std::unique_ptr<Block>> owned;
  std::vector<Block *>                list; /* in the registry's order: the order of their fields */
  Conditions                          conditions;
  System                              system;

  /* The named splits of PCFIELDSPLIT (run/splits.h), in their blocks' places. */
  fsi::Splits Splits() const;
  /* The prefixes of every block type's options ("structure_", ...): an unused option that
     starts with one is a mistake (CheckUnusedOptions). */
  static std::vector<std::string> Prefixes();
};

/* The blocks the scene names, wired and with their options read (before the mesh exists:
   they name the groups it must have); sc.problem gets their problem-defining options. */
PetscErrorCode CreateBlocks(Scene &sc, Blocks &b);

/* The scene's mesh with the groups the blocks need, its cells balanced over the ranks region
   by region, refined (-refine); a label "boundary" on its boundary faces. */
PetscErrorCode CreateSceneMesh(const Scene &sc, const Blocks &b, DM *dm);

/* Fields, conditions, the section, cells; the system becomes dm's residual and Jacobian.
   `sc` and `b` must outlive dm. */
PetscErrorCode SetUpBlocks(DM dm, Blocks &b);

} // namespace fsi
