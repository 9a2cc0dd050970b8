/* First level: exact (or inexact, by options) solves on the overlapping subdomains
   Omega_i^delta, sum_i R_i^T A_i^{-1} R_i, or its restricted variant that prolongates each
   correction only on a nonoverlapping partition (each node goes to the subdomain of smallest
   id that contains it in Omega~). */
#include "gdswimpl.h"
#include <algorithm>

using gdsw::Subdomain;

static PetscErrorCode CreateScatters(PC pc)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;
  const PetscInt bs = gd->bs;
  std::vector<PetscInt> all, keepPos, keepGlobal;
  PetscInt total = 0;
  Vec      x;
  IS       is, isw;

  PetscFunctionBegin;
  for (auto &s : *gd->sub) {
    PetscInt        n;
    const PetscInt *idx;
    PetscCall(ISGetLocalSize(s.overlap, &n));
    PetscCall(ISGetIndices(s.overlap, &idx));
    s.wOffset = total;
    for (PetscInt k = 0; k < n; k++) {
      all.push_back(idx[k]);
      const PetscInt node = idx[k] / bs;
      auto it = std::lower_bound(s.nodes.begin(), s.nodes.end(), node);
      if (it != s.nodes.end() && *it == node && (*gd->sets)[s.setOf[it - s.nodes.begin()]][0] == s.gid) {
        keepPos.push_back(total + k);
        keepGlobal.push_back(idx[k]);
      }
    }
    PetscCall(ISRestoreIndices(s.overlap, &idx));
    total += n;
    PetscCall(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n, nullptr, &s.x));
    PetscCall(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n, nullptr, &s.y));
  }
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, total, &gd->work));
  PetscCall(VecDuplicate(gd->work, &gd->workOut));
  PetscCall(MatCreateVecs(gd->A, &x, nullptr));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, total, all.data(), PETSC_USE_POINTER, &is));
  PetscCall(VecScatterCreate(x, is, gd->work, nullptr, &gd->restrictTo));
  PetscCall(ISDestroy(&is));
  if (gd->firstLevel == PC_GDSW_FIRST_LEVEL_RESTRICTED) {
    PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)keepPos.size(), keepPos.data(), PETSC_USE_POINTER, &isw));
    PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)keepGlobal.size(), keepGlobal.data(), PETSC_USE_POINTER, &is));
    PetscCall(VecScatterCreate(gd->workOut, isw, x, is, &gd->prolongFrom));
    PetscCall(ISDestroy(&is));
    PetscCall(ISDestroy(&isw));
  }
  PetscCall(VecDestroy(&x));
  PetscFunctionReturn(0);
}

PetscErrorCode GDSWSetUpFirstLevel(PC pc, MatReuse reuse)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;
  auto    &sub = *gd->sub;
  const PetscInt n = (PetscInt)sub.size();

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(GDSW_LocalFactor, pc, 0, 0, 0));
  if (reuse == MAT_INITIAL_MATRIX) PetscCall(CreateScatters(pc));
  for (PetscInt i = 0; i < n; i++) {
    Subdomain &s = sub[i];
    if (!s.ksp) {
      PetscCall(KSPCreate(PETSC_COMM_SELF, &s.ksp));
      PetscCall(KSPSetErrorIfNotConverged(s.ksp, pc->erroriffailure));
      PetscCall(PetscObjectIncrementTabLevel((PetscObject)s.ksp, (PetscObject)pc, 1));
      PetscCall(KSPSetOptionsPrefix(s.ksp, ((PetscObject)pc)->prefix));
      PetscCall(KSPAppendOptionsPrefix(s.ksp, "pc_gdsw_sub_"));
      PetscCall(GDSWDefaultFactorSolver(s.ksp, nullptr, gd->symmetric));
      PetscCall(KSPSetFromOptions(s.ksp));
    }
    PetscCall(KSPSetOperators(s.ksp, s.Aovl, s.Aovl));
    PetscCall(GDSWSetUpLocalSolver(s.ksp, "overlapping", s.gid));
  }
  PetscCall(PetscLogEventEnd(GDSW_LocalFactor, pc, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* y += sum_i R~_i^T A_i^{-1} R_i x */
PetscErrorCode GDSWApplyFirstLevel(PC pc, Vec x, Vec y)
{
  PC_GDSW     *gd = (PC_GDSW *)pc->data;
  PetscScalar *w, *wo;

  PetscFunctionBegin;
  PetscCall(VecScatterBegin(gd->restrictTo, x, gd->work, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(gd->restrictTo, x, gd->work, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetArray(gd->work, &w));
  PetscCall(VecGetArray(gd->workOut, &wo));
  for (auto &s : *gd->sub) {
    PetscCall(VecPlaceArray(s.x, w + s.wOffset));
    PetscCall(VecPlaceArray(s.y, wo + s.wOffset));
    PetscCall(KSPSolve(s.ksp, s.x, s.y));
    PetscCall(KSPCheckSolve(s.ksp, pc, s.y));
    PetscCall(VecResetArray(s.x));
    PetscCall(VecResetArray(s.y));
  }
  PetscCall(VecRestoreArray(gd->work, &w));
  PetscCall(VecRestoreArray(gd->workOut, &wo));
  if (gd->firstLevel == PC_GDSW_FIRST_LEVEL_RESTRICTED) {
    PetscCall(VecScatterBegin(gd->prolongFrom, gd->workOut, y, ADD_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(gd->prolongFrom, gd->workOut, y, ADD_VALUES, SCATTER_FORWARD));
  } else {
    PetscCall(VecScatterBegin(gd->restrictTo, gd->workOut, y, ADD_VALUES, SCATTER_REVERSE));
    PetscCall(VecScatterEnd(gd->restrictTo, gd->workOut, y, ADD_VALUES, SCATTER_REVERSE));
  }
  PetscFunctionReturn(0);
}
