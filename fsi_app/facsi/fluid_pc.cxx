// SPDX-License-Identifier: BSD-2-Clause
#include "fluid_pc.h"
#include <petsc/private/pcimpl.h>
#include <petscdm.h>
#include <string>
#include <vector>

namespace fsi {

static PetscLogEvent FaCSI_SetUp, FaCSI_Apply;

struct PC_FaCSIFluid {
  std::string multiplier = "multiplier";
  IS          isFluid = nullptr, isLambda = nullptr; /* in the split's numbering */
  DM          dmFluid = nullptr;                     /* the fluid's fields: the inner KSP splits by name */
  Mat         A = nullptr, C = nullptr, G = nullptr; /* fluid block (u, p); lambda rows (u cols); (u, p) rows (lambda cols) */
  Mat         Fhat = nullptr;                        /* A with the interface velocity rows of the identity */
  KSP         ksp = nullptr;
  Vec         b = nullptr, z = nullptr, r = nullptr;
  /* interface pairs: lambda dof i (local) <-> velocity dof row[i] (local in the fluid block) */
  std::vector<PetscInt>    row;
  std::vector<PetscScalar> c, g; /* lambda row's velocity coefficient; momentum row's lambda coefficient */
};

/* The one nonzero of global row `i` of M, in column *col with value *val; error otherwise. */
static PetscErrorCode SingleEntry(Mat M, PetscInt i, const char *what, PetscInt *col, PetscScalar *val)
{
  PetscInt           n, found = 0;
  const PetscInt    *cols;
  const PetscScalar *vals;

  PetscFunctionBegin;
  PetscCall(MatGetRow(M, i, &n, &cols, &vals));
  for (PetscInt k = 0; k < n; k++)
    if (vals[k] != 0.0) found++, *col = cols[k], *val = vals[k];
  PetscCall(MatRestoreRow(M, i, &n, &cols, &vals));
  PetscCheck(found == 1, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "PCFACSIFLUID: %s %" PetscInt_FMT " has %" PetscInt_FMT " nonzeros, not one: the condensation needs a nodal multiplier on a conforming interface (C1 = I on Gamma)", what, i, found);
  PetscFunctionReturn(0);
}

/* Which velocity dof each local lambda dof ties down, and the two coefficients of the pair. */
static PetscErrorCode FindInterfacePairs(PC_FaCSIFluid *fs)
{
  PetscInt lStart, lEnd, uStart, uEnd, mStart;

  PetscFunctionBegin;
  PetscCall(MatGetOwnershipRange(fs->C, &lStart, &lEnd));
  PetscCall(MatGetOwnershipRange(fs->A, &uStart, &uEnd));
  PetscCall(MatGetOwnershipRangeColumn(fs->G, &mStart, nullptr));
  fs->row.resize(lEnd - lStart);
  fs->c.resize(lEnd - lStart);
  fs->g.resize(lEnd - lStart);
  for (PetscInt i = lStart; i < lEnd; i++) {
    PetscInt u, l;
    PetscCall(SingleEntry(fs->C, i, "multiplier row", &u, &fs->c[i - lStart]));
    PetscCheck(u >= uStart && u < uEnd, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "PCFACSIFLUID: multiplier row %" PetscInt_FMT " ties down velocity dof %" PetscInt_FMT " of another rank; a node's multiplier and velocity must share their owner", i, u);
    PetscCall(SingleEntry(fs->G, u, "interface momentum row", &l, &fs->g[i - lStart]));
    PetscCheck(l == i - lStart + mStart, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "PCFACSIFLUID: velocity dof %" PetscInt_FMT " is tied to multiplier %" PetscInt_FMT " but its momentum row holds multiplier %" PetscInt_FMT, u, i, l);
    fs->row[i - lStart] = u - uStart;
  }
  PetscFunctionReturn(0);
}

/* F^ = A with the interface velocity rows of the identity (their columns stay: the interior
   rows see the Dirichlet data through them). */
static PetscErrorCode CondenseInterface(PC_FaCSIFluid *fs, MatReuse reuse)
{
  PetscInt              uStart;
  std::vector<PetscInt> rows(fs->row.size());

  PetscFunctionBegin;
  if (reuse == MAT_INITIAL_MATRIX) {
    PetscCall(MatDuplicate(fs->A, MAT_COPY_VALUES, &fs->Fhat));
    PetscCall(MatSetOption(fs->Fhat, MAT_KEEP_NONZERO_PATTERN, PETSC_TRUE));
  } else PetscCall(MatCopy(fs->A, fs->Fhat, SAME_NONZERO_PATTERN));
  PetscCall(MatGetOwnershipRange(fs->A, &uStart, nullptr));
  for (size_t i = 0; i < rows.size(); i++) rows[i] = fs->row[i] + uStart;
  PetscCall(MatZeroRows(fs->Fhat, (PetscInt)rows.size(), rows.data(), 1.0, nullptr, nullptr));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCReset_FaCSIFluid(PC pc)
{
  PC_FaCSIFluid *fs = (PC_FaCSIFluid *)pc->data;

  PetscFunctionBegin;
  PetscCall(ISDestroy(&fs->isFluid));
  PetscCall(ISDestroy(&fs->isLambda));
  PetscCall(DMDestroy(&fs->dmFluid));
  PetscCall(MatDestroy(&fs->A));
  PetscCall(MatDestroy(&fs->C));
  PetscCall(MatDestroy(&fs->G));
  PetscCall(MatDestroy(&fs->Fhat));
  PetscCall(VecDestroy(&fs->b));
  PetscCall(VecDestroy(&fs->z));
  PetscCall(VecDestroy(&fs->r));
  PetscFunctionReturn(0);
}

/* The split's fields: the multiplier, and the fluid's (every other) with their sub-DM. */
static PetscErrorCode SplitFields(PC pc, PC_FaCSIFluid *fs)
{
  DM                    dm;
  PetscInt              nf;
  char                **names;
  IS                   *is;
  std::vector<PetscInt> fluid;

  PetscFunctionBegin;
  PetscCall(PCGetDM(pc, &dm));
  PetscCheck(dm, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_WRONGSTATE, "PCFACSIFLUID needs the fluid split's DM (its fields name the multiplier): set it with KSPSetDM() on the split's KSP, as fsi_app's named splits do");
  PetscCall(DMCreateFieldIS(dm, &nf, &names, &is));
  for (PetscInt f = 0; f < nf; f++) {
    if (fs->multiplier == names[f]) PetscCall(PetscObjectReference((PetscObject)(fs->isLambda = is[f])));
    else fluid.push_back(f);
    PetscCall(ISDestroy(&is[f]));
    PetscCall(PetscFree(names[f]));
  }
  PetscCall(PetscFree(is));
  PetscCall(PetscFree(names));
  PetscCheck(fs->isLambda, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_WRONG, "PCFACSIFLUID: the split has no field called %s (-pc_facsi_fluid_multiplier_field): FaCSI's fluid split holds the fluid's fields and the interface multiplier", fs->multiplier.c_str());
  PetscCheck(!fluid.empty(), PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_WRONG, "PCFACSIFLUID: the split holds only the multiplier; it needs the fluid's fields too");
  PetscCall(DMCreateSubDM(dm, (PetscInt)fluid.size(), fluid.data(), &fs->isFluid, &fs->dmFluid));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCSetUp_FaCSIFluid(PC pc)
{
  PC_FaCSIFluid *fs    = (PC_FaCSIFluid *)pc->data;
  const MatReuse reuse = (!pc->setupcalled || pc->flag == DIFFERENT_NONZERO_PATTERN) ? MAT_INITIAL_MATRIX : MAT_REUSE_MATRIX;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(FaCSI_SetUp, pc, 0, 0, 0));
  if (reuse == MAT_INITIAL_MATRIX) {
    PetscCall(PCReset_FaCSIFluid(pc));
    PetscCall(SplitFields(pc, fs));
  }
  PetscCall(MatCreateSubMatrix(pc->pmat, fs->isFluid, fs->isFluid, reuse, &fs->A));
  PetscCall(MatCreateSubMatrix(pc->pmat, fs->isLambda, fs->isFluid, reuse, &fs->C));
  PetscCall(MatCreateSubMatrix(pc->pmat, fs->isFluid, fs->isLambda, reuse, &fs->G));
  PetscCall(FindInterfacePairs(fs));
  PetscCall(CondenseInterface(fs, reuse));
  if (!fs->ksp) {
    const char *prefix;
    PetscCall(KSPCreate(PetscObjectComm((PetscObject)pc), &fs->ksp));
    PetscCall(KSPSetErrorIfNotConverged(fs->ksp, pc->erroriffailure));
    PetscCall(PetscObjectIncrementTabLevel((PetscObject)fs->ksp, (PetscObject)pc, 1));
    PetscCall(PCGetOptionsPrefix(pc, &prefix));
    PetscCall(KSPSetOptionsPrefix(fs->ksp, prefix));
    PetscCall(KSPAppendOptionsPrefix(fs->ksp, "dirichlet_"));
    PetscCall(KSPSetType(fs->ksp, KSPPREONLY));
  }
  if (reuse == MAT_INITIAL_MATRIX) {
    PC inner;
    PetscCall(KSPSetDM(fs->ksp, fs->dmFluid));
    PetscCall(KSPSetDMActive(fs->ksp, PETSC_FALSE));
    PetscCall(KSPGetPC(fs->ksp, &inner));
    PetscCall(PCSetType(inner, PCLU));
    PetscCall(KSPSetOperators(fs->ksp, fs->Fhat, fs->Fhat));
    PetscCall(KSPSetFromOptions(fs->ksp));
    PetscCall(MatCreateVecs(fs->A, &fs->z, &fs->b));
    PetscCall(VecDuplicate(fs->b, &fs->r));
  } else PetscCall(KSPSetOperators(fs->ksp, fs->Fhat, fs->Fhat));
  PetscCall(KSPSetUp(fs->ksp)); /* now, not in the first application */
  PetscCall(PetscLogEventEnd(FaCSI_SetUp, pc, 0, 0, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCApply_FaCSIFluid(PC pc, Vec x, Vec y)
{
  PC_FaCSIFluid     *fs = (PC_FaCSIFluid *)pc->data;
  Vec                xu, xl, yu, yl;
  const PetscScalar *xlam, *r;
  PetscScalar       *b, *ylam;
  KSPConvergedReason reason;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(FaCSI_Apply, pc, x, y, 0));
  PetscCall(VecGetSubVector(x, fs->isFluid, &xu));
  PetscCall(VecGetSubVector(x, fs->isLambda, &xl));
  /* 1. the interface velocity rows carry the Dirichlet data x_lambda / c */
  PetscCall(VecCopy(xu, fs->b));
  PetscCall(VecGetArray(fs->b, &b));
  PetscCall(VecGetArrayRead(xl, &xlam));
  for (size_t i = 0; i < fs->row.size(); i++) b[fs->row[i]] = xlam[i] / fs->c[i];
  PetscCall(VecRestoreArrayRead(xl, &xlam));
  PetscCall(VecRestoreArray(fs->b, &b));
  /* 2. the fluid with Dirichlet rows on Gamma */
  PetscCall(KSPSolve(fs->ksp, fs->b, fs->z));
  PetscCall(KSPGetConvergedReason(fs->ksp, &reason));
  if (reason < 0) PetscCall(PCSetFailedReason(pc, PC_SUBPC_ERROR));
  /* 3. lambda from the interface momentum rows: g y_lambda = (x_u - A z)|Gamma */
  PetscCall(MatMult(fs->A, fs->z, fs->r));
  PetscCall(VecAYPX(fs->r, -1.0, xu));
  PetscCall(VecRestoreSubVector(x, fs->isLambda, &xl));
  PetscCall(VecRestoreSubVector(x, fs->isFluid, &xu));
  PetscCall(VecGetSubVector(y, fs->isFluid, &yu));
  PetscCall(VecCopy(fs->z, yu));
  PetscCall(VecRestoreSubVector(y, fs->isFluid, &yu));
  PetscCall(VecGetSubVector(y, fs->isLambda, &yl));
  PetscCall(VecGetArrayRead(fs->r, &r));
  PetscCall(VecGetArray(yl, &ylam));
  for (size_t i = 0; i < fs->row.size(); i++) ylam[i] = r[fs->row[i]] / fs->g[i];
  PetscCall(VecRestoreArray(yl, &ylam));
  PetscCall(VecRestoreArrayRead(fs->r, &r));
  PetscCall(VecRestoreSubVector(y, fs->isLambda, &yl));
  PetscCall(PetscLogEventEnd(FaCSI_Apply, pc, x, y, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCSetFromOptions_FaCSIFluid(PC pc, PetscOptionItems *PetscOptionsObject)
{
  PC_FaCSIFluid *fs = (PC_FaCSIFluid *)pc->data;
  char           name[256];
  PetscBool      flg;

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "FaCSI fluid step (interface condensation) options");
  PetscCall(PetscOptionsString("-pc_facsi_fluid_multiplier_field", "The split's field that is the interface multiplier", "", fs->multiplier.c_str(), name, sizeof(name), &flg));
  if (flg) fs->multiplier = name;
  PetscOptionsHeadEnd();
  PetscFunctionReturn(0);
}

static PetscErrorCode PCView_FaCSIFluid(PC pc, PetscViewer viewer)
{
  PC_FaCSIFluid *fs = (PC_FaCSIFluid *)pc->data;
  PetscBool      ascii;

  PetscFunctionBegin;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &ascii));
  if (!ascii) PetscFunctionReturn(0);
  PetscInt n = 0, mine = (PetscInt)fs->row.size();
  PetscCallMPI(MPI_Allreduce(&mine, &n, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)pc)));
  PetscCall(PetscViewerASCIIPrintf(viewer, "  multiplier field %s: %" PetscInt_FMT " interface velocity rows condensed to Dirichlet rows\n", fs->multiplier.c_str(), n));
  if (fs->ksp) {
    PetscCall(PetscViewerASCIIPrintf(viewer, "  the fluid with Dirichlet rows on the interface, F^:\n"));
    PetscCall(PetscViewerASCIIPushTab(viewer));
    PetscCall(KSPView(fs->ksp, viewer));
    PetscCall(PetscViewerASCIIPopTab(viewer));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode PCDestroy_FaCSIFluid(PC pc)
{
  PC_FaCSIFluid *fs = (PC_FaCSIFluid *)pc->data;

  PetscFunctionBegin;
  PetscCall(PCReset_FaCSIFluid(pc));
  PetscCall(KSPDestroy(&fs->ksp));
  PetscCall(PetscObjectComposeFunction((PetscObject)pc, "PCFaCSIFluidGetKSP_C", nullptr));
  delete fs;
  pc->data = nullptr;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCFaCSIFluidGetKSP_FaCSIFluid(PC pc, KSP *ksp)
{
  PetscFunctionBegin;
  *ksp = ((PC_FaCSIFluid *)pc->data)->ksp;
  PetscFunctionReturn(0);
}

PetscErrorCode PCFaCSIFluidGetKSP(PC pc, KSP *ksp)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  *ksp = nullptr;
  PetscTryMethod(pc, "PCFaCSIFluidGetKSP_C", (PC, KSP *), (pc, ksp));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCCreate_FaCSIFluid(PC pc)
{
  PetscFunctionBegin;
  PetscCall(PetscObjectComposeFunction((PetscObject)pc, "PCFaCSIFluidGetKSP_C", PCFaCSIFluidGetKSP_FaCSIFluid));
  pc->data                = new PC_FaCSIFluid;
  pc->ops->setup          = PCSetUp_FaCSIFluid;
  pc->ops->apply          = PCApply_FaCSIFluid;
  pc->ops->reset          = PCReset_FaCSIFluid;
  pc->ops->destroy        = PCDestroy_FaCSIFluid;
  pc->ops->setfromoptions = PCSetFromOptions_FaCSIFluid;
  pc->ops->view           = PCView_FaCSIFluid;
  PetscFunctionReturn(0);
}

PetscErrorCode PCRegisterFaCSIFluid()
{
  PetscFunctionBegin;
  PetscCall(PetscLogEventRegister("FaCSIFluidSetUp", PC_CLASSID, &FaCSI_SetUp));
  PetscCall(PetscLogEventRegister("FaCSIFluidApply", PC_CLASSID, &FaCSI_Apply));
  PetscCall(PCRegister(PCFACSIFLUID, PCCreate_FaCSIFluid));
  PetscFunctionReturn(0);
}

} // namespace fsi
