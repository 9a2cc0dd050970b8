// SPDX-License-Identifier: BSD-2-Clause
#include "block.h"
#include "discretization/conditions.h"
#include "discretization/fields.h"
#include "mesh/mesh.h"
#include "base/options.h"
#include "verification/errors.h"
#include "io/csv.h"
#include <algorithm>
#include <string>

namespace fsi {

const char *const PulseShapeNames[] = {"step", "cosine", "PulseShape", "PULSE_", nullptr};

/* The manufactured flows' Dirichlet faces: the boundary but the outlet, where the exact
   traction fixes the pressure's constant. */
static PetscErrorCode MMSDirichletFaces(const FluidOptions &o, DM dm, DMLabel *faces)
{
  DMLabel              boundary;
  std::vector<DMLabel> outlets;

  PetscFunctionBegin;
  PetscCall(DMGetLabel(dm, "boundary", &boundary));
  for (const auto &g : SplitList(o.outlet)) {
    DMLabel l;
    PetscCall(DMGetLabel(dm, g.c_str(), &l));
    outlets.push_back(l);
  }
  PetscCall(DMCreateLabel(dm, "mms_dirichlet"));
  PetscCall(DMGetLabel(dm, "mms_dirichlet", faces));
  PetscCall(ForEachLabelPoint(boundary, {1}, [&](PetscInt face) -> PetscErrorCode {
    PetscInt v = -1;
    PetscFunctionBegin;
    for (DMLabel l : outlets)
      if (v < 0) PetscCall(DMLabelGetValue(l, face, &v));
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

std::string FluidBlock::Walls() const
{
  std::string walls = opt.noslip;
  if (coupled) walls += (walls.empty() ? "" : ",") + mesh->Group("interface");
  return walls;
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
  PetscCall(r.String("-fluid_inflow_waveform", "the inflow rate Q(t) from a file of samples 't Q' (s, cm^3/s into the fluid) over one period, the last repeating the first; a periodic cubic spline between samples; imposed as a velocity profile on -fluid_inlet (named in an options file: relative to that file)", o.flowWaveform, sizeof(o.flowWaveform), PROBLEM));
  PetscCall(r.Numbers("-fluid_inflow_fourier", "the inflow rate Q(t) = a0 + sum_k a_k cos(2 pi k t/T) + b_k sin(2 pi k t/T) as T,a0,a1,b1,... (s, cm^3/s into the fluid)", o.flowFourier, 41, "numbers separated by commas; T, then at most 20 harmonics", PROBLEM));
  PetscCall(r.Enum("-fluid_inflow_profile", "the inflow rate's velocity profile: plug (uniform), parabolic (-Delta phi = 1 on the inlet, 0 on its rim: any inlet shape), womersley (circular inlets: Womersley's solution for each harmonic of Q)", InflowProfileNames, &o.profile, PROBLEM));
  PetscCall(r.Real("-fluid_inflow_ramp", "the inflow rate rises as sin^2(pi t / 2T) over this time T (s); 0: at once", &o.flowRamp, NonNegative, PROBLEM));
  PetscCall(r.Bool("-womersley", "verification: the velocity's L2 error against Womersley's flow for the inflow rate, every step (a rigid straight tube along the inlet's normal, -fluid_inflow_profile womersley)", &o.womersley, PROBLEM));
  PetscCall(r.Reals("-fluid_inflow_velocity", "prescribed velocity ux,uy,uz on the faces of -fluid_inlet (cm/s; no-slip groups keep u = 0 on their nodes; on a coupled wall the rim moves with the wall)", o.inflowVelocity, &n, &o.inflow, Any, PROBLEM));
  PetscCheck(!o.inflow || n == 3, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-fluid_inflow_velocity: give ux,uy,uz (got %" PetscInt_FMT " values)", n);
  PetscCall(r.Points("-fluid_probes", "points x1,y1,z1,x2,... (at most 20, reference configuration) where the pressure is recorded every step (in the run report); with -fluid_inlet_pressure, when the pulse's front (half its pressure) passes each and the wave speed", o.probes));
  PetscCall(r.String("-fluid_inlet", "group of the inflow faces", o.inlet, sizeof(o.inlet), PROBLEM));
  PetscCall(r.String("-fluid_outlet", "groups of the outflow faces, comma separated, each an outlet: traction-free, or a 0D model of the outlets block", o.outlet, sizeof(o.outlet), PROBLEM));
  PetscCall(r.Real("-fluid_backflow_stabilization", "beta of the backflow term -beta rho (u.n)_- u.v on the outlets (Esmaily Moghadam et al. 2011): damps fluid re-entering through them; 0 turns it off", &o.backflow, {0, 1}, PROBLEM));
  PetscCall(r.Real("-fluid_wall_shear_from", "the wall shear stress's time average (tawss) and oscillatory shear index (osi) in the output are taken over [this time, t] (s)", &o.shearFrom, NonNegative, RUN));
  {
    const char *const policies[] = {"every_newton", "every_step", "SplitSetUp", "", nullptr}; /* SplitSetUp's order */
    PetscCall(r.Choice("-fluid_pc_setup", "when the fluid split's preconditioner (FaCSI's fluid step) is rebuilt: every Newton step, or every time step from its first Newton step's matrices", policies, &o.pcSetUp, RUN));
  }
  PetscCall(ReadSetUpInterval(r, "fluid", &o.pcSetUpInterval));
  PetscCall(r.Bool("-fluid_shape_derivatives", "on a moving mesh, the fluid's Jacobian holds its derivative in the mesh displacement (exact Newton); false: quasi-Newton", &o.shapeDerivatives, RUN));
  n = 3;
  PetscBool set;
  PetscCall(r.Reals("-poiseuille", "verification: Hagen-Poiseuille flow in a tube of radius R and length L along z driven by a pressure drop: R,L,dp (cm, cm, dyn/cm^2)", o.poiseuille, &n, &set, Any, PROBLEM));
  PetscCheck(!set || (n == 3 && o.poiseuille[0] > 0 && o.poiseuille[1] > 0), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-poiseuille: give R,L,dp with R > 0 and L > 0");
  PetscCall(r.Enum("-mms_flow", "-mms: the manufactured flow (exact velocity on the boundary but -fluid_outlet, exact traction there)", FlowMMSKindNames, &o.mmsFlow, PROBLEM));
  PetscCall(r.Real("-mms_ramp", "-mms: the trigonometric manufactured flow rises as sin^2(pi t / 2T) over this time T (s); 0: steady", &o.mmsRamp, NonNegative, PROBLEM));
  PetscOptionsEnd();
  PetscCall(CheckSetUpInterval("fluid", o.pcSetUpInterval, SetUpPolicy()));
  const std::vector<std::string> outlets = SplitList(o.outlet);
  for (size_t k = 0; k < outlets.size(); k++)
    PetscCheck(std::count(outlets.begin(), outlets.end(), outlets[k]) == 1, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-fluid_outlet %s: the group %s is named twice; each outlet is named once", o.outlet, outlets[k].c_str());
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
  const char *flow = o.flowWaveform[0] ? "-fluid_inflow_waveform" : !o.flowFourier.empty() ? "-fluid_inflow_fourier" : nullptr;
  if (flow) {
    PetscCheck(!(o.flowWaveform[0] && !o.flowFourier.empty()) && !wave && o.inletPressure == 0 && !o.inflow && !sc.mms && o.poiseuille[0] == 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_INCOMP,
               "%s: the inlet cannot also take -fluid_inflow_waveform or _fourier, an inlet pressure, -fluid_inflow_velocity, -mms or -poiseuille (one condition per face)", flow);
    PetscCheck(sc.Dynamic(), PETSC_COMM_WORLD, PETSC_ERR_ARG_INCOMP, "%s: the inflow rate is a function of time: give a time step (-dt)", flow);
    if (o.flowWaveform[0]) PetscCall(WaveformRead(PETSC_COMM_WORLD, flow, o.flowWaveform, inflow.flow));
    else PetscCall(WaveformFourier(flow, o.flowFourier.data(), (PetscInt)o.flowFourier.size(), inflow.flow));
    inflow.kind = o.profile, inflow.ramp = o.flowRamp, inflow.rho = o.rho, inflow.mu = o.mu;
  }
  PetscCheck(!o.womersley || (flow && o.profile == INFLOW_WOMERSLEY && !mesh), PETSC_COMM_WORLD, PETSC_ERR_ARG_INCOMP, "-womersley: Womersley's flow is the exact solution in a rigid tube (-blocks fluid) driven by -fluid_inflow_waveform or _fourier with -fluid_inflow_profile womersley");
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
  const bool inletNeeded = opt.inletPressure != 0 || opt.poiseuille[0] > 0 || opt.inflow || inletPressure.period > 0 || inflow.flow.period > 0;
  if (inletNeeded) groups.push_back({opt.inlet, "-fluid_inlet", 2, conditions});
  /* the outlet's conditions need it; a stress-free outlet under a pressure or inflow only has its flux reported */
  const bool outletNeeded = opt.poiseuille[0] > 0 || sc.mms;
  if (outletNeeded || inletNeeded)
    for (const auto &g : SplitList(opt.outlet)) groups.push_back({g, "-fluid_outlet", 2, conditions, !outletNeeded});
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
  if (inflow.flow.period > 0) { /* the profile is set up with the cells (SetUp); its values are read after */
    Condition            c;
    const InflowProfile *p = &inflow;
    PetscCall(DMGetLabel(dm, opt.inlet, &c.label));
    c.name = std::string("-fluid_inflow_profile ") + InflowProfileNames[opt.profile] + " on " + opt.inlet, c.field = velocity;
    c.value = [p](const PetscReal x[3], PetscReal t, PetscScalar *v) { p->Velocity(x, t, v); };
    if (coupled) PetscCall(DMGetLabel(dm, mesh->Group("interface").c_str(), &c.except));
    list.push_back(c);
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

/* Womersley's velocity u = W(r, t) n and its gradient W_r n (x) e_r about the inlet's axis. */
static void WomersleyExact(const PetscReal x[3], PetscReal t, const void *ctx, PetscReal u[3], PetscReal G[9])
{
  const auto     *b = (const std::pair<const Womersley *, const InflowProfile *> *)ctx;
  const PetscReal *c = b->second->centre, *n = b->second->normal;
  PetscReal        y[3], along = 0, r2 = 0;
  for (int d = 0; d < 3; d++) y[d] = x[d] - c[d], along += y[d] * n[d];
  for (int d = 0; d < 3; d++) y[d] -= along * n[d], r2 += y[d] * y[d];
  const PetscReal r = PetscSqrtReal(r2), w = b->first->Velocity(r, t), wr = r > 0 ? b->first->RadialDerivative(r, t) / r : 0.0;
  for (int i = 0; i < 3; i++) {
    u[i] = w * n[i];
    if (G)
      for (int j = 0; j < 3; j++) G[3 * i + j] = wr * n[i] * y[j];
  }
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
  auto faces = [&](const std::string &group, std::vector<CellFace> &f) -> PetscErrorCode { /* the fluxes a run reports */
    DMLabel label;
    PetscFunctionBegin;
    PetscCall(DMGetLabel(dm, group.c_str(), &label));
    if (label) PetscCall(CellFacesCreate(dm, fb.velocity, label, f));
    PetscFunctionReturn(0);
  };
  PetscCall(faces(opt.inlet, inletFaces));
  const std::vector<std::string> outlets = SplitList(opt.outlet);
  outletsFaces.assign(outlets.size() > 1 ? outlets.size() : 0, {});
  for (size_t k = 0; k < outlets.size(); k++) {
    std::vector<CellFace> f;
    PetscCall(faces(outlets[k], f));
    outletFaces.insert(outletFaces.end(), f.begin(), f.end());
    if (outlets.size() > 1) outletsFaces[k] = f;
  }
  fb.backflow = outletFaces, fb.backflowBeta = sc.mms || opt.poiseuille[0] > 0 || opt.womersley ? 0.0 : opt.backflow; /* the exact flows' traction holds there */
  if (coupled) PetscCall(balance.SetUp(dm, fb, mesh->Group("interface").c_str()));
  if (inflow.flow.period > 0) PetscCall(InflowProfileSetUp(dm, fb.velocity, opt.inlet, inflow));
  if (opt.womersley) exact.SetUp(inflow.flow.Harmonics((PetscInt)inflow.womersley.c.size() - 1), inflow.flow.period, inflow.radius, opt.rho, opt.mu);
  if (!opt.probes.empty()) PetscCall(ProbesCreate(PetscObjectComm((PetscObject)dm), fb.pressure, opt.probes, "-fluid_probes", probes));
  PetscCall(WallShearSetUp(dm, fb, Walls(), opt.shearFrom, shear));
  std::vector<std::string> named = {opt.inlet};
  named.insert(named.end(), outlets.begin(), outlets.end());
  for (const auto &g : SplitList(Walls().c_str())) named.push_back(g.substr(0, g.find(':')));
  for (const auto &g : named) {
    std::vector<CellFace> f;
    PetscCall(faces(g, f));
    boundaries.push_back({g, f});
  }
  if (sc.mms) {
    const FlowMMS *m = &flow;
    for (const auto &g : outlets) PetscCall(addTraction(g.c_str(), [m](const PetscReal x[3], const PetscReal n[3], PetscReal t, PetscReal tr[3]) { FlowMMSTraction(*m, x, n, t, tr); }));
    fb.force = [m](const PetscReal x[3], PetscReal t, PetscReal f[3]) { FlowMMSForce(*m, x, t, f); };
  } else if (opt.poiseuille[0] > 0) { /* the exact flow's traction sigma n at both ends */
    const Poiseuille p = {opt.poiseuille[0], opt.poiseuille[1], opt.poiseuille[2], opt.mu};
    std::vector<std::string> ends = outlets;
    ends.push_back(opt.inlet);
    for (const auto &g : ends) PetscCall(addTraction(g.c_str(), [p](const PetscReal x[3], const PetscReal n[3], PetscReal, PetscReal t[3]) { PoiseuilleTraction(p, x, n, t); }));
  } else if (opt.womersley) { /* the exact flow's traction mu (grad u + grad u^T) n on the outlets: its pressure is 0 there */
    const Womersley     *w = &exact;
    const InflowProfile *in = &inflow;
    const PetscReal      mu = opt.mu;
    for (const auto &g : outlets)
      PetscCall(addTraction(g.c_str(), [w, in, mu](const PetscReal x[3], const PetscReal n[3], PetscReal t, PetscReal tr[3]) {
        const std::pair<const Womersley *, const InflowProfile *> ctx(w, in);
        PetscReal u[3], G[9];
        WomersleyExact(x, t, &ctx, u, G);
        for (int i = 0; i < 3; i++) tr[i] = mu * ((G[3 * i] + G[i]) * n[0] + (G[3 * i + 1] + G[3 + i]) * n[1] + (G[3 * i + 2] + G[6 + i]) * n[2]);
      }));
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
  OutputPart p{"fluid", &forms.velocity, {{"velocity", velocity}, {"pressure", pressure}}, {}};
  if (mesh) p.fields.push_back({"displacement", mesh->Field("geometry")}); /* the mesh's: named as the wall's, so Warp By Vector moves both parts */
  if (!Walls().empty()) p.derived = {{"wss", 3, &shear.tau}, {"tawss", 1, &shear.tawss}, {"osi", 1, &shear.osi}}; /* nonzero on the walls, as svMultiPhysics writes them */
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

/* Womersley's wall shear stress -mu W_r(R, t) along the axis. */
struct WomersleyWall {
  const Womersley     *w;
  const InflowProfile *inlet;
  PetscReal            mu;
};
static void WomersleyShear(const PetscReal *, PetscReal t, const void *ctx, PetscReal tau[3])
{
  const WomersleyWall *b = (const WomersleyWall *)ctx;
  const PetscReal      s = -b->mu * b->w->RadialDerivative(b->inlet->radius, t);
  for (int i = 0; i < 3; i++) tau[i] = s * b->inlet->normal[i];
}

/* Poiseuille's R dp / (2 L) along z, at the wall r = R. */
static void PoiseuilleShear(const PetscReal *, PetscReal, const void *ctx, PetscReal tau[3])
{
  const Poiseuille &f = *(const Poiseuille *)ctx;
  tau[0] = tau[1] = 0, tau[2] = f.R * f.dp / (2 * f.L);
}

/* The wall shear stress at time t from the global state x, and each boundary's flow and mean
   pressure (NAME_boundaries.csv: t, then Q_<group>, p_<group> per group). */
PetscErrorCode FluidBlock::RecordBoundaries(DM dm, PetscInt step, PetscReal t, Vec x)
{
  Vec                    xl;
  const PetscScalar     *a;
  std::vector<PetscReal> row = {t};
  std::string            header = "t";

  PetscFunctionBegin;
  PetscCall(DMGetLocalVector(dm, &xl));
  PetscCall(DMGlobalToLocal(dm, x, INSERT_VALUES, xl));
  PetscCall(InsertEssentialValues(dm, t, xl));
  PetscCall(VecGetArrayRead(xl, &a));
  PetscCall(WallShearCompute(dm, forms, a, t, sc.Dynamic() ? sc.dt : 1.0 / sc.Steps(), shear));
  for (const auto &b : boundaries) {
    PetscReal v[3];
    PetscCall(FluidFaceIntegrals(dm, forms, b.second, a, v));
    row.insert(row.end(), {v[0], v[2] > 0 ? v[1] / v[2] : 0.0});
    header += ",Q_" + b.first + ",p_" + b.first;
  }
  PetscCall(VecRestoreArrayRead(xl, &a));
  PetscCall(DMRestoreLocalVector(dm, &xl));
  if (firstStep < 0) firstStep = step;
  PetscCall(CsvAppend(sc.output, "boundaries", header, (PetscBool)(step == firstStep), (PetscBool)(firstStep > 1), row));
  PetscFunctionReturn(0);
}

PetscErrorCode FluidBlock::AfterStep(DM dm, PetscInt step, PetscReal t, Vec x)
{
  PetscFunctionBegin;
  PetscCall(RecordBoundaries(dm, step, t, x));
  if (opt.womersley) {
    const std::pair<const Womersley *, const InflowProfile *> ctx(&exact, &inflow);
    Errors    e, n;
    PetscReal se, sn;
    PetscCall(ComputeErrors(dm, forms.velocity, x, t, WomersleyExact, &ctx, e));
    PetscCall(ComputeErrors(dm, forms.velocity, x, t, ZeroSolution, nullptr, n));
    const WomersleyWall wall = {&exact, &inflow, opt.mu};
    PetscCall(WallShearError(dm, shear, WomersleyShear, &wall, t, &se, &sn));
    womersleyErrors.insert(womersleyErrors.end(), {t, e.l2, n.l2, se, sn});
  }
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
  const std::vector<std::string> outlets = SplitList(opt.outlet);
  for (size_t k = 0; k < outletsFaces.size(); k++) {
    PetscReal q;
    PetscCall(FluidFlux(dm, forms, outletsFaces[k], x, &q));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "flux outlet %s %.6e\n", outlets[k].c_str(), (double)q));
    report.results.push_back({"outlet_flux_" + outlets[k], q});
  }
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
  if (opt.womersley && !womersleyErrors.empty()) { /* over the last period: the largest error against the largest norm */
    PetscReal e = 0, n = 0, se = 0, sn = 0;
    for (size_t k = 0; k < womersleyErrors.size(); k += 5)
      if (womersleyErrors[k] >= t - inflow.flow.period * (1 - 1e-9)) {
        e = PetscMax(e, womersleyErrors[k + 1]), n = PetscMax(n, womersleyErrors[k + 2]);
        se = PetscMax(se, womersleyErrors[k + 3]), sn = PetscMax(sn, womersleyErrors[k + 4]);
      }
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "Womersley's flow (R %.6e, alpha %.4g): velocity L2 error over the last period %.6e, relative %.6e; wall shear stress relative %.6e\n", (double)inflow.radius, (double)(inflow.radius * PetscSqrtReal(2 * PETSC_PI / inflow.flow.period * opt.rho / opt.mu)), (double)e, (double)(e / n), (double)(se / sn)));
    report.results.insert(report.results.end(), {{"womersley_l2", e}, {"womersley_l2_relative", e / n}, {"womersley_wss_relative", se / sn}});
  }
  if (!Walls().empty()) {
    WallShearSummary w;
    PetscCall(WallShearSummarize(dm, shear, w));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "wall shear stress: largest %.6e, time average (mean over the wall) %.6e, OSI %.6e to %.6e (averages from t = %g)\n", (double)w.maxTau, (double)w.meanTawss, (double)w.minOsi, (double)w.maxOsi, (double)opt.shearFrom));
    report.results.insert(report.results.end(), {{"wss_max", w.maxTau}, {"tawss_mean", w.meanTawss}, {"osi_min", w.minOsi}, {"osi_max", w.maxOsi}});
    if (p.R > 0) {
      PetscReal se, sn;
      PetscCall(WallShearError(dm, shear, PoiseuilleShear, &p, t, &se, &sn));
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "wall shear stress against R dp / 2L = %.6e: relative error %.6e\n", (double)(p.R * p.dp / (2 * p.L)), (double)(se / sn)));
      report.results.push_back({"wss_relative_error", se / sn});
    }
  }
  if (coupled) PetscCall(balance.Report(dm, forms, report));
  if (!probes.cell.empty()) report.series.push_back({"pressure", &probes});
  if (!probes.cell.empty() && opt.inletPressure != 0) PetscCall(ReportArrivals(probes, opt.inletPressure / 2, report));
  PetscFunctionReturn(0);
}

} // namespace fsi
