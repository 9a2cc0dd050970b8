// SPDX-License-Identifier: BSD-2-Clause
#include "conditions.h"
#include <algorithm>
#include <iterator>
#include "discretization/fields.h"
#include "discretization/nodes.h"
#include "mesh/mesh.h"
#include <algorithm>
#include <petscfe.h>

namespace fsi {

/* u = the constant vector ctx (nullptr: zero) */
static NodalValue ConstantValue(const PetscReal *value)
{
  if (!value) return NodalValue();
  return [value](const PetscReal *, PetscReal, PetscScalar *v) {
    for (int c = 0; c < 3; c++) v[c] = value[c];
  };
}

PetscErrorCode AddDirichlet(DM dm, Conditions &list, const char *groups, PetscInt field, const char *option, const PetscReal *value)
{
  PetscFunctionBegin;
  for (const auto &spec : SplitList(groups)) {
    Condition c;
    const std::string g = spec.substr(0, spec.find(':'));
    if (spec.find(':') != std::string::npos)
      for (char x : spec.substr(spec.find(':') + 1)) {
        PetscCheck(x == 'x' || x == 'y' || x == 'z', PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s %s: components are x, y, z", option, spec.c_str());
        c.comps.push_back(x - 'x');
      }
    PetscCall(DMGetLabel(dm, g.c_str(), &c.label));
    PetscCheck(c.label, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s %s: the mesh has no group '%s'", option, groups, g.c_str());
    c.name  = std::string(option) + " " + spec;
    c.field = field, c.value = ConstantValue(value);
    list.push_back(c);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ConditionPoints(DM dm, const Condition &c, std::vector<PetscInt> &points)
{
  DMLabel closure;

  PetscFunctionBegin;
  points.clear();
  PetscCall(DMLabelCreate(PETSC_COMM_SELF, "condition", &closure));
  PetscCall(ForEachLabelPoint(c.label, c.values, [&](PetscInt p) { return DMLabelSetValue(closure, p, 1); }));
  PetscCall(DMPlexLabelComplete(dm, closure)); /* also across ranks: a ghost's owner learns of it */
  PetscCall(ForEachLabelPoint(closure, {1}, [&](PetscInt p) -> PetscErrorCode {
    points.push_back(p);
    return 0;
  }));
  PetscCall(DMLabelDestroy(&closure));
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (c.except) {
    Condition             other;
    std::vector<PetscInt> excluded, kept;
    other.label = c.except;
    PetscCall(ConditionPoints(dm, other, excluded));
    std::set_difference(points.begin(), points.end(), excluded.begin(), excluded.end(), std::back_inserter(kept));
    points.swap(kept);
  }
  PetscFunctionReturn(0);
}

/* The constrained nodes, kept on the DM: per condition, the local offsets, dofs and positions
   of its nodes (label closures and node positions cost more than a residual). */
struct ConstrainedNodes {
  struct Nodes {
    const Condition       *c;
    std::vector<PetscInt>  offset, dof;
    std::vector<PetscReal> x; /* 3 per node */
  };
  Conditions         list;
  std::vector<Nodes> nodes;
};

static PetscErrorCode DestroyConstrainedNodes(void *ctx)
{
  delete (ConstrainedNodes *)ctx;
  return 0;
}

/* Add the components condition c fixes, on its points, to mask (nc components). */
static void AddComponents(const Condition &c, PetscInt nc, const std::vector<PetscInt> &points, std::map<PetscInt, unsigned> &mask)
{
  unsigned m = c.comps.empty() ? (1u << nc) - 1 : 0;
  for (PetscInt k : c.comps) m |= 1u << k;
  for (PetscInt p : points) mask[p] |= m;
}

PetscErrorCode ConstrainedComponents(DM dm, const Conditions &list, PetscInt field, PetscInt nc, std::map<PetscInt, unsigned> &mask)
{
  PetscFunctionBegin;
  mask.clear();
  for (const Condition &c : list) {
    std::vector<PetscInt> points;
    if (c.field != field) continue;
    PetscCall(ConditionPoints(dm, c, points));
    AddComponents(c, nc, points, mask);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CreateSection(DM dm, const Conditions &list)
{
  PetscInt                        nf, dim, pStart, pEnd;
  std::vector<DMLabel>            labels;
  std::vector<PetscInt>           nc, numDof;
  std::map<std::pair<PetscInt, unsigned>, std::vector<PetscInt>> groups; /* (field, components) -> points */

  PetscFunctionBegin;
  PetscCall(DMGetNumFields(dm, &nf));
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  labels.resize(nf), nc.resize(nf), numDof.assign(nf * (dim + 1), 0);
  for (PetscInt f = 0; f < nf; f++) {
    PetscObject disc;
    PetscSpace  space;
    PetscInt    degree;
    PetscCall(DMGetField(dm, f, &labels[f], &disc));
    PetscCall(PetscFEGetNumComponents((PetscFE)disc, &nc[f]));
    PetscCall(PetscFEGetBasisSpace((PetscFE)disc, &space));
    PetscCall(PetscSpaceGetDegree(space, &degree, nullptr));
    PetscCheck(degree >= 0 && degree <= 2, PetscObjectComm((PetscObject)dm), PETSC_ERR_SUP, "field %" PetscInt_FMT ": Lagrange degree %" PetscInt_FMT " (the element loops are P1 and P2; degree 0: scalars on a cell)", f, degree);
    numDof[f * (dim + 1) + 0]   = degree > 0 ? nc[f] : 0;  /* vertices */
    numDof[f * (dim + 1) + 1]   = degree == 2 ? nc[f] : 0; /* edges */
    numDof[f * (dim + 1) + dim] = degree == 0 ? nc[f] : 0; /* cells: the unknowns of a 0D model */
  }
  std::vector<std::vector<PetscInt>>        points(list.size()); /* each condition's points, found once */
  std::vector<std::map<PetscInt, unsigned>> mask(nf);
  for (size_t k = 0; k < list.size(); k++) {
    const Condition &c = list[k];
    PetscCheck(c.field >= 0 && c.field < nf, PetscObjectComm((PetscObject)dm), PETSC_ERR_PLIB, "%s: no field %" PetscInt_FMT, c.name.c_str(), c.field);
    PetscCall(ConditionPoints(dm, c, points[k]));
    AddComponents(c, nc[c.field], points[k], mask[c.field]);
  }
  for (PetscInt f = 0; f < nf; f++)
    for (const auto &pm : mask[f]) groups[{f, pm.second}].push_back(pm.first);
  std::vector<PetscInt> bcField;
  std::vector<IS>       bcComps, bcPoints;
  for (const auto &g : groups) { /* one constraint per field and set of components, none twice */
    std::vector<PetscInt> comps;
    for (PetscInt k = 0; k < nc[g.first.first] && g.first.second != (1u << nc[g.first.first]) - 1; k++)
      if (g.first.second & (1u << k)) comps.push_back(k);
    IS cis = nullptr, pis;
    if (!comps.empty()) PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)comps.size(), comps.data(), PETSC_COPY_VALUES, &cis));
    PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)g.second.size(), g.second.data(), PETSC_COPY_VALUES, &pis));
    bcField.push_back(g.first.first), bcComps.push_back(cis), bcPoints.push_back(pis);
  }
  PetscSection section;
  PetscCall(DMPlexCreateSection(dm, labels.data(), nc.data(), numDof.data(), (PetscInt)bcField.size(), bcField.data(), bcComps.data(), bcPoints.data(), nullptr, &section));
  for (PetscInt f = 0; f < nf; f++) {
    PetscObject disc;
    const char *name;
    PetscCall(DMGetField(dm, f, nullptr, &disc));
    PetscCall(PetscObjectGetName(disc, &name));
    PetscCall(PetscSectionSetFieldName(section, f, name));
  }
  PetscCall(DMSetLocalSection(dm, section));
  PetscCall(PetscSectionDestroy(&section));
  for (IS &is : bcComps) PetscCall(ISDestroy(&is));
  for (IS &is : bcPoints) PetscCall(ISDestroy(&is));

  /* the nodes of every condition, for InsertEssentialValues */
  auto *cn = new ConstrainedNodes;
  cn->list = list;
  PetscCall(DMGetLocalSection(dm, &section));
  for (size_t k = 0; k < cn->list.size(); k++) {
    const Condition        &c = cn->list[k];
    ConstrainedNodes::Nodes n;
    n.c = &c;
    for (PetscInt p : points[k]) {
      PetscInt  dof, off;
      PetscReal x[3];
      PetscCall(PetscSectionGetFieldDof(section, p, c.field, &dof));
      if (!dof) continue;
      PetscCall(PetscSectionGetFieldOffset(section, p, c.field, &off));
      PetscCall(NodePosition(dm, p, x));
      n.offset.push_back(off), n.dof.push_back(dof), n.x.insert(n.x.end(), x, x + 3);
    }
    cn->nodes.push_back(n);
  }
  PetscContainer container;
  PetscCall(PetscContainerCreate(PetscObjectComm((PetscObject)dm), &container));
  PetscCall(PetscContainerSetPointer(container, cn));
  PetscCall(PetscContainerSetUserDestroy(container, DestroyConstrainedNodes));
  PetscCall(PetscObjectCompose((PetscObject)dm, "fsi_constrained_nodes", (PetscObject)container));
  PetscCall(PetscContainerDestroy(&container));
  PetscFunctionReturn(0);
}

PetscErrorCode InsertEssentialValues(DM dm, PetscReal t, Vec local)
{
  PetscContainer    container;
  ConstrainedNodes *cn;
  PetscScalar      *u;

  PetscFunctionBegin;
  PetscCall(PetscObjectQuery((PetscObject)dm, "fsi_constrained_nodes", (PetscObject *)&container));
  PetscCheck(container, PetscObjectComm((PetscObject)dm), PETSC_ERR_ARG_WRONGSTATE, "the DM's section was not made by CreateSection()");
  PetscCall(PetscContainerGetPointer(container, (void **)&cn));
  PetscCall(VecGetArray(local, &u));
  for (const auto &n : cn->nodes)
    for (size_t k = 0; k < n.offset.size(); k++) {
      PetscScalar val[3] = {0, 0, 0};
      if (n.c->value) n.c->value(&n.x[3 * k], t, val);
      if (n.c->comps.empty())
        for (PetscInt i = 0; i < n.dof[k]; i++) u[n.offset[k] + i] = val[i];
      else
        for (PetscInt i : n.c->comps) u[n.offset[k] + i] = val[i];
    }
  PetscCall(VecRestoreArray(local, &u));
  PetscFunctionReturn(0);
}

} // namespace fsi
