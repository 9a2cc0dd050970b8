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

/* u = the constant vector ctx (nullptr: zero) */
static PetscErrorCode Constant(PetscInt, PetscReal, const PetscReal[], PetscInt nc, PetscScalar *u, void *ctx)
{
  for (PetscInt c = 0; c < nc; c++) u[c] = ctx ? ((const PetscReal *)ctx)[c] : 0.0;
  return 0;
}

PetscErrorCode LabelValues(DMLabel label, std::vector<PetscInt> &ids)
{
  IS              values;
  PetscInt        nv, any, gany;
  const PetscInt *v;

  PetscFunctionBegin;
  PetscCall(DMLabelGetValueIS(label, &values));
  PetscCall(ISGetLocalSize(values, &nv));
  PetscCall(ISGetIndices(values, &v));
  ids.assign(v, v + nv);
  PetscCall(ISRestoreIndices(values, &v));
  PetscCall(ISDestroy(&values));
  any = nv;
  PetscCallMPI(MPIU_Allreduce(&any, &gany, 1, MPIU_INT, MPI_MAX, PetscObjectComm((PetscObject)label)));
  if (ids.empty() && gany) ids.push_back(0); /* the label's values live on other ranks: DMAddBoundary is collective */
  PetscFunctionReturn(0);
}

PetscErrorCode AddDirichlet(DM dm, const char *groups, PetscInt field, const char *option, const PetscReal *value)
{
  PetscFunctionBegin;
  for (const auto &spec : SplitList(groups)) {
    const std::string     g = spec.substr(0, spec.find(':'));
    std::vector<PetscInt> comps; /* empty: all */
    if (spec.find(':') != std::string::npos)
      for (char c : spec.substr(spec.find(':') + 1)) {
        PetscCheck(c == 'x' || c == 'y' || c == 'z', PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s %s: components are x, y, z", option, spec.c_str());
        comps.push_back(c - 'x');
      }
    DMLabel               group;
    std::vector<PetscInt> ids;
    PetscCall(DMGetLabel(dm, g.c_str(), &group));
    PetscCall(LabelValues(group, ids));
    PetscCall(DMAddBoundary(dm, DM_BC_ESSENTIAL, spec.c_str(), group, (PetscInt)ids.size(), ids.data(), field, (PetscInt)comps.size(), comps.empty() ? nullptr : comps.data(), (void (*)(void))Constant, nullptr, (void *)value, nullptr));
  }
  PetscFunctionReturn(0);
}

} // namespace fsi
