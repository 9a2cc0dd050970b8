// SPDX-License-Identifier: BSD-2-Clause
#include "block.h"
#include "discretization/conditions.h"
#include "discretization/fields.h"
#include "mesh/mesh.h"
#include "base/options.h"
#include "verification/errors.h"
#include <string>

namespace fsi {

const char *const PulseShapeNames[] = {"step", "cosine", "PulseShape", "PULSE_", nullptr};

/* The manufactured flows' Dirichlet faces: the boundary but the outlet, where the exact
   traction fixes the pressure's constant. */
static PetscErrorCode MMSDirichletFaces(const FluidOptions &o, DM dm, DMLabel *faces)
{
  DMLabel boundary, outlet;

  PetscFunctionBegin;
  PetscCall(DMGetLabel(dm, "boundary", &boundary));
  PetscCall(DMGetLabel(dm, o.outlet, &outlet));
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

PetscErrorCode FluidBlock::Wire(const std::vector<Block *> &scene)
{
  mesh    = FindBlock(scene, "geometry");
  coupled = (PetscBool)(mesh && FindBlock(scene, "coupling"));
  return 0;
}

std::string FluidBlock::Group(const std::string &role) const
{
  return role == "region" ? opt.region : role == "noslip" ? opt.noslip : role == "inlet" ? opt.inlet : role == "outlet" ? opt.outlet : "";
}

PetscErrorCode FluidBlock::ReadOptions(std::map<std::string, std::string> &problem)
{
  FluidOptions &o = opt;
  PetscInt      n = 3;

  PetscFunctionBegin;
  PetscOptionsBegin(PETSC_COMM_WORLD, nullptr, "fsi_app: the fluid block", nullptr);
  const OptionReader r{PetscOptionsObject, problem};
  PetscBool          wall;
  /* one pulse for the wall and the inlet unless told otherwise */
  PetscCall(PetscOptionsGetReal(nullptr, nullptr, "-structure_pressure_until", &o.pulseEnd, &wall));
  if (wall) PetscCall(r.Check("-structure_pressure_until", &o.pulseEnd, 1, NonNegative));
  PetscCall(r.String("-fluid_region", "physical group of the fluid's cells", o.region, sizeof(o.region), PROBLEM));
  PetscCall(r.String("-fluid_noslip", "groups of faces where the velocity is zero, comma separated", o.noslip, sizeof(o.noslip), PROBLEM));
  PetscCall(r.Real("-fluid_density", "density of the fluid (g/cm^3)", &o.rho, Positive, PROBLEM));
  PetscCall(r.Real("-fluid_viscosity", "dynamic viscosity of the fluid (poise)", &o.mu, Positive, PROBLEM));
  PetscCall(r.Real("-fluid_inlet_pressure", "normal stress: traction -p n on the faces of -fluid_inlet (dyn/cm^2)", &o.inletPressure, Any, PROBLEM));
  PetscCall(r.Real("-fluid_inlet_pressure_until", "the inlet pressure acts while t <= this (s); 0: always (default: -structure_pressure_until)", &o.pulseEnd, NonNegative, PROBLEM));
  PetscCall(r.Enum("-fluid_inlet_pressure_shape", "the inlet pressure over time: step (on at once) or cosine (p (1 - cos(2 pi t / T)) / 2 over [0, T], T = -fluid_inlet_pressure_until)", PulseShapeNames, &o.pulseShape, PROBLEM));
  PetscCall(r.String("-fluid_inlet_pressure_waveform", "the inlet pressure p(t) from a file of samples 't p' (s, dyn/cm^2) over one period, the last repeating the first; repeated periodically, a periodic cubic spline between samples; traction -p n on -fluid_inlet (named in an options file: relative to that file)", o.pressureWaveform, sizeof(o.pressureWaveform), PROBLEM));
  PetscCall(r.Numbers("-fluid_inlet_pressure_fourier", "the inlet pressure p(t) = a0 + sum_k a_k cos(2 pi k t/T) + b_k sin(2 pi k t/T) as T,a0,a1,b1,a2,b2,... (s, dyn/cm^2); traction -p n on -fluid_inlet", o.pressureFourier, 41, "numbers separated by commas; T, then at most 20 harmonics", PROBLEM));
  PetscCall(r.Reals("-fluid_inflow_velocity", "prescribed velocity ux,uy,uz on the faces of -fluid_inlet (cm/s; no-slip groups keep u = 0 on their nodes; on a coupled wall the rim moves with the wall)", o.inflowVelocity, &n, &o.inflow, Any, PROBLEM));
  PetscCheck(!o.inflow || n == 3, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-fluid_inflow_velocity: give ux,uy,uz (got %" PetscInt_FMT " values)", n);
  PetscCall(r.Points("-fluid_probes", "points x1,y1,z1,x2,... (at most 20, reference configuration) where the pressure is recorded every step (in the run report); with -fluid_inlet_pressure, when the pulse's front (half its pressure) passes each and the wave speed", o.probes));
  PetscCall(r.String("-fluid_inlet", "group of the inflow faces", o.inlet, sizeof(o.inlet), PROBLEM));
  PetscCall(r.String("-fluid_outlet", "group of the outflow faces (stress-free)", o.outlet, sizeof(o.outlet), PROBLEM));
  PetscCall(r.Bool("-fluid_shape_derivatives", "on a moving mesh, the fluid's Jacobian holds its derivative in the mesh displacement (exact Newton); false: quasi-Newton", &o.shapeDerivatives, RUN));
  n = 3;
  PetscBool set;
  PetscCall(r.Reals("-poiseuille", "verification: Hagen-Poiseuille flow in a tube of radius R and length L along z driven by a pressure drop: R,L,dp (cm, cm, dyn/cm^2)", o.poiseuille, &n, &set, Any, PROBLEM));
  PetscCheck(!set || (n == 3 && o.poiseuille[0] > 0 && o.poiseuille[1] > 0), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-poiseuille: give R,L,dp with R > 0 and L > 0");
  PetscCall(r.Enum("-mms_flow", "-mms: the manufactured flow (exact velocity on the boundary but -fluid_outlet, exact traction there)", FlowMMSKindNames, &o.mmsFlow, PROBLEM));
  PetscCall(r.Real("-mms_ramp", "-mms: the trigonometric manufactured flow rises as sin^2(pi t / 2T) over this time T (s); 0: steady", &o.mmsRamp, NonNegative, PROBLEM));
  PetscOptionsEnd();
  PetscCheck(o.pulseShape == PULSE_STEP || o.pulseEnd > 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_INCOMP, "-fluid_inlet_pressure_shape cosine needs the hump's length: -fluid_inlet_pressure_until T with T > 0");
  PetscCheck(!o.inflow || (o.inletPressure == 0 && !sc.mms && o.poiseuille[0] == 0), PETSC_COMM_WORLD, PETSC_ERR_ARG_INCOMP, "-fluid_inflow_velocity: the inlet cannot also take -fluid_inlet_pressure, -mms or -poiseuille (one condition per face)");
  const char *wave = o.pressureWaveform[0] ? "-fluid_inlet_pressure_waveform" : !o.pressureFourier.empty() ? "-fluid_inlet_pressure_fourier" : nullptr;
  if (wave) { /* a signal of time: checked and read before the mesh */
    PetscCheck(!(o.pressureWaveform[0] && !o.pressureFourier.empty()) && o.inletPressure == 0 && !o.inflow && !sc.mms && o.poiseuille[0] == 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_INCOMP,
               "%s: the inlet cannot also take -fluid_inlet_pressure_waveform or _fourier, -fluid_inlet_pressure, -fluid_inflow_velocity, -mms or -poiseuille (one condition per face)", wave);
    PetscCheck(sc.Dynamic(), PETSC_COMM_WORLD, PETSC_ERR_ARG_INCOMP, "%s: the inlet pressure is a function of time: give a time step (-dt)", wave);
    if (o.pressureWaveform[0]) PetscCall(WaveformRead(PETSC_COMM_WORLD, wave, o.pressureWaveform, inletPressure));
    else PetscCall(WaveformFourier(wave, o.pressureFourier.data(), (PetscInt)o.pressureFourier.size(), inletPressure));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode FluidBlock::Check() const
{
  PetscFunctionBegin;
  PetscCheck(!mesh || coupled || !opt.noslip[0], PETSC_COMM_WORLD, PETSC_ERR_SUP, "-blocks fluid,geometry with -fluid_noslip %s: a wall that moves needs u = w (the mesh velocity) there, which the coupling to the structure will impose; until then a moving mesh takes the manufactured flows' boundary values (-mms) and -fluid_noslip must be empty", opt.noslip);
  PetscFunctionReturn(0);
}

void FluidBlock::Groups(std::vector<GroupUse> &groups) const
{
  const char *conditions = "fluid's inlet, outlet and no-slip faces";
  groups.push_back({opt.region, "-fluid_region", 3, RegionsRole});
  for (const auto &g : SplitList(opt.noslip)) groups.push_back({g.substr(0, g.find(':')), "-fluid_noslip", 2, conditions});
  const bool inletNeeded = opt.inletPressure != 0 || opt.poiseuille[0] > 0 || opt.inflow || inletPressure.period > 0;
  if (inletNeeded) groups.push_back({opt.inlet, "-fluid_inlet", 2, conditions});
  /* the outlet's conditions need it; a stress-free outlet under a pressure or inflow only has its flux reported */
  const bool outletNeeded = opt.poiseuille[0] > 0 || sc.mms;
  if (outletNeeded || inletNeeded) groups.push_back({opt.outlet, "-fluid_outlet", 2, conditions, !outletNeeded});
}

PetscErrorCode FluidBlock::AddFields(DM dm)
{
  PetscFunctionBegin;
  PetscCall(AddLagrangeField(dm, "velocity", opt.region, 3, 2, &velocity));
  PetscCall(AddLagrangeField(dm, "pressure", opt.region, 1, 1, &pressure));
  flow.kind = opt.mmsFlow, flow.rho = opt.rho, flow.mu = opt.mu, flow.ramp = opt.mmsRamp, flow.dynamic = sc.Dynamic();
  flow.motion = mesh ? mesh->Motion() : nullptr;
  PetscFunctionReturn(0);
}

PetscErrorCode FluidBlock::AddConditions(DM dm, Conditions &list)
{
  PetscFunctionBegin;
  if (opt.inflow) { /* first: the no-slip rim wins; on a coupled wall, the rim moves with the wall (the coupling's u = d_t d_s) */
    PetscCall(AddDirichlet(dm, list, opt.inlet, velocity, "-fluid_inlet", opt.inflowVelocity));
    if (coupled) PetscCall(DMGetLabel(dm, mesh->Group("interface").c_str(), &list.back().except));
  }
  PetscCall(AddDirichlet(dm, list, opt.noslip, velocity, "-fluid_noslip"));
  if (sc.mms) {
    Condition      c;
    const FlowMMS *m = &flow;
    PetscCall(MMSDirichletFaces(opt, dm, &c.label));
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
  PetscCall(GetRegionLabel(dm, opt.region, &region));
  PetscCall(FieldCellsCreate(dm, region, velocity, fb.velocity));
  PetscCall(FieldCellsCreate(dm, region, pressure, fb.pressure));
  fb.mesh = mesh ? mesh->Cells("geometry") : nullptr;
  fb.rho = opt.rho, fb.mu = opt.mu, fb.shapeDerivatives = opt.shapeDerivatives;
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
  for (auto g : {std::make_pair(opt.inlet, &inletFaces), std::make_pair(opt.outlet, &outletFaces)}) { /* the fluxes a run reports */
    DMLabel label;
    PetscCall(DMGetLabel(dm, g.first, &label));
    if (label) PetscCall(CellFacesCreate(dm, fb.velocity, label, *g.second));
  }
  if (coupled) PetscCall(balance.SetUp(dm, fb, mesh->Group("interface").c_str()));
  if (!opt.probes.empty()) PetscCall(ProbesCreate(PetscObjectComm((PetscObject)dm), fb.pressure, opt.probes, "-fluid_probes", probes));
  if (sc.mms) {
    const FlowMMS *m = &flow;
    PetscCall(addTraction(opt.outlet, [m](const PetscReal x[3], const PetscReal n[3], PetscReal t, PetscReal tr[3]) { FlowMMSTraction(*m, x, n, t, tr); }));
    fb.force = [m](const PetscReal x[3], PetscReal t, PetscReal f[3]) { FlowMMSForce(*m, x, t, f); };
  } else if (opt.poiseuille[0] > 0) { /* the exact flow's traction sigma n at both ends */
    const Poiseuille p = {opt.poiseuille[0], opt.poiseuille[1], opt.poiseuille[2], opt.mu};
    for (const char *g : {opt.inlet, opt.outlet}) PetscCall(addTraction(g, [p](const PetscReal x[3], const PetscReal n[3], PetscReal, PetscReal t[3]) { PoiseuilleTraction(p, x, n, t); }));
  } else if (inletPressure.period > 0) {
    const Waveform *w = &inletPressure;
    PetscCall(addTraction(opt.inlet, [w](const PetscReal *, const PetscReal n[3], PetscReal time, PetscReal t[3]) {
      const PetscReal p = w->Value(time);
      for (int d = 0; d < 3; d++) t[d] = -p * n[d];
    }));
  } else if (opt.inletPressure != 0) {
    const PetscReal p = opt.inletPressure, until = opt.pulseEnd;
    const PetscBool steady = (PetscBool)!sc.Dynamic(), /* time is then the load fraction: continuation in p */
      cosine = (PetscBool)(opt.pulseShape == PULSE_COSINE);
    PetscCall(addTraction(opt.inlet, [p, until, steady, cosine](const PetscReal *, const PetscReal n[3], PetscReal time, PetscReal t[3]) {
      const bool      on = until == 0 || time <= until + 1e-12;
      const PetscReal pt = steady ? p * time : !on ? 0.0 : cosine ? p * (1 - PetscCosReal(2 * PETSC_PI * time / until)) / 2 : p;
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
  if (mesh) p.fields.push_back({"displacement", mesh->Field("geometry")}); /* the mesh's: named as the wall's, so Warp By Vector moves both parts */
  parts.push_back(p);
}

std::string FluidBlock::InvertedCause() const
{
  char cause[256];
  if (!forms.inverted) return "";
  if (coupled) return "a cell of the moved fluid mesh inverted (J <= 0): the wall moved too far in one step for the harmonic extension of its displacement";
  PetscSNPrintf(cause, sizeof(cause), "a cell of the moved fluid mesh inverted (J <= 0): the prescribed interface displacement is too large for its harmonic extension; reduce -geometry_amplitude (%g now)", (double)mesh->Motion()->a);
  return cause;
}

PetscErrorCode FluidBlock::AfterStep(DM dm, PetscInt, PetscReal t, Vec x)
{
  PetscFunctionBegin;
  if (!probes.cell.empty()) PetscCall(ProbesRecordGlobal(dm, forms.pressure, x, t, probes));
  if (coupled) PetscCall(balance.Record(dm, forms, inletFaces, outletFaces, t, x));
  PetscFunctionReturn(0);
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
  Poiseuille p = {opt.poiseuille[0], opt.poiseuille[1], opt.poiseuille[2], opt.mu};
  PetscReal  in = 0, out = 0; /* fluxes through inlet and outlet */

  PetscFunctionBegin;
  /* equal to the solver's tolerance without a moving wall: div u is orthogonal to the constants */
  PetscCall(FluidFlux(dm, forms, inletFaces, x, &in));
  PetscCall(FluidFlux(dm, forms, outletFaces, x, &out));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "flux inlet %.6e outlet %.6e (int u.n with the outward normal: an inflow is negative)\n", (double)in, (double)out));
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
  if (coupled) PetscCall(balance.Report(dm, forms, report));
  if (!probes.cell.empty()) report.series.push_back({"pressure", &probes});
  if (!probes.cell.empty() && opt.inletPressure != 0) PetscCall(ReportArrivals(probes, opt.inletPressure / 2, report));
  PetscFunctionReturn(0);
}

} // namespace fsi
