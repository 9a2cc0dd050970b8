#include "setup.h"
#include "verification/mms.h"

namespace fsi {

PetscErrorCode SetUpFluid(const Scene &sc, DM dm, FluidBlock &fb, PetscInt *velocity, PetscInt *pressure)
{
  DMLabel region;

  PetscFunctionBegin;
  PetscCall(AddLagrangeField(dm, "velocity", sc.fluidRegion, 3, 2, velocity));
  PetscCall(AddLagrangeField(dm, "pressure", sc.fluidRegion, 1, 1, pressure));
  PetscCall(DMCreateDS(dm));
  PetscCall(AddZeroDirichlet(dm, sc.noslip, *velocity, "-fluid_noslip"));
  PetscCall(DMGetLabel(dm, (std::string("region_") + sc.fluidRegion).c_str(), &region));
  PetscCall(FieldCellsCreate(dm, region, *velocity, fb.velocity));
  PetscCall(FieldCellsCreate(dm, region, *pressure, fb.pressure));
  fb.rho = sc.rhoFluid, fb.mu = sc.muFluid;
  PetscCall(CreateP2Rule(5, fb.rule));
  PetscCall(CreateFaceRule(4, fb.faceRule));
  PetscCall(CreateP2Mass(fb.mass));
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
  if (sc.poiseuille[0] > 0) { /* the exact flow's traction sigma n at both ends */
    const Poiseuille flow = {sc.poiseuille[0], sc.poiseuille[1], sc.poiseuille[2], sc.muFluid};
    for (const char *g : {sc.inlet, sc.outlet}) PetscCall(addTraction(g, [flow](const PetscReal x[3], const PetscReal n[3], PetscReal, PetscReal t[3]) { PoiseuilleTraction(flow, x, n, t); }));
  } else if (sc.inletPressure != 0) {
    const PetscReal p = sc.inletPressure, until = sc.pulseEnd;
    const PetscBool steady = (PetscBool)!sc.Dynamic(); /* time is then the load fraction: continuation in p */
    PetscCall(addTraction(sc.inlet, [p, until, steady](const PetscReal *, const PetscReal n[3], PetscReal time, PetscReal t[3]) {
      const PetscReal pt = steady ? p * time : (until == 0 || time <= until + 1e-12 ? p : 0.0);
      for (int d = 0; d < 3; d++) t[d] = -pt * n[d];
    }));
  }
  PetscCall(DMSNESSetFunctionLocal(dm, FluidResidual, &fb));
  PetscCall(DMSNESSetJacobianLocal(dm, FluidJacobian, &fb));
  PetscFunctionReturn(0);
}

} // namespace fsi
