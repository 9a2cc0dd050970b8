/* The fluid block: incompressible Navier-Stokes, P2 velocity and P1 pressure (Taylor-Hood) on
   the fluid region, on a fixed mesh for now (the ALE terms arrive with the geometry block):
     R_u(v) = int rho (d_t u + (u . grad) u) . v + 2 mu eps(u) : eps(v) - p div v - int_faces t . v
     R_p(q) = - int q div u
   with d_t u the fully implicit difference of solver/time_history.h and t a prescribed
   traction on groups of faces (natural: stress-free). Newton's Jacobian is exact (convection
   included), so Newton converges quadratically up to the Reynolds numbers where it converges. */
#pragma once

#include "discretization/cells.h"
#include "solver/time_history.h"
#include <functional>
#include <petscsnes.h>

namespace fsi {

/* traction t(x, outward normal n, time) on a group of faces */
using Traction = std::function<void(const PetscReal x[3], const PetscReal n[3], PetscReal t, PetscReal traction[3])>;

struct TractionGroup {
  std::vector<CellFace> faces; /* faces of the velocity cells */
  Traction              traction;
};

struct FluidBlock {
  PetscReal                  rho = 1, mu = 0.03;
  FieldCells                 velocity, pressure; /* the same cells, P2 (3 components) and P1 */
  P2Rule                     rule;               /* degree 5: the convective term exactly */
  FaceRule                   faceRule;
  PetscReal                  mass[100];
  std::vector<TractionGroup> tractions;
  PetscReal                  time    = 0; /* of the step being solved: for the tractions */
  const TimeHistory         *history = nullptr;
};

PetscErrorCode FluidResidual(DM dm, Vec X, Vec F, void *ctx);
PetscErrorCode FluidJacobian(DM dm, Vec X, Mat J, Mat P, void *ctx);

/* int_faces u . n over the faces of group g (the flux through an outlet) */
PetscErrorCode FluidFlux(DM dm, const FluidBlock &fb, const std::vector<CellFace> &faces, Vec X, PetscReal *flux);

} // namespace fsi
