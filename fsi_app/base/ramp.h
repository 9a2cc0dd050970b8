// SPDX-License-Identifier: BSD-2-Clause
/* The smooth start of a load or a prescribed motion: no jump in the value or its rate, so the
   time schemes keep their order. */
#pragma once

#include <petscsys.h>

namespace fsi {

/* sin^2(pi t / 2T) for t < T, then 1 (T = 0: 1 at once); its rate d/dt if asked. */
inline PetscReal SmoothRamp(PetscReal t, PetscReal T, PetscReal *rate = nullptr)
{
  const PetscBool rising = (PetscBool)(T > 0 && t < T);
  if (rate) *rate = rising ? PETSC_PI / (2 * T) * PetscSinReal(PETSC_PI * t / T) : 0.0;
  return rising ? PetscSqr(PetscSinReal(PETSC_PI * t / (2 * T))) : 1.0;
}

} // namespace fsi
