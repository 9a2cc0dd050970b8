#include "splits.h"
#include <petscdm.h>

namespace fsi {

PetscErrorCode SetNamedSplits(PC pc, DM dm, const Splits &splits)
{
  PetscBool        isFieldSplit, byNumber;
  const char      *prefix;
  PCCompositeType  type;
  std::vector<DM>  sub(splits.size());

  PetscFunctionBegin;
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCFIELDSPLIT, &isFieldSplit));
  if (!isFieldSplit || splits.size() < 2) PetscFunctionReturn(0);
  PetscCall(PCGetOptionsPrefix(pc, &prefix));
  PetscCall(PetscOptionsHasName(nullptr, prefix, "-pc_fieldsplit_0_fields", &byNumber));
  if (byNumber) PetscFunctionReturn(0);
  for (size_t s = 0; s < splits.size(); s++) {
    IS is;
    PetscCall(DMCreateSubDM(dm, (PetscInt)splits[s].second.size(), splits[s].second.data(), &is, &sub[s]));
    PetscCall(PCFieldSplitSetIS(pc, splits[s].first.c_str(), is));
    PetscCall(ISDestroy(&is));
  }
  PetscCall(PCFieldSplitGetType(pc, &type));
  if (type != PC_COMPOSITE_SCHUR) { /* the Schur type makes its KSPs at set-up */
    KSP     *ksp;
    PetscInt n;
    PetscCall(PCFieldSplitGetSubKSP(pc, &n, &ksp));
    for (PetscInt s = 0; s < n; s++) {
      PetscCall(KSPSetDM(ksp[s], sub[s]));
      PetscCall(KSPSetDMActive(ksp[s], PETSC_FALSE));
    }
    PetscCall(PetscFree(ksp));
  }
  for (DM &d : sub) PetscCall(DMDestroy(&d));
  PetscFunctionReturn(0);
}

} // namespace fsi
