// SPDX-License-Identifier: BSD-2-Clause
#include "block.h"
#include "discretization/fields.h"
#include <petscsf.h>

namespace fsi {

PetscErrorCode CouplingBlock::Wire(const std::vector<Block *> &scene)
{
  PetscFunctionBegin;
  structure = FindBlock(scene, "structure");
  fluid     = FindBlock(scene, "fluid");
  geometry  = FindBlock(scene, "geometry");
  PetscCheck(structure && fluid && geometry, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-blocks: the coupling ties structure, fluid and geometry: name all four");
  PetscFunctionReturn(0);
}

PetscErrorCode CouplingBlock::Check() const
{
  PetscFunctionBegin;
  PetscCheck(sc.Dynamic(), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-dt 0: the coupled problem is dynamic (u = d_t d_s on the interface); give a time step");
  const std::string noslip = fluid->Group("noslip"), interface = geometry->Group("interface");
  PetscCheck(!structure->Region().empty(), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-structure_region: name the wall's group (the fluid's cells are not the wall's)");
  PetscCheck(!fluid->Region().empty(), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-fluid_region: name the fluid's group (the wall's cells are not the fluid's)");
  for (const auto &g : SplitList(noslip.c_str()))
    PetscCheck(g.substr(0, g.find(':')) != interface, PETSC_COMM_WORLD, PETSC_ERR_ARG_INCOMP, "-fluid_noslip %s: on the interface %s the fluid moves with the wall (the coupling's u = d_t d_s); remove it from -fluid_noslip", noslip.c_str(), interface.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode CouplingBlock::AddFields(DM dm)
{
  PetscFunctionBegin;
  PetscCall(AddLagrangeField(dm, "multiplier", geometry->Group("interface"), 3, 2, &field));
  PetscFunctionReturn(0);
}

PetscErrorCode CouplingBlock::AddConditions(DM dm, Conditions &list)
{
  std::map<PetscInt, unsigned> u, d;
  DMLabel                      fixed;

  PetscFunctionBegin;
  PetscCall(ConstrainedComponents(dm, list, fluid->Field("velocity"), 3, u));
  PetscCall(ConstrainedComponents(dm, list, structure->Field("displacement"), 3, d));
  PetscCall(DMCreateLabel(dm, "multiplier_fixed"));
  PetscCall(DMGetLabel(dm, "multiplier_fixed", &fixed));
  for (const auto &pu : u) { /* value: the components fixed in both */
    auto pd = d.find(pu.first);
    if (pd != d.end() && (pu.second & pd->second)) PetscCall(DMLabelSetValue(fixed, pu.first, (PetscInt)(pu.second & pd->second)));
  }
  for (unsigned m = 1; m < 8; m++) { /* collective: every rank adds the seven conditions */
    Condition c;
    c.name = "lambda where u and d_s are both prescribed", c.field = field, c.label = fixed, c.values = {(PetscInt)m};
    for (PetscInt k = 0; k < 3; k++)
      if (m & (1u << k)) c.comps.push_back(k);
    if (m == 7) c.comps.clear();
    list.push_back(c);
  }
  PetscFunctionReturn(0);
}

/* Global indices of the nc components of field f at point p: -1 where constrained. A point's
   global dofs are its fields' unconstrained dofs, field after field (DMPlex's layout). */
static PetscErrorCode PointIndices(PetscSection local, PetscSection global, PetscInt p, PetscInt f, PetscInt idx[3])
{
  PetscInt        goff, dof, cdof;
  const PetscInt *cidx;

  PetscFunctionBegin;
  PetscCall(PetscSectionGetOffset(global, p, &goff));
  if (goff < 0) goff = -(goff + 1); /* a ghost: the owner's offset */
  for (PetscInt g = 0; g < f; g++) {
    PetscCall(PetscSectionGetFieldDof(local, p, g, &dof));
    PetscCall(PetscSectionGetFieldConstraintDof(local, p, g, &cdof));
    goff += dof - cdof;
  }
  PetscCall(PetscSectionGetFieldDof(local, p, f, &dof));
  PetscCall(PetscSectionGetFieldConstraintDof(local, p, f, &cdof));
  PetscCall(PetscSectionGetFieldConstraintIndices(local, p, f, &cidx));
  for (PetscInt c = 0, k = 0; c < dof; c++) {
    if (k < cdof && cidx[k] == c) idx[c] = -1, k++;
    else idx[c] = goff++;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CouplingBlock::SetUp(DM dm)
{
  PetscSection      local, global;
  PetscInt          pStart, pEnd, bad = -1, gbad;
  std::vector<char> owned;
  const PetscInt    fields[4] = {field, fluid->Field("velocity"), structure->Field("displacement"), geometry->Field("geometry")};

  PetscFunctionBegin;
  PetscCall(DMGetLocalSection(dm, &local));
  PetscCall(DMGetGlobalSection(dm, &global));
  PetscCall(PetscSectionGetChart(local, &pStart, &pEnd));
  PetscCall(OwnedPoints(dm, owned));
  nodes.clear();
  for (PetscInt p = pStart; p < pEnd; p++) {
    PetscInt dof;
    PetscCall(PetscSectionGetFieldDof(local, p, field, &dof));
    if (!dof) continue;
    Node n;
    for (int k = 0; k < 4; k++) {
      PetscCall(PetscSectionGetFieldDof(local, p, fields[k], &dof));
      if (dof != 3) bad = p; /* the interface is not where fluid and wall cells meet */
      PetscCall(PetscSectionGetFieldOffset(local, p, fields[k], &n.local[k]));
      if (dof == 3) PetscCall(PointIndices(local, global, p, fields[k], n.global[k]));
    }
    if (owned[p] && bad < 0) nodes.push_back(n);
  }
  PetscCallMPI(MPIU_Allreduce(&bad, &gbad, 1, MPIU_INT, MPI_MAX, PetscObjectComm((PetscObject)dm)));
  PetscCheck(gbad < 0, PetscObjectComm((PetscObject)dm), PETSC_ERR_ARG_WRONG, "-geometry_interface %s: the group's faces must lie between cells of -fluid_region %s and of -structure_region %s with a node of each at every interface node (a conforming interface); mesh point %" PetscInt_FMT " lacks one", geometry->Group("interface").c_str(),
             fluid->Region().c_str(), structure->Region().c_str(), gbad);
  PetscFunctionReturn(0);
}

/* d_t d_s at a node: the structure's first difference of the states x (now) and the past ones. */
static void WallVelocity(const TimeHistory &h, const PetscScalar *x, const std::vector<const PetscScalar *> &past, PetscInt off, PetscReal v[3])
{
  for (int c = 0; c < 3; c++) {
    v[c] = h.first[0] * PetscRealPart(x[off + c]);
    for (size_t j = 0; j < past.size() && h.first[j + 1] != 0; j++) v[c] += h.first[j + 1] * PetscRealPart(past[j][off + c]);
    v[c] /= h.dt;
  }
}

PetscErrorCode CouplingBlock::Residual(const PetscScalar *x, PetscScalar *f)
{
  std::vector<const PetscScalar *> past;

  PetscFunctionBegin;
  PetscCall(TimeHistoryGetPast(history, past));
  for (const Node &n : nodes) {
    const PetscInt l = n.local[LAMBDA], u = n.local[U], ds = n.local[DS], df = n.local[DF];
    PetscReal      v[3];
    WallVelocity(*history, x, past, ds, v);
    for (int c = 0; c < 3; c++) {
      f[u + c] += x[l + c];
      f[ds + c] -= x[l + c];
      f[l + c] += x[u + c] - v[c];
      f[df + c] += x[df + c] - x[ds + c];
    }
  }
  PetscCall(TimeHistoryRestorePast(history, past));
  PetscFunctionReturn(0);
}

void CouplingBlock::Couplings(Sparsity &s) const
{
  for (const Node &n : nodes)
    for (int c = 0; c < 3; c++) {
      const PetscInt l = n.global[LAMBDA][c], u = n.global[U][c], ds = n.global[DS][c], df = n.global[DF][c];
      const PetscInt momentum[2] = {u, ds}, geometry[2] = {df, ds};
      s.Couple(2, momentum, 1, &l); /* lambda in the fluid's and the wall's momentum rows */
      s.Couple(1, &l, 2, momentum); /* u = d_t d_s on the interface */
      s.Couple(1, &df, 2, geometry); /* d_f = d_s on the interface */
    }
}

PetscErrorCode CouplingBlock::Jacobian(const PetscScalar *, Mat P)
{
  const PetscScalar one = 1, minus = -1, rate = -history->first[0] / history->dt;

  PetscFunctionBegin;
  for (const Node &n : nodes)
    for (int c = 0; c < 3; c++) { /* negative indices: constrained dofs, skipped */
      const PetscInt l = n.global[LAMBDA][c], u = n.global[U][c], ds = n.global[DS][c], df = n.global[DF][c];
      PetscCall(MatSetValues(P, 1, &u, 1, &l, &one, ADD_VALUES));
      PetscCall(MatSetValues(P, 1, &ds, 1, &l, &minus, ADD_VALUES));
      PetscCall(MatSetValues(P, 1, &l, 1, &u, &one, ADD_VALUES));
      PetscCall(MatSetValues(P, 1, &l, 1, &ds, &rate, ADD_VALUES));
      PetscCall(MatSetValues(P, 1, &df, 1, &df, &one, ADD_VALUES));
      PetscCall(MatSetValues(P, 1, &df, 1, &ds, &minus, ADD_VALUES));
    }
  PetscFunctionReturn(0);
}

/* The largest |u - d_t d_s| and |d_f - d_s| over the interface nodes for the state just
   pushed into the history (its past[0]). */
PetscErrorCode CouplingBlock::Continuity(DM dm, PetscReal *velocity, PetscReal *geometric)
{
  std::vector<const PetscScalar *> past;
  PetscReal                        m[2] = {0, 0};

  PetscFunctionBegin;
  PetscCall(TimeHistoryGetPast(history, past));
  const PetscScalar                     *x = past[0];
  const std::vector<const PetscScalar *> before(past.begin() + 1, past.end());
  for (const Node &n : nodes) {
    PetscReal v[3];
    WallVelocity(*history, x, before, n.local[DS], v);
    for (int c = 0; c < 3; c++) {
      m[0] = PetscMax(m[0], PetscAbsReal(PetscRealPart(x[n.local[U] + c]) - v[c]));
      m[1] = PetscMax(m[1], PetscAbsReal(PetscRealPart(x[n.local[DF] + c] - x[n.local[DS] + c])));
    }
  }
  PetscCall(TimeHistoryRestorePast(history, past));
  PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, m, 2, MPIU_REAL, MPIU_MAX, PetscObjectComm((PetscObject)dm)));
  *velocity = m[0], *geometric = m[1];
  PetscFunctionReturn(0);
}

PetscErrorCode CouplingBlock::Results(DM dm, Vec, PetscReal, RunReport &report)
{
  PetscReal velocity, geometric;

  PetscFunctionBegin;
  PetscCall(Continuity(dm, &velocity, &geometric));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "interface continuity: max |u - d_t d_s| %.3e max |d_f - d_s| %.3e\n", (double)velocity, (double)geometric));
  report.results.insert(report.results.end(), {{"interface_velocity_jump", velocity}, {"interface_displacement_jump", geometric}});
  PetscFunctionReturn(0);
}

} // namespace fsi
