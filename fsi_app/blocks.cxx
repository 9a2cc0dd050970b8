#include "blocks.h"
#include "discretization/fields.h"

namespace fsi {

PetscErrorCode CreateBlocks(const Scene &sc, DM dm, Blocks &b)
{
  Fields         &f      = b.fields;
  const PetscBool solid  = (PetscBool)(sc.physics == PHYSICS_STRUCTURE);
  const PetscBool fluid  = (PetscBool)(sc.physics == PHYSICS_FLUID);
  const PetscBool moving = (PetscBool)(sc.physics == PHYSICS_GEOMETRY || sc.movingMesh);

  PetscFunctionBegin;
  PetscCheck(!solid || sc.degree == 2, PETSC_COMM_WORLD, PETSC_ERR_SUP, "-structure_degree %" PetscInt_FMT ": the element loops are P2 (use 2)", sc.degree);
  if (solid) PetscCall(AddLagrangeField(dm, "displacement", sc.region, 3, sc.degree, &f.displacement));
  if (fluid) {
    PetscCall(AddLagrangeField(dm, "velocity", sc.fluidRegion, 3, 2, &f.velocity));
    PetscCall(AddLagrangeField(dm, "pressure", sc.fluidRegion, 1, 1, &f.pressure));
  }
  if (moving) PetscCall(AddLagrangeField(dm, "geometry", sc.fluidRegion, 3, 2, &f.geometry));
  PetscCall(DMCreateDS(dm));

  b.motion = {sc.geometryAmplitude, sc.geometryRamp, sc.Dynamic()};
  b.flow.kind = sc.mmsFlow, b.flow.rho = sc.rhoFluid, b.flow.mu = sc.muFluid, b.flow.ramp = sc.mmsRamp, b.flow.dynamic = sc.Dynamic();
  b.flow.motion = moving ? &b.motion : nullptr;
  if (solid) PetscCall(StructureConditions(sc, dm, f.displacement));
  if (fluid) PetscCall(FluidConditions(sc, dm, f.velocity, b.flow));
  if (moving) PetscCall(GeometryConditions(sc, dm, f.geometry, b.motion));

  if (solid) {
    PetscCall(SetUpStructure(sc, dm, f.displacement, b.structure));
    b.system.blocks.push_back({"structure", StructureResidual, StructureJacobian, &b.structure});
  }
  if (moving) {
    PetscCall(SetUpGeometry(sc, dm, f.geometry, b.geometry));
    b.system.blocks.push_back({"geometry", GeometryResidual, GeometryJacobian, &b.geometry});
  }
  if (fluid) {
    PetscCall(SetUpFluid(sc, dm, f.velocity, f.pressure, b.flow, b.fluid));
    b.fluid.mesh = moving ? &b.geometry.cells : nullptr;
    b.system.blocks.push_back({"fluid", FluidResidual, FluidJacobian, &b.fluid});
  }
  PetscCall(SystemAttach(dm, b.system));
  PetscFunctionReturn(0);
}

} // namespace fsi
