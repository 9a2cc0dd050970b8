#include "setup.h"
#include "discretization/fields.h"
#include "verification/mms.h"

namespace fsi {

PetscErrorCode StructureConditions(const Scene &sc, DM dm, PetscInt field)
{
  PetscFunctionBegin;
  if (sc.mms) {
    DMLabel        boundary;
    const PetscInt one = 1;
    PetscCall(DMGetLabel(dm, "boundary", &boundary));
    PetscCall(DMAddBoundary(dm, DM_BC_ESSENTIAL, "boundary", boundary, 1, &one, field, 0, nullptr, (void (*)(void))MMSElasticityExact, nullptr, (void *)&sc.mmsAmplitude, nullptr));
  }
  PetscCall(AddDirichlet(dm, sc.clamp, field, "-structure_clamp"));
  PetscFunctionReturn(0);
}

PetscErrorCode SetUpStructure(const Scene &sc, DM dm, PetscInt field, StructureBlock &sb)
{
  PetscFunctionBegin;
  PetscCall(GetMaterialLaw(sc.material, &sb.law));
  switch (sc.material) {
  case LINEAR_ELASTIC:
    sb.param[0] = sc.E / (2 * (1 + sc.nu)), sb.param[1] = sc.E * sc.nu / ((1 + sc.nu) * (1 - 2 * sc.nu));
    break;
  case NEO_HOOKE:
    sb.param[0] = sc.mu, sb.param[1] = sc.kappa;
    break;
  case ARTERIAL:
    for (int k = 0; k < 5; k++) sb.param[k] = sc.arterial[k];
    sb.fibreAngle = sc.fibreAngle * PETSC_PI / 180;
    break;
  }
  sb.mms = sc.mms ? sc.mmsAmplitude : 0.0;
  if (sc.region[0]) PetscCall(GetRegionLabel(dm, sc.region, &sb.region));
  /* affine P2 stiffness: degree 2 (exact for the linear law); the trigonometric load: more */
  PetscCall(CreateP2Rule(sc.mms ? 5 : 2, sb.rule));
  PetscCall(CreateP2Mass(sb.mass));
  PetscCall(CreateFaceRule(sc.follower ? 4 : 2, sb.faceRule)); /* P2 times the normal: constant (dead) or quadratic (follower) */
  sb.follower = sc.follower;
  sb.rho      = sc.rho;
  PetscCall(FieldCellsCreate(dm, sb.region, field, sb.cells));
  if (sc.pressure != 0) {
    DMLabel loaded;
    PetscCall(DMGetLabel(dm, sc.loaded, &loaded));
    PetscCall(CellFacesCreate(dm, sb.cells, loaded, sb.loaded));
  }
  if (sc.tractionGroup[0]) {
    DMLabel group;
    PetscCall(DMGetLabel(dm, sc.tractionGroup, &group));
    PetscCall(CellFacesCreate(dm, sb.cells, group, sb.tractionFaces));
  }
  for (int d = 0; d < 3; d++) sb.bodyForce[d] = sc.bodyForce[d], sb.traction[d] = sc.traction[d];
  PetscFunctionReturn(0);
}

PetscReal StructureLoadFactor(const Scene &sc, PetscReal t)
{
  if (!sc.Dynamic()) return t;
  if (sc.pulseEnd > 0 && t > sc.pulseEnd + 1e-12) return 0.0;
  return SmoothRamp(t, sc.ramp);
}

} // namespace fsi
