// SPDX-License-Identifier: BSD-2-Clause
/* Fully implicit differences on a uniform step dt: the k-th time derivative at t^(n+1) is
   dt^-k sum_j c_j x^(n+1-j), j = 0..depth, for backward Euler and BDF2 applied to the
   first-order system (x, v): the second derivative is the first one applied twice, so both
   schemes keep their stability (BDF2: A-stable, second order, mildly dissipative). The past
   states x^n, x^(n-1), ... are local vectors the blocks read cell by cell. */
#pragma once

#include <petscdm.h>
#include <vector>

namespace fsi {

enum TimeScheme { BACKWARD_EULER = 0, BDF2 = 1 };
extern const char *const TimeSchemeNames[];

struct TimeHistory {
  DM               dm     = nullptr;
  TimeScheme       scheme = BACKWARD_EULER;
  PetscReal        dt     = 0;
  PetscReal        first[5]{}, second[5]{}; /* c_j of the first and second derivative */
  std::vector<Vec> past;                    /* past[j] = x^(n-j) (local), j < depth */
};

/* Coefficients of `scheme` for step dt and, in dynamics, as many zero local vectors of dm as
   the second derivative needs (2 for backward Euler, 4 for BDF2): a start at rest. Statics
   has no past states; dt is then the load increment. */
PetscErrorCode TimeHistoryCreate(DM dm, TimeScheme scheme, PetscReal dt, PetscBool dynamic, TimeHistory &h);
PetscErrorCode TimeHistoryDestroy(TimeHistory &h);

/* x^(n+1) (global, at time t) becomes x^n, with its essential values: the states shift by one. */
PetscErrorCode TimeHistoryPush(TimeHistory &h, Vec x, PetscReal t);

/* Every past state becomes x (global, essential values at t = 0): a start from a state held
   since t = -infinity. */
PetscErrorCode TimeHistorySetState(TimeHistory &h, Vec x);

/* The arrays of the past states (none for h == nullptr: statics), and their release. */
PetscErrorCode TimeHistoryGetPast(const TimeHistory *h, std::vector<const PetscScalar *> &past);
PetscErrorCode TimeHistoryRestorePast(const TimeHistory *h, std::vector<const PetscScalar *> &past);

/* A new history with the states and step of h; copy one into another of the same shape. */
PetscErrorCode TimeHistoryDuplicate(const TimeHistory &h, TimeHistory &copy);
PetscErrorCode TimeHistoryCopy(const TimeHistory &from, TimeHistory &to);

/* x (global) = the polynomial through the newest order+1 states extrapolated one step ahead,
   t^(n+1): Newton's first iterate (order 1: 2 x^n - x^(n-1)). Order 0 leaves x alone. */
PetscErrorCode TimeHistoryExtrapolate(const TimeHistory &h, PetscInt order, Vec x);

/* The same history on the finer step dt/m: states at t^n - j dt/m from the polynomial through
   the stored states (interpolation: these times lie between the stored ones). */
PetscErrorCode TimeHistoryRefine(TimeHistory &h, PetscInt m);

} // namespace fsi
