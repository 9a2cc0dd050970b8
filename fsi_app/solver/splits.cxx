#include "splits.h"
#include <petscdm.h>

namespace fsi {

PetscErrorCode SetNamedSplits(PC pc, DM dm, const Splits &splits)
{
  PetscBool       isFieldSplit, byNumber;
  const char     *prefix;
  PCCompositeType type;
  std::vector<DM> sub(splits.size());
  std::vector<IS> is(splits.size());

  PetscFunctionBegin;
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCFIELDSPLIT, &isFieldSplit));
  if (!isFieldSplit || splits.size() < 2) PetscFunctionReturn(0);
  PetscCall(PCGetOptionsPrefix(pc, &prefix));
  PetscCall(PetscOptionsHasName(nullptr, prefix, "-pc_fieldsplit_0_fields", &byNumber));
  if (byNumber) PetscFunctionReturn(0);
  for (size_t s = 0; s < splits.size(); s++) {
    PetscCall(DMCreateSubDM(dm, (PetscInt)splits[s].fields.size(), splits[s].fields.data(), &is[s], &sub[s]));
    PetscCall(PCFieldSplitSetIS(pc, splits[s].name.c_str(), is[s]));
  }
  PetscCall(PCFieldSplitGetType(pc, &type));
  if (type != PC_COMPOSITE_SCHUR) { /* the Schur type makes its KSPs at set-up */
    KSP     *ksp;
    PetscInt n;
    PetscCall(PCFieldSplitGetSubKSP(pc, &n, &ksp));
    for (PetscInt s = 0; s < n; s++) {
      PC           subpc;
      MatNullSpace nsp = nullptr;
      PetscCall(KSPSetDM(ksp[s], sub[s]));
      PetscCall(KSPSetDMActive(ksp[s], PETSC_FALSE));
      PetscCall(KSPSetFromOptions(ksp[s])); /* the split's PC type, before its owner configures it */
      PetscCall(KSPGetPC(ksp[s], &subpc));
      if (splits[s].owner) PetscCall(splits[s].owner->ConfigurePC(sub[s], subpc, &nsp));
      if (nsp) PetscCall(PetscObjectCompose((PetscObject)is[s], "nearnullspace", (PetscObject)nsp)); /* PCFIELDSPLIT sets it on the split's matrix */
      PetscCall(MatNullSpaceDestroy(&nsp));
    }
    PetscCall(PetscFree(ksp));
  }
  for (size_t s = 0; s < splits.size(); s++) {
    PetscCall(ISDestroy(&is[s]));
    PetscCall(DMDestroy(&sub[s]));
  }
  PetscFunctionReturn(0);
}

} // namespace fsi
