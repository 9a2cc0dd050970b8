// SPDX-License-Identifier: BSD-2-Clause
#include "splits.h"
#include <petscdm.h>
#include <petsc/private/snesimpl.h> /* KSPPreSolve_SNESEW: our pre-solve hook replaces SNES's */

namespace fsi {

struct SplitSetUps {
  SNES                       snes;
  std::vector<KSP>           ksp; /* borrowed: PCFIELDSPLIT owns them */
  std::vector<SplitSetUp>    policy;
  std::vector<PetscInt>      interval; /* SETUP_EVERY_STEP: at every interval-th solve */
  PetscInt                   solves = 0; /* SNES solves begun: the run's time steps (and their retries) */
  std::vector<PetscLogEvent> event;
};

static PetscErrorCode DestroySplitSetUps(void *ctx)
{
  delete (SplitSetUps *)ctx;
  return 0;
}

/* Before the Krylov iteration: the fieldsplit's matrices for this Jacobian, then each split's
   preconditioner, rebuilt or kept as its block asks. A KSP has one pre-solve hook, so this one
   also does SNES's: the Eisenstat-Walker tolerance (-snes_ksp_ew). */
static PetscErrorCode SetUpSplits(KSP ksp, Vec b, Vec x, void *ctx)
{
  SplitSetUps *s = (SplitSetUps *)ctx;
  PetscInt     it;
  PetscBool    ew;

  PetscFunctionBegin;
  PetscCall(SNESKSPGetUseEW(s->snes, &ew));
  if (ew) PetscCall(KSPPreSolve_SNESEW(ksp, b, x, s->snes));
  PetscCall(KSPSetUp(ksp));
  PetscCall(SNESGetIterationNumber(s->snes, &it));
  if (it == 0) s->solves++;
  for (size_t k = 0; k < s->ksp.size(); k++) {
    PC              pc;
    const PetscBool keep = (PetscBool)(s->policy[k] == SETUP_ONCE || (s->policy[k] == SETUP_EVERY_STEP && (it > 0 || (s->solves - 1) % s->interval[k])));
    PetscCall(KSPGetPC(s->ksp[k], &pc));
    PetscCall(PCSetReusePreconditioner(pc, keep)); /* a PC never set up is set up regardless */
    PetscCall(PetscLogEventBegin(s->event[k], s->ksp[k], 0, 0, 0));
    PetscCall(KSPSetUp(s->ksp[k]));
    PetscCall(KSPSetUpOnBlocks(s->ksp[k]));
    PetscCall(PetscLogEventEnd(s->event[k], s->ksp[k], 0, 0, 0));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode SetNamedSplits(SNES snes, DM dm, const Splits &splits)
{
  KSP             outer;
  PC              pc;
  PetscBool       isFieldSplit, byNumber;
  const char     *prefix;
  PCCompositeType type;
  std::vector<DM> sub(splits.size());
  std::vector<IS> is(splits.size());

  PetscFunctionBegin;
  PetscCall(SNESGetKSP(snes, &outer));
  PetscCall(KSPGetPC(outer, &pc));
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
    KSP         *ksp;
    PetscInt     n;
    SplitSetUps *ctx = new SplitSetUps;
    ctx->snes        = snes;
    PetscCall(PCFieldSplitGetSubKSP(pc, &n, &ksp));
    for (PetscInt s = 0; s < n; s++) {
      PC            subpc;
      MatNullSpace  nsp = nullptr;
      PetscLogEvent event;
      PetscCall(KSPSetDM(ksp[s], sub[s]));
      PetscCall(KSPSetDMActive(ksp[s], PETSC_FALSE));
      PetscCall(KSPSetFromOptions(ksp[s])); /* the split's PC type, before its owner configures it */
      PetscCall(KSPGetPC(ksp[s], &subpc));
      if (splits[s].owner) PetscCall(splits[s].owner->ConfigurePC(sub[s], subpc, &nsp));
      if (nsp) PetscCall(PetscObjectCompose((PetscObject)is[s], "nearnullspace", (PetscObject)nsp)); /* PCFIELDSPLIT sets it on the split's matrix */
      PetscCall(MatNullSpaceDestroy(&nsp));
      PetscCall(PetscLogEventRegister(("SplitSetUp_" + splits[s].name).c_str(), KSP_CLASSID, &event));
      ctx->ksp.push_back(ksp[s]);
      ctx->policy.push_back(splits[s].owner ? splits[s].owner->SetUpPolicy() : SETUP_EVERY_NEWTON);
      ctx->interval.push_back(splits[s].owner ? splits[s].owner->SetUpInterval() : 1);
      ctx->event.push_back(event);
    }
    PetscCall(PetscFree(ksp));
    PetscContainer container;
    PetscCall(PetscContainerCreate(PETSC_COMM_SELF, &container));
    PetscCall(PetscContainerSetPointer(container, ctx));
    PetscCall(PetscContainerSetUserDestroy(container, DestroySplitSetUps));
    PetscCall(PetscObjectCompose((PetscObject)outer, "fsi_split_setups", (PetscObject)container));
    PetscCall(PetscContainerDestroy(&container));
    PetscCall(KSPSetPreSolve(outer, SetUpSplits, ctx));
  }
  for (size_t s = 0; s < splits.size(); s++) {
    PetscCall(ISDestroy(&is[s]));
    PetscCall(DMDestroy(&sub[s]));
  }
  PetscFunctionReturn(0);
}

} // namespace fsi
