// SPDX-License-Identifier: BSD-2-Clause
/* The mesh motion ahead of each step: the harmonic extension of the step's new interface
   displacement, solved alone before the coupled Newton iteration starts (the geometry rows
   do not depend on the flow). Without it the first iterate would move only the boundary nodes,
   by the whole step's displacement (in statics: all of it), and tangle the cells beside them,
   where the fluid's residual does not exist. */
#pragma once

#include "geometry/harmonic.h"

namespace fsi {

struct GeometryPredictor {
  DM                   dm = nullptr;
  const GeometryForms *gb = nullptr;
  IS                   is = nullptr; /* the geometry rows of the global vector */
  Mat                  K  = nullptr; /* their vector Laplacian */
  KSP                  ksp = nullptr; /* options prefix -geometry_predictor_ (CG + GAMG, rtol 1e-10) */
  Vec                  delta = nullptr;
};

PetscErrorCode GeometryPredictorCreate(DM dm, PetscInt field, const GeometryForms &gb, GeometryPredictor &p);
/* x (global) gets d_f = the harmonic extension of the interface displacement at time t. */
PetscErrorCode GeometryPredict(GeometryPredictor &p, PetscReal t, Vec x);
PetscErrorCode GeometryPredictorDestroy(GeometryPredictor &p);

} // namespace fsi
