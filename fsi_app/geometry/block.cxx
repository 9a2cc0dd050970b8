// SPDX-License-Identifier: BSD-2-Clause
#include "block.h"
#include "discretization/fields.h"
#include "verification/errors.h"

namespace fsi {

void GeometryBlock::Groups(std::vector<GroupUse> &groups) const
{
  groups.push_back({sc.fluidRegion, "-fluid_region", 3, RegionsRole});
  groups.push_back({sc.interface, "-geometry_interface", 2});
  for (const auto &g : SplitList(sc.slip)) groups.push_back({g.substr(0, g.find(':')), "-geometry_slip", 2});
}

PetscErrorCode GeometryBlock::AddFields(DM dm)
{
  PetscFunctionBegin;
  PetscCall(AddLagrangeField(dm, "geometry", sc.fluidRegion, 3, 2, &field));
  motion = {sc.geometryAmplitude, sc.geometryRamp, sc.Dynamic()};
  PetscFunctionReturn(0);
}

PetscErrorCode GeometryBlock::AddConditions(DM dm, Conditions &list)
{
  PetscFunctionBegin;
  if (!coupled) {
    Condition               c;
    const PrescribedMotion *m = &motion;
    c.name = "the prescribed interface displacement (-geometry_interface)", c.field = field;
    PetscCall(DMGetLabel(dm, sc.interface, &c.label));
    c.value = [m](const PetscReal X[3], PetscReal t, PetscScalar *v) { PrescribedDisplacementBC(3, t, X, 3, v, (void *)m); };
    list.push_back(c);
  }
  PetscCall(AddDirichlet(dm, list, sc.slip, field, "-geometry_slip"));
  PetscFunctionReturn(0);
}

PetscErrorCode GeometryBlock::SetUp(DM dm)
{
  DMLabel region;

  PetscFunctionBegin;
  PetscCall(GetRegionLabel(dm, sc.fluidRegion, &region));
  PetscCall(FieldCellsCreate(dm, region, field, forms.cells));
  PetscCall(CreateP2Rule(2, forms.rule));
  if (coupled) {
    Condition             onInterface;
    std::vector<PetscInt> points;
    PetscCall(DMGetLabel(dm, sc.interface, &onInterface.label));
    PetscCall(ConditionPoints(dm, onInterface, points));
    FieldCellsDropRows(forms.cells, points);
  }
  if (!coupled && movesFluid) PetscCall(GeometryPredictorCreate(dm, field, forms, predictor));
  PetscFunctionReturn(0);
}

PetscErrorCode GeometryBlock::Predict(PetscReal t, Vec x)
{
  return predictor.ksp ? GeometryPredict(predictor, t, x) : 0;
}

void GeometryBlock::Output(std::vector<OutputPart> &parts) const
{
  if (!movesFluid) parts.push_back({"fluid", &forms.cells, {{"displacement", field}}}); /* else the fluid's part shows it */
}

PetscErrorCode GeometryBlock::Results(DM dm, Vec x, PetscReal t, RunReport &report)
{
  PetscFunctionBegin;
  if (movesFluid) {
    PetscReal dmax;
    PetscCall(FieldNorm(dm, x, field, NORM_INFINITY, &dmax));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "max mesh displacement %.6e\n", (double)dmax));
    report.results.push_back({"max_mesh_displacement", dmax});
  } else if (!coupled) {
    Errors e;
    PetscCall(ComputeErrors(dm, forms.cells, x, t, PrescribedDisplacementSolution, &motion, e));
    PetscCall(ReportErrors("", e, report));
  }
  PetscFunctionReturn(0);
}

} // namespace fsi
