// SPDX-License-Identifier: BSD-2-Clause
#include "block.h"
#include "discretization/ale_map.h"
#include "discretization/fields.h"
#include <petscsf.h>

namespace fsi {

PetscErrorCode CouplingBlock::Wire(const std::vector<Block *> &scene)
{
  PetscFunctionBegin;
  structure = FindBlock<StructureBlock>(scene, "structure");
  fluid     = FindBlock<FluidBlock>(scene, "fluid");
  geometry  = FindBlock<GeometryBlock>(scene, "geometry");
  PetscCheck(structure && fluid && geometry, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-blocks: the coupling ties structure, fluid and geometry: name all four");
  PetscFunctionReturn(0);
}

PetscErrorCode CouplingBlock::Check() const
{
  PetscFunctionBegin;
  PetscCheck(sc.Dynamic(), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-dt 0: the coupled problem is dynamic (u = d_t d_s on the interface); give a time step");
  PetscCheck(structure->opt.region[0], PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-structure_region: name the wall's group (the fluid's cells are not the wall's)");
  for (const auto &g : SplitList(fluid->opt.noslip))
    PetscCheck(g.substr(0, g.find(':')) != geometry->opt.interface, PETSC_COMM_WORLD, PETSC_ERR_ARG_INCOMP, "-fluid_noslip %s: on the interface %s the fluid moves with the wall (the coupling's u = d_t d_s); remove it from -fluid_noslip", fluid->opt.noslip, geometry->opt.interface);
  PetscFunctionReturn(0);
}

PetscErrorCode CouplingBlock::AddFields(DM dm)
{
  PetscFunctionBegin;
  PetscCall(AddLagrangeField(dm, "multiplier", geometry->opt.interface, 3, 2, &field));
  PetscFunctionReturn(0);
}

PetscErrorCode CouplingBlock::AddConditions(DM dm, Conditions &list)
{
  std::map<PetscInt, unsigned> u, d;
  DMLabel                      fixed;

  PetscFunctionBegin;
  PetscCall(ConstrainedComponents(dm, list, fluid->velocity, 3, u));
  PetscCall(ConstrainedComponents(dm, list, structure->field, 3, d));
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
  PetscSection    local, global;
  PetscSF         sf;
  PetscInt        pStart, pEnd, nleaves, bad = -1, gbad;
  const PetscInt *leaves;
  const PetscInt  fields[4] = {field, fluid->velocity, structure->field, geometry->field};

  PetscFunctionBegin;
  PetscCall(DMGetLocalSection(dm, &local));
  PetscCall(DMGetGlobalSection(dm, &global));
  PetscCall(PetscSectionGetChart(local, &pStart, &pEnd));
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(PetscSFGetGraph(sf, nullptr, &nleaves, &leaves, nullptr));
  std::vector<char> ghost(pEnd - pStart, 0);
  for (PetscInt l = 0; l < nleaves; l++) ghost[(leaves ? leaves[l] : l) - pStart] = 1;
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
    if (!ghost[p - pStart] && bad < 0) nodes.push_back(n);
  }
  PetscCallMPI(MPIU_Allreduce(&bad, &gbad, 1, MPIU_INT, MPI_MAX, PetscObjectComm((PetscObject)dm)));
  PetscCheck(gbad < 0, PetscObjectComm((PetscObject)dm), PETSC_ERR_ARG_WRONG, "-geometry_interface %s: the group's faces must lie between cells of -fluid_region %s and of -structure_region %s with a node of each at every interface node (a conforming interface); mesh point %" PetscInt_FMT " lacks one", geometry->opt.interface, fluid->opt.region, structure->opt.region, gbad);
  DMLabel wall;
  PetscCall(DMGetLabel(dm, geometry->opt.interface, &wall));
  PetscCall(CellFacesCreate(dm, fluid->forms.velocity, wall, wallFaces));
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

/* The moved fluid region's volume int J dX (exact: J is a polynomial of degree 3) for the
   local state x. */
PetscErrorCode CouplingBlock::FluidVolume(DM dm, const PetscScalar *x, PetscReal *volume)
{
  const FieldCells &cells = geometry->forms.cells;
  const P2Rule     &rule  = fluid->forms.rule;
  PetscReal         sum   = 0;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < cells.Size(); k++) {
    PetscReal de[30];
    Gather(cells, k, x, de);
    for (PetscInt q = 0; q < rule.nq; q++) {
      MovedPoint m;
      sum += rule.w[q] * cells.geom[k].detE * MovePoint(cells.geom[k], de, &rule.lambda[4 * q], &rule.N[10 * q], m);
    }
  }
  PetscCallMPI(MPIU_Allreduce(&sum, volume, 1, MPIU_REAL, MPIU_SUM, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

/* int_Gamma |d|^2 dA in the reference configuration for the local state x: d_f on the fluid's
   interface faces, which equals d_s there. */
PetscErrorCode CouplingBlock::InterfaceDisplacementSquared(DM dm, const PetscScalar *x, PetscReal *d2)
{
  PetscFunctionBegin;
  PetscCall(FluidFaceNormSquared(dm, fluid->forms, geometry->forms.cells, wallFaces, x, d2));
  PetscFunctionReturn(0);
}

PetscErrorCode CouplingBlock::AfterStep(DM dm, PetscInt, PetscReal t, Vec x)
{
  Balance b;

  PetscFunctionBegin;
  if (balance.empty()) /* the states before the first step recorded (the start, or a checkpoint's state) */
    for (size_t j = 1; j < history->past.size(); j++) {
      const PetscScalar *y;
      PetscReal          v;
      PetscCall(VecGetArrayRead(history->past[j], &y));
      PetscCall(FluidVolume(dm, y, &v));
      if (j == 1) PetscCall(InterfaceDisplacementSquared(dm, y, &d2Before));
      PetscCall(VecRestoreArrayRead(history->past[j], &y));
      before.push_back(v);
    }
  b.t = t;
  PetscCall(FluidFlux(dm, fluid->forms, fluid->inletFaces, x, &b.in));
  PetscCall(FluidFlux(dm, fluid->forms, fluid->outletFaces, x, &b.out));
  PetscCall(FluidFlux(dm, fluid->forms, wallFaces, x, &b.wall));
  {
    const PetscScalar *y; /* past[0] is x with its essential values */
    PetscCall(VecGetArrayRead(history->past[0], &y));
    PetscCall(FluidVolume(dm, y, &b.volume));
    PetscCall(InterfaceDisplacementSquared(dm, y, &b.d2));
    PetscCall(VecRestoreArrayRead(history->past[0], &y));
  }
  b.in = -b.in; /* into the fluid */
  balance.push_back(b);
  PetscFunctionReturn(0);
}

PetscErrorCode CouplingBlock::Results(DM dm, Vec, PetscReal, RunReport &report)
{
  PetscReal velocity, geometric, mass = 0, rate = 0, inMax = 0, wallMax = 0;

  PetscFunctionBegin;
  PetscCall(Continuity(dm, &velocity, &geometric));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "interface continuity: max |u - d_t d_s| %.3e max |d_f - d_s| %.3e\n", (double)velocity, (double)geometric));
  report.results.insert(report.results.end(), {{"interface_velocity_jump", velocity}, {"interface_displacement_jump", geometric}});
  /* volume balance: (1) inflow - outflow - int_G u.n = 0 (div u orthogonal to the constants);
     (2) int_G u.n = dV/dt, V differenced by the time scheme's formula */
  for (size_t k = 0; k < balance.size(); k++) {
    const Balance &b = balance[k];
    PetscReal      dV = history->first[0] * b.volume;
    for (PetscInt j = 1; j < 3 && history->first[j] != 0; j++) dV += history->first[j] * ((PetscInt)k - j >= 0 ? balance[k - j].volume : before[j - k - 1]);
    dV /= history->dt;
    mass    = PetscMax(mass, PetscAbsReal(b.in - b.out - b.wall));
    rate    = PetscMax(rate, PetscAbsReal(b.wall - dV));
    inMax   = PetscMax(inMax, PetscAbsReal(b.in));
    wallMax = PetscMax(wallMax, PetscAbsReal(b.wall));
    PetscCall(PetscInfo(nullptr, "t %g inflow %g outflow %g interface %g dV/dt %g volume %g\n", (double)b.t, (double)b.in, (double)b.out, (double)b.wall, (double)dV, (double)b.volume));
  }
  if (balance.empty()) PetscFunctionReturn(0);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "volume balance over %zu steps: max |inflow - outflow - interface flux| %.3e (max inflow %.3e); max |interface flux - dV/dt| %.3e (max interface flux %.3e)\n", balance.size(), (double)mass, (double)inMax, (double)rate, (double)wallMax));
  report.results.insert(report.results.end(), {{"volume_balance", mass}, {"max_inflow", inMax}, {"volume_rate_mismatch", rate}, {"max_interface_flux", wallMax}});
  /* ||d||_{L2(Gamma x (t0, T))} by the trapezoidal rule (second order: it does not cap BDF2's) */
  PetscReal integral = 0, previous = d2Before;
  for (const Balance &b : balance) integral += history->dt * (previous + b.d2) / 2, previous = b.d2;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "interface displacement: L2 norm in space and time %.6e cm^2 s^1/2\n", (double)PetscSqrtReal(integral)));
  report.results.push_back({"interface_displacement_l2", PetscSqrtReal(integral)});
  PetscFunctionReturn(0);
}

} // namespace fsi
