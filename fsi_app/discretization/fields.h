/* Fields on regions: one PetscFE per unknown, living on the cells of a named physical group
   (or on the whole mesh), so a scene allocates only the unknowns of the blocks it names. */
#pragma once

#include <petscdmplex.h>
#include <string>

namespace fsi {

/* Add a Lagrange field of `degree` with `nc` components on the cells of group `region`
   ("" for every cell); returns its field number. Call DMCreateDS() after the last one. */
PetscErrorCode AddLagrangeField(DM dm, const std::string &name, const std::string &region, PetscInt nc, PetscInt degree, PetscInt *field);

} // namespace fsi
