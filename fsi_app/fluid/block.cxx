// SPDX-License-Identifier: BSD-2-Clause
#include "block.h"
#include "discretization/conditions.h"
#include "verification/errors.h"
#include <string>
#include "discretization/fields.h"
#include "mesh/mesh.h"

namespace fsi {

/* The manufactured flows' Dirichlet faces: the boundary but the outlet, where the exact
   traction fixes the pressure's constant. */
static PetscErrorCode MMSDirichletFaces(const Scene &sc, DM dm, DMLabel *faces)
{
  DMLabel boundary, outlet;

  PetscFunctionBegin;
  PetscCall(DMGetLabel(dm, "boundary", &boundary));
  PetscCall(DMGetLabel(dm, sc.outlet, &outlet));
  PetscCall(DMCreateLabel(dm, "mms_dirichlet"));
  PetscCall(DMGetLabel(dm, "mms_dirichlet", faces));
  PetscCall(ForEachLabelPoint(boundary, {1}, [&](PetscInt face) -> PetscErrorCode {
    PetscInt v;
    PetscFunctionBegin;
    PetscCall(DMLabelGetValue(outlet, face, &v));
    if (v < 0) PetscCall(DMLabelSetValue(*faces, face, 1));
    PetscFunctionReturn(0);
  }));
  PetscFunctionReturn(0);
}

void FluidBlock::Groups(std::vector<GroupUse> &groups) const
{
  const char *conditions = "fluid's inlet, outlet and no-slip faces";
  groups.push_back({sc.fluidRegion, "-fluid_region", 3, RegionsRole});
  for (const auto &g : SplitList(sc.noslip)) groups.push_back({g.substr(0, g.find(':')), "-fluid_noslip", 2, conditions});
  if (sc.inletPressure != 0 || sc.poiseuille[0] > 0 || sc.inflow) groups.push_back({sc.inlet, "-fluid_inlet", 2, conditions});
  /* the outlet's conditions need it; a stress-free outlet under a pressure or inflow only has its flux reported */
  const bool outletNeeded = sc.poiseuille[0] > 0 || sc.mms;
  if (outletNeeded || sc.inletPressure != 0 || sc.inflow) groups.push_back({sc.outlet, "-fluid_outlet", 2, conditions, !outletNeeded});
}

PetscErrorCode FluidBlock::AddFields(DM dm)
{
  PetscFunctionBegin;
  PetscCall(AddLagrangeField(dm, "velocity", sc.fluidRegion, 3, 2, &velocity));
  PetscCall(AddLagrangeField(dm, "pressure", sc.fluidRegion, 1, 1, &pressure));
  flow.kind = sc.mmsFlow, flow.rho = sc.rhoFluid, flow.mu = sc.muFluid, flow.ramp = sc.mmsRamp, flow.dynamic = sc.Dynamic();
  flow.motion = geometry && !geometry->Coupled() ? &geometry->motion : nullptr;
  PetscFunctionReturn(0);
}

PetscErrorCode FluidBlock::AddConditions(DM dm, Conditions &list)
{
  PetscFunctionBegin;
  if (sc.inflow) PetscCall(AddDirichlet(dm, list, sc.inlet, velocity, "-fluid_inlet", sc.inflowVelocity)); /* first: the no-slip rim wins */
  PetscCall(AddDirichlet(dm, list, sc.noslip, velocity, "-fluid_noslip"));
  if (sc.mms) {
    Condition      c;
    const FlowMMS *m = &flow;
    PetscCall(MMSDirichletFaces(sc, dm, &c.label));
    c.name = "-mms (the manufactured velocity on the boundary but the outlet)", c.field = velocity;
    c.value = [m](const PetscReal x[3], PetscReal t, PetscScalar *v) { FlowMMSVelocityBC(3, t, x, 3, v, (void *)m); };
    list.push_back(c);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode FluidBlock::SetUp(DM dm)
{
  FluidForms &fb = forms;
  DMLabel     region;

  PetscFunctionBegin;
  PetscCall(GetRegionLabel(dm, sc.fluidRegion, &region));
  PetscCall(FieldCellsCreate(dm, region, velocity, fb.velocity));
  PetscCall(FieldCellsCreate(dm, region, pressure, fb.pressure));
  fb.mesh = geometry ? &geometry->forms.cells : nullptr;
  fb.rho = sc.rhoFluid, fb.mu = sc.muFluid, fb.shapeDerivatives = sc.shapeDerivatives;
  PetscCall(CreateP2Rule(5, fb.rule));
  PetscCall(CreateFaceRule(4, fb.faceRule));
  auto addTraction = [&](const char *group, Traction t) -> PetscErrorCode {
    DMLabel       label;
    TractionGroup tg;
    PetscFunctionBegin;
    PetscCall(DMGetLabel(dm, group, &label));
    PetscCall(CellFacesCreate(dm, fb.velocity, label, tg.faces));
    tg.traction = t;
    fb.tractions.push_back(tg);
    PetscFunctionReturn(0);
  };
  for (auto g : {std::make_pair(sc.inlet, &inletFaces), std::make_pair(sc.outlet, &outletFaces), std::make_pair(sc.interface, &interfaceFaces)}) { /* the fluxes a run reports */
    DMLabel label;
    PetscCall(DMGetLabel(dm, g.first, &label));
    if (label) PetscCall(CellFacesCreate(dm, fb.velocity, label, *g.second));
  }
  if (!sc.fluidProbes.empty()) PetscCall(ProbesCreate(PetscObjectComm((PetscObject)dm), fb.pressure, sc.fluidProbes, "-fluid_probes", probes));
  if (sc.mms) {
    const FlowMMS *m = &flow;
    PetscCall(addTraction(sc.outlet, [m](const PetscReal x[3], const PetscReal n[3], PetscReal t, PetscReal tr[3]) { FlowMMSTraction(*m, x, n, t, tr); }));
    fb.force = [m](const PetscReal x[3], PetscReal t, PetscReal f[3]) { FlowMMSForce(*m, x, t, f); };
  } else if (sc.poiseuille[0] > 0) { /* the exact flow's traction sigma n at both ends */
    const Poiseuille p = {sc.poiseuille[0], sc.poiseuille[1], sc.poiseuille[2], sc.muFluid};
    for (const char *g : {sc.inlet, sc.outlet}) PetscCall(addTraction(g, [p](const PetscReal x[3], const PetscReal n[3], PetscReal, PetscReal t[3]) { PoiseuilleTraction(p, x, n, t); }));
  } else if (sc.inletPressure != 0) {
    const PetscReal p = sc.inletPressure, until = sc.pulseEnd;
    const PetscBool steady = (PetscBool)!sc.Dynamic(); /* time is then the load fraction: continuation in p */
    PetscCall(addTraction(sc.inlet, [p, until, steady](const PetscReal *, const PetscReal n[3], PetscReal time, PetscReal t[3]) {
      const PetscReal pt = steady ? p * time : (until == 0 || time <= until + 1e-12 ? p : 0.0);
      for (int d = 0; d < 3; d++) t[d] = -pt * n[d];
    }));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode FluidBlock::InitialState(DM dm, Vec x, PetscBool *set)
{
  Vec          local;
  PetscScalar *a;

  PetscFunctionBegin;
  *set = (PetscBool)(sc.mms && sc.Dynamic()); /* the manufactured flow at t = 0, held since t = -infinity (uniform: nonzero; ramped: zero) */
  if (!*set) PetscFunctionReturn(0);
  PetscCall(DMGetLocalVector(dm, &local));
  PetscCall(VecSet(local, 0.0));
  PetscCall(VecGetArray(local, &a));
  SetNodalValues(forms.velocity, [&](const PetscReal X[3], PetscScalar *u) { FlowMMSVelocityBC(3, 0.0, X, 3, u, (void *)&flow); }, a);
  PetscCall(VecRestoreArray(local, &a));
  PetscCall(DMLocalToGlobal(dm, local, INSERT_VALUES, x));
  PetscCall(DMRestoreLocalVector(dm, &local));
  PetscFunctionReturn(0);
}

void FluidBlock::Output(std::vector<OutputPart> &parts) const
{
  OutputPart p{"fluid", &forms.velocity, {{"velocity", velocity}, {"pressure", pressure}}};
  if (geometry) p.fields.push_back({"displacement", geometry->field}); /* the mesh's: named as the wall's, so Warp By Vector moves both parts */
  parts.push_back(p);
}

std::string FluidBlock::InvertedCause() const
{
  char cause[256];
  if (!forms.inverted) return "";
  if (geometry && geometry->Coupled()) return "a cell of the moved fluid mesh inverted (J <= 0): the wall moved too far in one step for the harmonic extension of its displacement";
  PetscSNPrintf(cause, sizeof(cause), "a cell of the moved fluid mesh inverted (J <= 0): the prescribed interface displacement is too large for its harmonic extension; reduce -geometry_amplitude (%g now)", (double)sc.geometryAmplitude);
  return cause;
}

PetscErrorCode FluidBlock::AfterStep(DM dm, PetscInt, PetscReal t, Vec x)
{
  return probes.cell.empty() ? 0 : ProbesRecordGlobal(dm, forms.pressure, x, t, probes);
}

/* When the pulse's front (half the inlet pressure) passes each probe, and the speed: the least
   squares slope of the distance from the first probe against the arrival time. */
static PetscErrorCode ReportArrivals(const Probes &probes, PetscReal level, RunReport &report)
{
  const std::vector<PetscReal> arrival = ProbesArrival(probes, level);
  PetscReal                    st = 0, ss = 0, stt = 0, sts = 0, m = 0;

  PetscFunctionBegin;
  for (size_t i = 0; i < arrival.size(); i++) {
    const PetscReal *X = &probes.X[3 * i];
    const PetscReal  s = PetscSqrtReal(PetscSqr(X[0] - probes.X[0]) + PetscSqr(X[1] - probes.X[1]) + PetscSqr(X[2] - probes.X[2]));
    if (arrival[i] >= 0) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "probe (%g, %g, %g): the front (p = %g) arrives at t %.6e\n", (double)X[0], (double)X[1], (double)X[2], (double)level, (double)arrival[i]));
    else PetscCall(PetscPrintf(PETSC_COMM_WORLD, "probe (%g, %g, %g): the front (p = %g) has not arrived by t %.6e, the end of the run\n", (double)X[0], (double)X[1], (double)X[2], (double)level, probes.t.empty() ? 0.0 : (double)probes.t.back()));
    report.results.push_back({"arrival_" + std::to_string(i), arrival[i]});
    if (arrival[i] < 0) continue;
    st += arrival[i], ss += s, stt += arrival[i] * arrival[i], sts += arrival[i] * s, m++;
  }
  if (m >= 2 && m * stt - st * st > 0) {
    const PetscReal c = (m * sts - st * ss) / (m * stt - st * st);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "wave speed %.6e cm/s (%g probes)\n", (double)c, (double)m));
    report.results.push_back({"wave_speed", c});
  }
  PetscFunctionReturn(0);
}

PetscErrorCode FluidBlock::Results(DM dm, Vec x, PetscReal t, RunReport &report)
{
  Errors     e, ep;
  Poiseuille p = {sc.poiseuille[0], sc.poiseuille[1], sc.poiseuille[2], sc.muFluid};
  PetscReal  in = 0, out = 0; /* fluxes through inlet and outlet */

  PetscFunctionBegin;
  /* equal to the solver's tolerance without a moving wall: div u is orthogonal to the constants */
  PetscCall(FluidFlux(dm, forms, inletFaces, x, &in));
  PetscCall(FluidFlux(dm, forms, outletFaces, x, &out));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "flux inlet %.6e outlet %.6e\n", (double)in, (double)out));
  report.results.insert(report.results.end(), {{"inlet_flux", in}, {"outlet_flux", out}});
  PetscCall(ComputeErrors(dm, forms.velocity, x, t, ZeroSolution, nullptr, e, forms.mesh)); /* the L2 norms: the error against zero */
  PetscCall(ComputeErrors(dm, forms.pressure, x, t, ZeroSolution, nullptr, ep, forms.mesh));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "L2 norms on the moved fluid: velocity %.6e pressure %.6e\n", (double)e.l2, (double)ep.l2));
  report.results.insert(report.results.end(), {{"velocity_l2_norm", e.l2}, {"pressure_l2_norm", ep.l2}});
  if (sc.mms) {
    PetscCall(ComputeErrors(dm, forms.pressure, x, t, FlowMMSPressure, &flow, e, forms.mesh));
    PetscCall(ReportErrors("pressure", e, report));
    PetscCall(ComputeErrors(dm, forms.velocity, x, t, FlowMMSVelocity, &flow, e, forms.mesh));
    PetscCall(ReportErrors("", e, report));
  } else if (p.R > 0) {
    const PetscReal exact = PETSC_PI * PetscPowReal(p.R, 4) * p.dp / (8 * p.mu * p.L), Q = out;
    PetscCall(ComputeErrors(dm, forms.velocity, x, t, PoiseuilleVelocity, &p, e, forms.mesh));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "flux %.6e exact %.6e relative error %.3e\n", (double)Q, (double)exact, (double)PetscAbsReal(Q / exact - 1)));
    report.results.insert(report.results.end(), {{"flux", Q}, {"flux_relative_error", PetscAbsReal(Q / exact - 1)}});
    PetscCall(ReportErrors("", e, report));
  }
  if (!probes.cell.empty()) report.series.push_back({"pressure", &probes});
  if (!probes.cell.empty() && sc.inletPressure != 0) PetscCall(ReportArrivals(probes, sc.inletPressure / 2, report));
  PetscFunctionReturn(0);
}

} // namespace fsi
