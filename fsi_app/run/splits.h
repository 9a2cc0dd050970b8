// SPDX-License-Identifier: BSD-2-Clause
/* PCFIELDSPLIT by name. A scene of several blocks splits its system into the blocks' named
   splits (structure, geometry, fluid — the order of the block lower triangle: the geometry
   follows the structure, the fluid follows both), so options files address them by name,
   -fieldsplit_structure_pc_type gdsw, and adding a field never retargets an options file. Each
   split's KSP gets the sub-DM of its fields (a nested PCFIELDSPLIT splits by field name,
   -fieldsplit_fluid_fieldsplit_velocity_...) and the block that owns the split configures its
   PC there as it would the whole system's: gdsw gets the wall's subdomains and coordinates in
   the split's numbering, and the rigid-body modes reach the split's matrix as its near-null
   space. Each split's preconditioner is set up before the Krylov iteration, under the log
   event SplitSetUp_<name>, as often as its block asks (Block::SetUpPolicy: a linear wall's
   once per run). Options that split by number (-pc_fieldsplit_0_fields) keep PETSc's meaning. */
#pragma once

#include "core/block.h"
#include <petscsnes.h>
#include <string>
#include <vector>

namespace fsi {

struct Split {
  std::string           name;
  std::vector<PetscInt> fields; /* of the whole DM */
  Block                *owner;  /* the block of the split's name (it configures the split's PC), or NULL */
};
using Splits = std::vector<Split>;

/* If the PC of snes's KSP is a PCFIELDSPLIT not split by number, give it `splits`. */
PetscErrorCode SetNamedSplits(SNES snes, DM dm, const Splits &splits);

} // namespace fsi
