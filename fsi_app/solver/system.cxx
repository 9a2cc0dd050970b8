#include "system.h"
#include "discretization/cells.h"
#include "discretization/conditions.h"

namespace fsi {

static PetscErrorCode SystemResidual(DM dm, Vec Xl, Vec Fl, void *ctx)
{
  const System      &s = *(System *)ctx;
  const PetscScalar *x;
  PetscScalar       *f;

  PetscFunctionBegin;
  PetscCall(InsertEssentialValues(dm, s.time, Xl));
  PetscCall(VecZeroEntries(Fl));
  PetscCall(VecGetArrayRead(Xl, &x));
  PetscCall(VecGetArray(Fl, &f));
  for (Block *b : s.blocks) PetscCall(b->Residual(x, f));
  PetscCall(VecRestoreArray(Fl, &f));
  PetscCall(VecRestoreArrayRead(Xl, &x));
  PetscFunctionReturn(0);
}

static PetscErrorCode SystemJacobian(DM dm, Vec Xl, Mat J, Mat P, void *ctx)
{
  const System      &s = *(System *)ctx;
  const PetscScalar *x;

  PetscFunctionBegin;
  PetscCall(InsertEssentialValues(dm, s.time, Xl));
  PetscCall(MatZeroEntries(P));
  PetscCall(VecGetArrayRead(Xl, &x));
  for (Block *b : s.blocks) PetscCall(b->Jacobian(x, P));
  PetscCall(VecRestoreArrayRead(Xl, &x));
  PetscCall(AssembleOperators(J, P));
  PetscFunctionReturn(0);
}

PetscErrorCode SystemAttach(DM dm, System &s)
{
  PetscFunctionBegin;
  PetscCall(DMSNESSetFunctionLocal(dm, SystemResidual, &s));
  PetscCall(DMSNESSetJacobianLocal(dm, SystemJacobian, &s));
  PetscFunctionReturn(0);
}

} // namespace fsi
