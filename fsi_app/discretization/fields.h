/* Fields on regions: one PetscFE per unknown, living on the cells of a named physical group
   (or on the whole mesh), so a scene allocates only the unknowns of the blocks it names. */
#pragma once

#include <petscdmplex.h>
#include <string>
#include <vector>

namespace fsi {

/* Add a Lagrange field of `degree` with `nc` components on the cells of group `region`
   ("" for every cell); returns its field number. Call DMCreateDS() after the last one. */
PetscErrorCode AddLagrangeField(DM dm, const std::string &name, const std::string &region, PetscInt nc, PetscInt degree, PetscInt *field);

/* The label "region_<group>" of the closure of group's cells (value 1; PETSc gives a field the
   points of its label's stratum 1), made on the first call. */
PetscErrorCode GetRegionLabel(DM dm, const std::string &region, DMLabel *label);

/* Field `field` = value (a constant vector that must outlive dm; nullptr: zero) on the faces
   of each comma-separated group ("a,b:xz": only components x, z on b); `option` names the
   option in error messages. */
PetscErrorCode AddDirichlet(DM dm, const char *groups, PetscInt field, const char *option, const PetscReal *value = nullptr);

/* The values of a label on every rank (a rank without points of it gets one, since
   DMAddBoundary is collective). */
PetscErrorCode LabelValues(DMLabel label, std::vector<PetscInt> &ids);

/* "a,b:xz" -> {"a", "b:xz"} */
std::vector<std::string> SplitList(const char *s);

} // namespace fsi
