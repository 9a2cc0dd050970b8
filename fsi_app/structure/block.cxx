// SPDX-License-Identifier: BSD-2-Clause
#include "block.h"
#include "discretization/fields.h"
#include "discretization/nodes.h"
#include "solver/subdomains.h"
#include "verification/errors.h"
#include "verification/mms.h"

namespace fsi {

void StructureBlock::Groups(std::vector<GroupUse> &groups) const
{
  for (const auto &g : SplitList(sc.region)) groups.push_back({g, "-structure_region", 3, RegionsRole});
  for (const auto &g : SplitList(sc.clamp)) groups.push_back({g.substr(0, g.find(':')), "-structure_clamp", 2});
  for (const auto &g : SplitList(sc.tractionGroup)) groups.push_back({g, "-structure_traction_group", 2});
  if (sc.pressure != 0) groups.push_back({sc.loaded, "-structure_pressure_group", 2});
}

PetscErrorCode StructureBlock::AddFields(DM dm)
{
  PetscFunctionBegin;
  PetscCheck(sc.degree == 2, PETSC_COMM_WORLD, PETSC_ERR_SUP, "-structure_degree %" PetscInt_FMT ": the element loops are P2 (use 2)", sc.degree);
  PetscCall(AddLagrangeField(dm, "displacement", sc.region, 3, sc.degree, &field));
  PetscFunctionReturn(0);
}

PetscErrorCode StructureBlock::AddConditions(DM dm, Conditions &list)
{
  PetscFunctionBegin;
  if (sc.mms) {
    Condition c;
    const PetscReal *a = &sc.mmsAmplitude;
    c.name = "-mms (the manufactured displacement on the boundary)", c.field = field;
    PetscCall(DMGetLabel(dm, "boundary", &c.label));
    c.value = [a](const PetscReal x[3], PetscReal t, PetscScalar *v) { MMSElasticityExact(3, t, x, 3, v, (void *)a); };
    list.push_back(c);
  }
  PetscCall(AddDirichlet(dm, list, sc.clamp, field, "-structure_clamp"));
  PetscFunctionReturn(0);
}

PetscErrorCode StructureBlock::SetUp(DM dm)
{
  StructureForms &sb = forms;

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
  if (!sc.structureProbes.empty()) PetscCall(ProbesCreate(PetscObjectComm((PetscObject)dm), sb.cells, sc.structureProbes, "-structure_probes", probes));
  PetscFunctionReturn(0);
}

PetscReal StructureLoadFactor(const Scene &sc, PetscReal t)
{
  if (!sc.Dynamic()) return t;
  if (sc.pulseEnd > 0 && t > sc.pulseEnd + 1e-12) return 0.0;
  return SmoothRamp(t, sc.ramp);
}

PetscErrorCode StructureBlock::SetTime(PetscReal t)
{
  forms.load     = StructureLoadFactor(sc, t);
  forms.pressure = sc.pressure * forms.load;
  return 0;
}

PetscErrorCode StructureBlock::ConfigurePC(DM dm, PC pc, MatNullSpace *nsp)
{
  PetscInt f;

  PetscFunctionBegin;
  PetscCall(FieldByName(dm, "displacement", &f));
  PetscCall(RigidBodyModes(dm, f, nsp));
  PetscCall(ConfigureGDSW(pc, dm, sc.region, sc.subdomains));
  PetscFunctionReturn(0);
}

std::string StructureBlock::InvertedCause() const
{
  return forms.inverted ? "an element inverted (det F <= 0)" : "";
}

PetscErrorCode StructureBlock::AfterStep(DM dm, PetscInt, PetscReal t, Vec x)
{
  return probes.cell.empty() ? 0 : ProbesRecordGlobal(dm, forms.cells, x, t, probes);
}

PetscErrorCode StructureBlock::Results(DM dm, Vec x, PetscReal t, RunReport &report)
{
  Errors e;
  Lame   lame = LameCylinder(sc.E, sc.nu, sc.pressure, sc.lameRadii[0], sc.lameRadii[1]);

  PetscFunctionBegin;
  if (!probes.cell.empty()) report.series.push_back({"displacement", &probes});
  if (sc.lameRadii[1] > 0) PetscCall(ComputeErrors(dm, forms.cells, x, t, LameSolution, &lame, e));
  else if (sc.mms) PetscCall(ComputeErrors(dm, forms.cells, x, t, MMSElasticitySolution, &sc.mmsAmplitude, e));
  else PetscFunctionReturn(0);
  PetscCall(ReportErrors("", e, report));
  PetscFunctionReturn(0);
}

} // namespace fsi
