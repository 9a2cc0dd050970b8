// SPDX-License-Identifier: BSD-2-Clause
/* Wall shear stress on the fluid's walls (the no-slip faces and the interface with the wall):
     tau = -(sigma n - (n . sigma n) n),  sigma = mu (grad u + grad u^T),
   the tangential force per area the fluid exerts on the wall (n: the fluid's outward normal;
   along the flow near the wall), on the current configuration. Each wall face gives tau at its
   six P2 nodes from its cell's velocity gradient there (O(h^2) for P2, also on curved cells);
   a node takes the area-weighted mean of its faces'. Over [from, t] the time average and the
   oscillatory shear index (Ku et al. 1985; the sum over the steps, each weighted by dt):
     TAWSS = int |tau| dt / (t - from),  OSI = (1 - |int tau dt| / int |tau| dt) / 2,
   so OSI = 0 for a flow that keeps its direction and 1/2 for a purely oscillating one. The
   values live per mesh point (io/xdmf.h's PointField); owned points hold the whole sums. */
#pragma once

#include "fluid/assembly.h"
#include <string>
#include <vector>

namespace fsi {

struct WallShear {
  std::vector<CellFace>  faces;            /* the walls' faces of the velocity cells */
  std::vector<char>      owned;            /* per point: this rank owns it */
  std::vector<PetscReal> weight;           /* per point: the area of its faces (0: not on a wall) */
  std::vector<PetscReal> position;         /* 3 per point: where it is now */
  std::vector<PetscReal> tau, tawss, osi;  /* 3, 1, 1 per point */
  std::vector<PetscReal> sums;             /* 4 per point: int tau dt, int |tau| dt since `from`; then t - from */
  PetscReal              from = 0;
};

/* The faces of `groups` (comma separated), averaging from time `from`. */
PetscErrorCode WallShearSetUp(DM dm, const FluidForms &fb, const std::string &groups, PetscReal from, WallShear &w);
/* tau at time t from the local state x, and its averages over the steps (of length dt) since `from`. */
PetscErrorCode WallShearCompute(DM dm, const FluidForms &fb, const PetscScalar *x, PetscReal t, PetscReal dt, WallShear &w);
/* Against an exact wall shear stress at time t, over the wall's nodes (a_p: their faces' area):
   the error sqrt(sum_p a_p |tau_p - exact(x_p)|^2) and the exact one's norm sqrt(sum_p a_p |exact(x_p)|^2). */
using ExactShear = void (*)(const PetscReal x[3], PetscReal t, const void *ctx, PetscReal tau[3]);
PetscErrorCode WallShearError(DM dm, const WallShear &w, ExactShear exact, const void *ctx, PetscReal t, PetscReal *error, PetscReal *norm);
/* Over the wall: the largest |tau|, the mean TAWSS (area-weighted), the smallest and largest OSI. */
struct WallShearSummary {
  PetscReal maxTau, meanTawss, minOsi, maxOsi;
};
PetscErrorCode WallShearSummarize(DM dm, const WallShear &w, WallShearSummary &s);

} // namespace fsi
