#include "setup.h"
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

PetscErrorCode FluidConditions(const Scene &sc, DM dm, PetscInt velocity, const FlowMMS &flow)
{
  PetscFunctionBegin;
  if (sc.inflow) PetscCall(AddDirichlet(dm, sc.inlet, velocity, "-fluid_inlet", sc.inflowVelocity)); /* first: the no-slip rim wins */
  PetscCall(AddDirichlet(dm, sc.noslip, velocity, "-fluid_noslip"));
  if (sc.mms) {
    DMLabel               faces;
    std::vector<PetscInt> ids;
    PetscCall(MMSDirichletFaces(sc, dm, &faces));
    PetscCall(LabelValues(faces, ids));
    PetscCall(DMAddBoundary(dm, DM_BC_ESSENTIAL, "manufactured velocity", faces, (PetscInt)ids.size(), ids.data(), velocity, 0, nullptr, (void (*)(void))FlowMMSVelocityBC, nullptr, (void *)&flow, nullptr));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode SetUpFluid(const Scene &sc, DM dm, PetscInt velocity, PetscInt pressure, const FlowMMS &flow, FluidBlock &fb)
{
  DMLabel region;

  PetscFunctionBegin;
  PetscCall(GetRegionLabel(dm, sc.fluidRegion, &region));
  PetscCall(FieldCellsCreate(dm, region, velocity, fb.velocity));
  PetscCall(FieldCellsCreate(dm, region, pressure, fb.pressure));
  fb.rho = sc.rhoFluid, fb.mu = sc.muFluid;
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
  for (auto g : {std::make_pair(sc.inlet, &fb.inletFaces), std::make_pair(sc.outlet, &fb.outletFaces)}) { /* the fluxes a run reports */
    DMLabel label;
    PetscCall(DMGetLabel(dm, g.first, &label));
    if (label) PetscCall(CellFacesCreate(dm, fb.velocity, label, *g.second));
  }
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

} // namespace fsi
