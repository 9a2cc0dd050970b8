// SPDX-License-Identifier: BSD-2-Clause
#include "system.h"
#include "discretization/cells.h"
#include "discretization/conditions.h"
#include "discretization/csr_add.h"
#include <algorithm>

namespace fsi {

static PetscLogEvent AssembleJacobian, LayOutJacobian, RestoreConstantRows, DirectAdd;

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
  PetscMPIInt inverted = 0, anywhere;
  for (size_t k = 0; k < s.blocks.size(); k++) {
    PetscCall(PetscLogEventBegin(s.residualEvent[k], 0, 0, 0, 0));
    PetscCall(s.blocks[k]->Residual(x, f));
    PetscCall(PetscLogEventEnd(s.residualEvent[k], 0, 0, 0, 0));
    if (!s.blocks[k]->InvertedCause().empty()) inverted = 1;
  }
  /* every rank must see the domain error: the line search branches on it, and ranks that
     branch apart wait in different collectives */
  PetscCallMPI(MPI_Allreduce(&inverted, &anywhere, 1, MPI_INT, MPI_MAX, PetscObjectComm((PetscObject)dm)));
  if (anywhere && s.snes) PetscCall(SNESSetFunctionDomainError(s.snes));
  PetscCall(VecRestoreArray(Fl, &f));
  PetscCall(VecRestoreArrayRead(Xl, &x));
  PetscFunctionReturn(0);
}

PetscErrorCode SystemCreateMatrix(DM dm, Mat *J)
{
  PetscSection global;
  PetscInt     m, pStart, pEnd, bs = 3;

  PetscFunctionBegin;
  PetscCall(DMGetGlobalSection(dm, &global));
  PetscCall(PetscSectionGetConstrainedStorageSize(global, &m));
  /* nodes of one 3-component field, none partly constrained: block size 3 (AMG's rigid-body modes) */
  PetscCall(PetscSectionGetChart(global, &pStart, &pEnd));
  for (PetscInt p = pStart; p < pEnd && bs == 3; p++) {
    PetscInt dof, cdof;
    PetscCall(PetscSectionGetDof(global, p, &dof));
    PetscCall(PetscSectionGetConstraintDof(global, p, &cdof));
    if (dof > 0 && dof - cdof != 3 && dof - cdof != 0) bs = 1;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &bs, 1, MPIU_INT, MPI_MIN, PetscObjectComm((PetscObject)dm)));
  PetscCall(MatCreate(PetscObjectComm((PetscObject)dm), J));
  PetscCall(MatSetSizes(*J, m, m, PETSC_DETERMINE, PETSC_DETERMINE));
  PetscCall(MatSetBlockSize(*J, bs));
  PetscCall(MatSetType(*J, MATAIJ));
  PetscCall(MatSetDM(*J, dm));
  PetscFunctionReturn(0);
}

/* P's storage: exactly the entries the blocks insert. */
static PetscErrorCode LayOut(const System &s, Mat P)
{
  PetscLayout rows, cols;

  PetscFunctionBegin;
  PetscCall(MatGetLayouts(P, &rows, &cols));
  PetscCall(PetscLayoutSetUp(rows));
  PetscCall(PetscLayoutSetUp(cols));
  Sparsity sparsity(rows, cols);
  for (const Block *b : s.blocks) b->Couplings(sparsity);
  PetscCall(sparsity.LayOut(P));
  PetscFunctionReturn(0);
}

/* P += the Jacobians of the blocks whose Jacobian is (or is not) constant */
static PetscErrorCode AddJacobians(const System &s, const PetscScalar *x, Mat P, PetscBool constant)
{
  CsrAdd csr;

  PetscFunctionBegin;
  if (s.directAdd) PetscCall(csr.Open(P));
  const PetscBool direct = (PetscBool)(CsrAdd::Of(P) != nullptr); /* -log_view's JacobianDirectAdd: the blocks' Jacobians written straight into P */
  if (direct) PetscCall(PetscLogEventBegin(DirectAdd, P, 0, 0, 0));
  for (size_t k = 0; k < s.blocks.size(); k++) {
    if (s.blocks[k]->ConstantJacobian() != constant) continue;
    PetscCall(PetscLogEventBegin(s.jacobianEvent[k], 0, 0, 0, 0));
    PetscCall(s.blocks[k]->Jacobian(x, P));
    PetscCall(PetscLogEventEnd(s.jacobianEvent[k], 0, 0, 0, 0));
  }
  if (direct) PetscCall(PetscLogEventEnd(DirectAdd, P, 0, 0, 0));
  PetscCall(csr.Close());
  PetscFunctionReturn(0);
}

static PetscErrorCode SystemJacobian(DM dm, Vec Xl, Mat J, Mat P, void *ctx)
{
  System            &s = *(System *)ctx;
  const PetscScalar *x;

  PetscFunctionBegin;
  PetscCall(InsertEssentialValues(dm, s.time, Xl));
  PetscCall(VecGetArrayRead(Xl, &x));
  if (!s.laidOut) {
    PetscCall(PetscLogEventBegin(LayOutJacobian, P, 0, 0, 0));
    PetscCall(LayOut(s, P));
    PetscCall(PetscLogEventEnd(LayOutJacobian, P, 0, 0, 0));
  }
  s.laidOut = PETSC_TRUE;
  PetscBool kept;
  PetscCall(s.constant.KeptFor(P, &kept));
  if (kept) {
    PetscCall(PetscLogEventBegin(RestoreConstantRows, P, 0, 0, 0));
    PetscCall(s.constant.Restore(P));
    PetscCall(PetscLogEventEnd(RestoreConstantRows, P, 0, 0, 0));
  } else {
    PetscCall(MatZeroEntries(P));
    PetscCall(AddJacobians(s, x, P, PETSC_TRUE));
    if (s.keepConstant && std::any_of(s.blocks.begin(), s.blocks.end(), [](const Block *b) { return b->ConstantJacobian(); })) {
      PetscCall(AssembleOperators(P, P)); /* the other ranks' shares of the constant rows arrive */
      PetscCall(s.constant.Keep(P));
    }
  }
  PetscCall(AddJacobians(s, x, P, PETSC_FALSE));
  PetscCall(VecRestoreArrayRead(Xl, &x));
  PetscCall(PetscLogEventBegin(AssembleJacobian, P, 0, 0, 0));
  PetscCall(AssembleOperators(J, P));
  PetscCall(PetscLogEventEnd(AssembleJacobian, P, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode SystemAttach(DM dm, System &s)
{
  PetscFunctionBegin;
  if (!AssembleJacobian) {
    PetscCall(PetscLogEventRegister("AssembleJacobian", MAT_CLASSID, &AssembleJacobian));
    PetscCall(PetscLogEventRegister("LayOutJacobian", MAT_CLASSID, &LayOutJacobian));
    PetscCall(PetscLogEventRegister("ConstantRows", MAT_CLASSID, &RestoreConstantRows));
    PetscCall(PetscLogEventRegister("JacobianDirectAdd", MAT_CLASSID, &DirectAdd));
  }
  s.residualEvent.resize(s.blocks.size());
  s.jacobianEvent.resize(s.blocks.size());
  for (size_t k = 0; k < s.blocks.size(); k++) {
    PetscCall(PetscLogEventRegister((std::string("Residual_") + s.blocks[k]->Name()).c_str(), SNES_CLASSID, &s.residualEvent[k]));
    PetscCall(PetscLogEventRegister((std::string("Jacobian_") + s.blocks[k]->Name()).c_str(), SNES_CLASSID, &s.jacobianEvent[k]));
  }
  PetscCall(DMSNESSetFunctionLocal(dm, SystemResidual, &s));
  PetscCall(DMSNESSetJacobianLocal(dm, SystemJacobian, &s));
  PetscFunctionReturn(0);
}

} // namespace fsi
