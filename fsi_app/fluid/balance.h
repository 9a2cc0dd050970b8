// SPDX-License-Identifier: BSD-2-Clause
/* The fluid's volume balance on a mesh moved by a coupled wall, recorded after every step and
   reported at the end: (1) inflow - outflow - int_G u.n = 0, since div u is orthogonal to the
   constants; (2) int_G u.n = dV/dt, the fluid volume V = int J dX differenced by the time
   scheme's own formula (the discrete geometric conservation law). With it, the interface
   displacement's norm in space and time ||d_f||_{L2(Gamma x (t0, T))}, the quantity of the
   work-precision studies. */
#pragma once

#include "fluid/assembly.h"
#include "io/report.h"

namespace fsi {

class VolumeBalance {
public:
  /* The fluid's faces on the moving wall `interface` (a group of dm). */
  PetscErrorCode SetUp(DM dm, const FluidForms &forms, const char *interface);
  /* The state x (global, at time t) of the step just pushed into forms.history; the inflow and
     outflow through `inlet` and `outlet` faces. */
  PetscErrorCode Record(DM dm, const FluidForms &forms, const std::vector<CellFace> &inlet, const std::vector<CellFace> &outlet, PetscReal t, Vec x);
  PetscErrorCode Report(DM dm, const FluidForms &forms, RunReport &report) const;

private:
  PetscErrorCode Volume(DM dm, const FluidForms &forms, const PetscScalar *x, PetscReal *volume) const;

  struct Step {
    PetscReal t, in, out, wall, volume, d2; /* d2: int_Gamma |d_f|^2 dA */
  };
  std::vector<CellFace>  wall;      /* the fluid's faces on the interface */
  std::vector<Step>      steps;
  std::vector<PetscReal> before;       /* volumes of the states before the first step recorded */
  PetscReal              d2Before = 0; /* int_Gamma |d_f|^2 dA of the state before it */
};

} // namespace fsi
