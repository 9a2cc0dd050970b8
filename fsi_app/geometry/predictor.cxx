// SPDX-License-Identifier: BSD-2-Clause
#include "predictor.h"
#include "discretization/conditions.h"

namespace fsi {

PetscErrorCode GeometryPredictorCreate(DM dm, PetscInt field, const GeometryForms &gb, GeometryPredictor &p)
{
  Mat full;
  PC  pc;

  PetscFunctionBegin;
  p.dm = dm, p.gb = &gb;
  PetscCall(DMCreateSubDM(dm, 1, &field, &p.is, nullptr));
  PetscCall(DMCreateMatrix(dm, &full));
  PetscCall(GeometryJacobian(gb, nullptr, full));
  PetscCall(AssembleOperators(full, full));
  PetscCall(MatCreateSubMatrix(full, p.is, p.is, MAT_INITIAL_MATRIX, &p.K));
  PetscCall(MatDestroy(&full));
  PetscCall(MatCreateVecs(p.K, &p.delta, nullptr));
  PetscCall(KSPCreate(PetscObjectComm((PetscObject)dm), &p.ksp));
  PetscCall(KSPSetOptionsPrefix(p.ksp, "geometry_predictor_"));
  PetscCall(KSPSetOperators(p.ksp, p.K, p.K));
  PetscCall(KSPSetType(p.ksp, KSPCG));
  PetscCall(KSPGetPC(p.ksp, &pc));
  PetscCall(PCSetType(pc, PCGAMG));
  PetscCall(KSPSetTolerances(p.ksp, 1e-10, 1e-14, PETSC_DEFAULT, PETSC_DEFAULT));
  PetscCall(KSPSetErrorIfNotConverged(p.ksp, PETSC_TRUE));
  PetscCall(KSPSetFromOptions(p.ksp));
  PetscFunctionReturn(0);
}

PetscErrorCode GeometryPredict(GeometryPredictor &p, PetscReal t, Vec x)
{
  Vec          Xl, Fl, F, r, xg;
  const PetscScalar *xa;
  PetscScalar *fa;

  PetscFunctionBegin;
  PetscCall(DMGetLocalVector(p.dm, &Xl));
  PetscCall(DMGetLocalVector(p.dm, &Fl));
  PetscCall(DMGetGlobalVector(p.dm, &F));
  PetscCall(DMGlobalToLocal(p.dm, x, INSERT_VALUES, Xl));
  PetscCall(InsertEssentialValues(p.dm, t, Xl));
  PetscCall(VecZeroEntries(Fl));
  PetscCall(VecGetArrayRead(Xl, &xa));
  PetscCall(VecGetArray(Fl, &fa));
  PetscCall(GeometryResidual(*p.gb, xa, fa));
  PetscCall(VecRestoreArray(Fl, &fa));
  PetscCall(VecRestoreArrayRead(Xl, &xa));
  PetscCall(VecZeroEntries(F));
  PetscCall(DMLocalToGlobal(p.dm, Fl, ADD_VALUES, F));
  PetscCall(VecGetSubVector(F, p.is, &r));
  PetscCall(KSPSolve(p.ksp, r, p.delta)); /* linear: one Newton step is the solution */
  PetscCall(VecRestoreSubVector(F, p.is, &r));
  PetscCall(VecGetSubVector(x, p.is, &xg));
  PetscCall(VecAXPY(xg, -1.0, p.delta));
  PetscCall(VecRestoreSubVector(x, p.is, &xg));
  PetscCall(DMRestoreGlobalVector(p.dm, &F));
  PetscCall(DMRestoreLocalVector(p.dm, &Fl));
  PetscCall(DMRestoreLocalVector(p.dm, &Xl));
  PetscFunctionReturn(0);
}

PetscErrorCode GeometryPredictorDestroy(GeometryPredictor &p)
{
  PetscFunctionBegin;
  PetscCall(KSPDestroy(&p.ksp));
  PetscCall(MatDestroy(&p.K));
  PetscCall(VecDestroy(&p.delta));
  PetscCall(ISDestroy(&p.is));
  PetscFunctionReturn(0);
}

} // namespace fsi
