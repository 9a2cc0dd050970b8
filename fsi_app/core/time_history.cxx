// SPDX-License-Identifier: BSD-2-Clause
#include "time_history.h"
#include "discretization/conditions.h"

namespace fsi {

const char *const TimeSchemeNames[] = {"backward_euler", "bdf2", "TimeScheme", "", nullptr};

/* d/dt of backward Euler {1, -1} and BDF2 {3/2, -2, 1/2}; d2/dt2 is the product of two. */
static void SetCoefficients(TimeHistory &h, PetscReal dt)
{
  const PetscReal be[3] = {1, -1, 0}, bdf2[3] = {1.5, -2, 0.5};
  const PetscReal *c    = h.scheme == BDF2 ? bdf2 : be;
  h.dt                  = dt;
  for (int j = 0; j < 5; j++) h.first[j] = j < 3 ? c[j] : 0, h.second[j] = 0;
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) h.second[a + b] += c[a] * c[b];
}

PetscErrorCode TimeHistoryCreate(DM dm, TimeScheme scheme, PetscReal dt, PetscBool dynamic, TimeHistory &h)
{
  PetscFunctionBegin;
  h.dm = dm, h.scheme = scheme;
  SetCoefficients(h, dt);
  h.past.resize(dynamic ? (scheme == BDF2 ? 4 : 2) : 0);
  for (Vec &v : h.past) {
    PetscCall(DMCreateLocalVector(dm, &v));
    PetscCall(VecSet(v, 0.0));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode TimeHistoryDestroy(TimeHistory &h)
{
  PetscFunctionBegin;
  for (Vec &v : h.past) PetscCall(VecDestroy(&v));
  h.past.clear();
  PetscFunctionReturn(0);
}

PetscErrorCode TimeHistoryPush(TimeHistory &h, Vec x, PetscReal t)
{
  PetscFunctionBegin;
  if (h.past.empty()) PetscFunctionReturn(0); /* statics */
  for (size_t j = h.past.size() - 1; j > 0; j--) PetscCall(VecCopy(h.past[j - 1], h.past[j]));
  PetscCall(DMGlobalToLocal(h.dm, x, INSERT_VALUES, h.past[0]));
  PetscCall(InsertEssentialValues(h.dm, t, h.past[0]));
  PetscFunctionReturn(0);
}

PetscErrorCode TimeHistorySetState(TimeHistory &h, Vec x)
{
  PetscFunctionBegin;
  for (Vec v : h.past) {
    PetscCall(DMGlobalToLocal(h.dm, x, INSERT_VALUES, v));
    PetscCall(InsertEssentialValues(h.dm, 0.0, v));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode TimeHistoryGetPast(const TimeHistory *h, std::vector<const PetscScalar *> &past)
{
  PetscFunctionBegin;
  past.clear();
  if (h)
    for (Vec v : h->past) {
      const PetscScalar *y;
      PetscCall(VecGetArrayRead(v, &y));
      past.push_back(y);
    }
  PetscFunctionReturn(0);
}

PetscErrorCode TimeHistoryRestorePast(const TimeHistory *h, std::vector<const PetscScalar *> &past)
{
  PetscFunctionBegin;
  for (size_t j = 0; j < past.size(); j++) PetscCall(VecRestoreArrayRead(h->past[j], &past[j]));
  past.clear();
  PetscFunctionReturn(0);
}

PetscErrorCode TimeHistoryDuplicate(const TimeHistory &h, TimeHistory &copy)
{
  PetscFunctionBegin;
  PetscCall(TimeHistoryCreate(h.dm, h.scheme, h.dt, (PetscBool)!h.past.empty(), copy));
  PetscCall(TimeHistoryCopy(h, copy));
  PetscFunctionReturn(0);
}

PetscErrorCode TimeHistoryCopy(const TimeHistory &from, TimeHistory &to)
{
  PetscFunctionBegin;
  to.scheme = from.scheme;
  SetCoefficients(to, from.dt);
  for (size_t j = 0; j < from.past.size(); j++) PetscCall(VecCopy(from.past[j], to.past[j]));
  PetscFunctionReturn(0);
}

/* The weights w_i of the polynomial through the s states at times -i (in steps) evaluated at tau. */
static std::vector<PetscScalar> LagrangeWeights(PetscInt s, PetscReal tau)
{
  std::vector<PetscScalar> w(s);
  for (PetscInt i = 0; i < s; i++) {
    PetscReal l = 1;
    for (PetscInt k = 0; k < s; k++)
      if (k != i) l *= (tau + k) / (PetscReal)(k - i);
    w[i] = l;
  }
  return w;
}

PetscErrorCode TimeHistoryExtrapolate(const TimeHistory &h, PetscInt order, Vec x)
{
  Vec xl;

  PetscFunctionBegin;
  if (h.past.empty() || order < 1) PetscFunctionReturn(0);
  PetscCheck(order < (PetscInt)h.past.size(), PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "extrapolation of order %" PetscInt_FMT " needs %" PetscInt_FMT " past states, the scheme keeps %zu", order, order + 1, h.past.size());
  const std::vector<PetscScalar> w = LagrangeWeights(order + 1, 1.0);
  PetscCall(DMGetLocalVector(h.dm, &xl));
  PetscCall(VecSet(xl, 0.0));
  PetscCall(VecMAXPY(xl, order + 1, w.data(), const_cast<Vec *>(h.past.data())));
  PetscCall(DMLocalToGlobal(h.dm, xl, INSERT_VALUES, x));
  PetscCall(DMRestoreLocalVector(h.dm, &xl));
  PetscFunctionReturn(0);
}

PetscErrorCode TimeHistoryRefine(TimeHistory &h, PetscInt m)
{
  const PetscInt   s = (PetscInt)h.past.size();
  std::vector<Vec> old(s);

  PetscFunctionBegin;
  for (PetscInt i = 0; i < s; i++) {
    PetscCall(VecDuplicate(h.past[i], &old[i]));
    PetscCall(VecCopy(h.past[i], old[i]));
  }
  for (PetscInt j = 1; j < s; j++) { /* tau in units of the old step: stored states at -i, wanted at -j/m */
    const std::vector<PetscScalar> w = LagrangeWeights(s, -(PetscReal)j / m);
    PetscCall(VecSet(h.past[j], 0.0));
    PetscCall(VecMAXPY(h.past[j], s, w.data(), old.data()));
  }
  for (Vec &v : old) PetscCall(VecDestroy(&v));
  SetCoefficients(h, h.dt / m);
  PetscFunctionReturn(0);
}

} // namespace fsi
