#include "fields.h"
#include "mesh/mesh.h"
#include <petscfe.h>

namespace fsi {

/* PETSc gives a field the points of stratum 1 of its label: the closure of the region's cells. */
static PetscErrorCode RegionLabel(DM dm, const std::string &region, DMLabel *label)
{
  const std::string name = "region_" + region;
  PetscBool         has;
  DMLabel           group;

  PetscFunctionBegin;
  PetscCall(DMHasLabel(dm, name.c_str(), &has));
  if (!has) {
    PetscCall(DMGetLabel(dm, region.c_str(), &group));
    PetscCheck(group, PetscObjectComm((PetscObject)dm), PETSC_ERR_ARG_WRONG, "the mesh has no group '%s' to put a field on", region.c_str());
    PetscCall(DMCreateLabel(dm, name.c_str()));
    PetscCall(DMGetLabel(dm, name.c_str(), label));
    PetscCall(ForEachLabelPoint(group, {}, [&](PetscInt p) { return DMLabelSetValue(*label, p, 1); }));
    PetscCall(DMPlexLabelComplete(dm, *label));
  }
  PetscCall(DMGetLabel(dm, name.c_str(), label));
  PetscFunctionReturn(0);
}

PetscErrorCode AddLagrangeField(DM dm, const std::string &name, const std::string &region, PetscInt nc, PetscInt degree, PetscInt *field)
{
  PetscInt  dim;
  PetscFE   fe;
  DMLabel   label = nullptr;
  PetscBool simplex;

  PetscFunctionBegin;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMPlexIsSimplex(dm, &simplex));
  PetscCall(PetscFECreateLagrange(PetscObjectComm((PetscObject)dm), dim, nc, simplex, degree, PETSC_DETERMINE, &fe));
  PetscCall(PetscObjectSetName((PetscObject)fe, name.c_str()));
  if (!region.empty()) PetscCall(RegionLabel(dm, region, &label));
  PetscCall(DMGetNumFields(dm, field));
  PetscCall(DMSetField(dm, *field, label, (PetscObject)fe));
  PetscCall(PetscFEDestroy(&fe));
  PetscFunctionReturn(0);
}

} // namespace fsi
