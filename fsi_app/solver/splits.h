/* PCFIELDSPLIT by name. A scene of several blocks splits its system into the blocks' named
   splits (structure, geometry, fluid — the order of the block lower triangle: the geometry
   follows the structure, the fluid follows both), so options files address them by name,
   -fieldsplit_structure_pc_type gdsw, and adding a field never retargets an options file. Each
   split's KSP gets the sub-DM of its fields: a nested PCFIELDSPLIT splits by field name
   (-fieldsplit_fluid_fieldsplit_velocity_...). Options that split by number
   (-pc_fieldsplit_0_fields) keep PETSc's meaning. */
#pragma once

#include <petscksp.h>
#include <string>
#include <vector>

namespace fsi {

using Splits = std::vector<std::pair<std::string, std::vector<PetscInt>>>;

/* If pc is a PCFIELDSPLIT not split by number, give it `splits` (names and dm's fields). */
PetscErrorCode SetNamedSplits(PC pc, DM dm, const Splits &splits);

} // namespace fsi
