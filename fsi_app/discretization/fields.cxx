// SPDX-License-Identifier: BSD-2-Clause
#include "fields.h"
#include "mesh/mesh.h"
#include <petscfe.h>

namespace fsi {

PetscErrorCode GetRegionLabel(DM dm, const std::string &region, DMLabel *label)
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
  if (!region.empty()) PetscCall(GetRegionLabel(dm, region, &label));
  PetscCall(DMGetNumFields(dm, field));
  PetscCall(DMSetField(dm, *field, label, (PetscObject)fe));
  PetscCall(PetscFEDestroy(&fe));
  PetscFunctionReturn(0);
}

std::vector<std::string> SplitList(const char *s)
{
  std::vector<std::string> out;
  for (std::string r = s; !r.empty();) {
    const size_t k = r.find(',');
    out.push_back(r.substr(0, k));
    r = k == std::string::npos ? "" : r.substr(k + 1);
  }
  return out;
}

PetscErrorCode FieldByName(DM dm, const char *name, PetscInt *field)
{
  PetscInt nf;

  PetscFunctionBegin;
  PetscCall(DMGetNumFields(dm, &nf));
  for (*field = 0; *field < nf; (*field)++) {
    PetscObject obj;
    const char *fname;
    PetscCall(DMGetField(dm, *field, nullptr, &obj));
    PetscCall(PetscObjectGetName(obj, &fname));
    if (!strcmp(fname, name)) PetscFunctionReturn(0);
  }
  SETERRQ(PetscObjectComm((PetscObject)dm), PETSC_ERR_ARG_WRONG, "the DM has no field called %s", name);
}

PetscErrorCode FieldNorm(DM dm, Vec x, PetscInt field, NormType type, PetscReal *norm)
{
  IS      *is;
  PetscInt nf;
  Vec      part;

  PetscFunctionBegin;
  PetscCall(DMCreateFieldIS(dm, &nf, nullptr, &is));
  PetscCall(VecGetSubVector(x, is[field], &part));
  PetscCall(VecNorm(part, type, norm));
  PetscCall(VecRestoreSubVector(x, is[field], &part));
  for (PetscInt f = 0; f < nf; f++) PetscCall(ISDestroy(&is[f]));
  PetscCall(PetscFree(is));
  PetscFunctionReturn(0);
}

} // namespace fsi
