// SPDX-License-Identifier: BSD-2-Clause
/* Fields on regions: one PetscFE per unknown, living on the cells of a named physical group
   (or on the whole mesh), so a scene allocates only the unknowns of the blocks it names. */
#pragma once

#include <petscdmplex.h>
#include <petscvec.h>
#include <string>
#include <vector>

namespace fsi {

/* Add a Lagrange field of `degree` with `nc` components on the cells of group `region`
   ("" for every cell); returns its field number. CreateSection() (conditions.h) lays them out. */
PetscErrorCode AddLagrangeField(DM dm, const std::string &name, const std::string &region, PetscInt nc, PetscInt degree, PetscInt *field);

/* The label "region_<group>" of the closure of the group's points (cells; faces for a field on an interface) (value 1; PETSc gives a field the
   points of its label's stratum 1), made on the first call. */
PetscErrorCode GetRegionLabel(DM dm, const std::string &region, DMLabel *label);

/* The number of the field called `name` in dm (a split's sub-DM numbers its fields anew). */
PetscErrorCode FieldByName(DM dm, const char *name, PetscInt *field);

/* A norm of field `field` of the global vector x. */
PetscErrorCode FieldNorm(DM dm, Vec x, PetscInt field, NormType type, PetscReal *norm);

/* "a,b:xz" -> {"a", "b:xz"} */
std::vector<std::string> SplitList(const char *s);

} // namespace fsi
