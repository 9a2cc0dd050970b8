/* The nonlinear system of a scene on one DM: the sum of the residuals and Jacobians of the
   blocks the scene names (structure, fluid, geometry, coupling), each adding its
   rows into the local vectors and the matrix. The essential values are inserted once, at the
   time of the step being solved, before any block reads the state. */
#pragma once

#include "solver/block.h"
#include <vector>

namespace fsi {

struct System {
  std::vector<Block *> blocks;
  PetscReal            time = 0; /* of the step being solved (statics: the load fraction) */
};

/* The system's residual and Jacobian become dm's DMSNES local callbacks; `s` must outlive dm. */
PetscErrorCode SystemAttach(DM dm, System &s);

} // namespace fsi
