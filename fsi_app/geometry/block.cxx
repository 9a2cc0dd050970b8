// SPDX-License-Identifier: BSD-2-Clause
#include "block.h"
#include "discretization/fields.h"
#include "base/options.h"
#include "verification/errors.h"

namespace fsi {

PetscErrorCode GeometryBlock::Wire(const std::vector<Block *> &scene)
{
  fluid      = FindBlock(scene, "fluid");
  coupled    = (PetscBool)(FindBlock(scene, "coupling") != nullptr);
  movesFluid = (PetscBool)(fluid != nullptr);
  return 0;
}

PetscErrorCode GeometryBlock::ReadOptions(std::map<std::string, std::string> &problem)
{
  GeometryOptions &o = opt;

  PetscFunctionBegin;
  PetscOptionsBegin(PETSC_COMM_WORLD, nullptr, "fsi_app: the geometry block (harmonic mesh motion)", nullptr);
  const OptionReader r{PetscOptionsObject, problem};
  if (fluid) PetscCall(PetscStrncpy(o.region, fluid->Region().c_str(), sizeof(o.region)));
  else PetscCall(r.String("-fluid_region", "physical group of the fluid's cells, where the mesh moves", o.region, sizeof(o.region), PROBLEM));
  PetscCall(r.String("-geometry_interface", "group where the fluid's mesh displacement is the structure's", o.interface, sizeof(o.interface), PROBLEM));
  PetscCall(r.String("-geometry_slip", "groups where the mesh slides: the listed components are zero (planar ends: group:z)", o.slip, sizeof(o.slip), PROBLEM));
  PetscCall(r.Real("-geometry_amplitude", "amplitude a of the prescribed interface displacement a s(t) (x^2 - y^2, -2xy, 0) (1/cm; -blocks geometry or fluid,geometry)", &o.amplitude, Any, PROBLEM));
  PetscCall(r.Real("-geometry_ramp", "the prescribed interface displacement rises as s(t) = sin^2(pi t / 2T) over this time T (s); 0: at once", &o.ramp, NonNegative, PROBLEM));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

std::string GeometryBlock::Group(const std::string &role) const
{
  return role == "region" ? opt.region : role == "interface" ? opt.interface : "";
}

void GeometryBlock::Groups(std::vector<GroupUse> &groups) const
{
  groups.push_back({opt.region, "-fluid_region", 3, RegionsRole});
  groups.push_back({opt.interface, "-geometry_interface", 2});
  for (const auto &g : SplitList(opt.slip)) groups.push_back({g.substr(0, g.find(':')), "-geometry_slip", 2});
}

PetscErrorCode GeometryBlock::AddFields(DM dm)
{
  PetscFunctionBegin;
  PetscCall(AddLagrangeField(dm, "geometry", opt.region, 3, 2, &field));
  motion = {opt.amplitude, opt.ramp, sc.Dynamic()};
  PetscFunctionReturn(0);
}

PetscErrorCode GeometryBlock::AddConditions(DM dm, Conditions &list)
{
  PetscFunctionBegin;
  if (!coupled) {
    Condition               c;
    const PrescribedMotion *m = &motion;
    c.name = "the prescribed interface displacement (-geometry_interface)", c.field = field;
    PetscCall(DMGetLabel(dm, opt.interface, &c.label));
    c.value = [m](const PetscReal X[3], PetscReal t, PetscScalar *v) { PrescribedDisplacementBC(3, t, X, 3, v, (void *)m); };
    list.push_back(c);
  }
  PetscCall(AddDirichlet(dm, list, opt.slip, field, "-geometry_slip"));
  PetscFunctionReturn(0);
}

PetscErrorCode GeometryBlock::SetUp(DM dm)
{
  DMLabel region;

  PetscFunctionBegin;
  PetscCall(GetRegionLabel(dm, opt.region, &region));
  PetscCall(FieldCellsCreate(dm, region, field, forms.cells));
  PetscCall(CreateP2Rule(2, forms.rule));
  if (coupled) {
    Condition             onInterface;
    std::vector<PetscInt> points;
    PetscCall(DMGetLabel(dm, opt.interface, &onInterface.label));
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
  if (!movesFluid) parts.push_back({"fluid", &forms.cells, {{"displacement", field}}, {}}); /* else the fluid's part shows it */
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
