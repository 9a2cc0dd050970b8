// SPDX-License-Identifier: BSD-2-Clause
/* The fluid block: incompressible Navier-Stokes in ALE form, P2 velocity and P1 pressure
   (Taylor-Hood) on the fluid region, on the current configuration x = X + d_f(X) of a mesh
   moved by the P2 mesh displacement d_f (or on the fixed mesh):
     R_u(v) = int_{Omega_t} rho (d_t u + ((u - w) . grad) u) . v + 2 mu eps(u) : eps(v) - p div v - f . v
              - int_{faces_t} t . v
              - beta rho int_{outlets_t} (u . n)_- u . v
     R_p(q) = - int_{Omega_t} q div u
   with d_t u the fully implicit difference (core/time_history.h) of the nodal values, which
   move with the mesh (the time derivative at fixed X), w the same difference of d_f (the mesh
   velocity), t a prescribed traction on groups of faces (natural: stress-free) and f a body
   force (manufactured solutions). (u . n)_- = min(u . n, 0) is the backflow through an outlet
   (Esmaily Moghadam et al. 2011): the term takes out the kinetic energy that fluid re-entering
   through a traction condition brings in (all of it for beta >= 1/2; svMultiPhysics' default
   0.2 suffices in practice) and is zero while the flow leaves; its derivative in d_f is left
   out (the outlets' planes do not move). The Jacobian is exact in (u, p), convection included, and
   holds the shape derivatives (in d_f: the moved geometry, the mesh velocity, the moved
   traction faces) if asked: in closed form for the volume terms, by forward differences of
   the face residual for the traction faces and of the body force in x; without them
   Newton is a quasi-Newton method on a moving mesh (-snes_mf_operator restores the exact
   derivative with this matrix as preconditioner). */
#pragma once

#include "discretization/cells.h"
#include "core/sparsity.h"
#include "core/time_history.h"
#include <functional>
#include <petscsnes.h>

namespace fsi {

/* traction t(x, outward normal n, time) on a group of faces, in the current configuration */
using Traction  = std::function<void(const PetscReal x[3], const PetscReal n[3], PetscReal t, PetscReal traction[3])>;
using BodyForce = std::function<void(const PetscReal x[3], PetscReal t, PetscReal f[3])>;

struct TractionGroup {
  std::vector<CellFace> faces; /* faces of the velocity cells */
  Traction              traction;
};

struct FluidForms {
  PetscReal                  rho = 1, mu = 0.03;
  FieldCells                 velocity, pressure; /* the same cells, P2 (3 components) and P1 */
  const FieldCells          *mesh = nullptr;     /* d_f on the same cells when the mesh moves */
  P2Rule                     rule;               /* degree 5: the convective term exactly on a fixed mesh */
  FaceRule                   faceRule;
  std::vector<TractionGroup> tractions;
  std::vector<CellFace>      backflow;         /* the outlets' faces, where backflow is damped */
  PetscReal                  backflowBeta = 0; /* beta of the backflow term */
  BodyForce                  force;
  PetscReal                  time    = 0; /* of the step being solved: tractions, body force */
  const TimeHistory         *history = nullptr;
  SNES                       snes    = nullptr; /* told when a moved cell inverts (J <= 0) */
  PetscInt                   inverted = 0;      /* quadrature points with J <= 0 in the last residual */
  PetscBool                  shapeDerivatives = PETSC_FALSE; /* D_{d_f} R in the Jacobian */
};

/* Its rows of the residual (added into the local f; the residual records inverted cells in
   the forms) and of the Jacobian, for the local state x. */
PetscErrorCode FluidResidual(FluidForms &fb, const PetscScalar *x, PetscScalar *f);
PetscErrorCode FluidJacobian(const FluidForms &fb, const PetscScalar *x, Mat P);
/* the entries FluidJacobian inserts */
void FluidCouplings(const FluidForms &fb, Sparsity &s);

/* Over the faces in the current configuration, from the local state x: v = (int u . n da, int p da,
   int da), summed over the ranks. */
PetscErrorCode FluidFaceIntegrals(DM dm, const FluidForms &fb, const std::vector<CellFace> &faces, const PetscScalar *x, PetscReal v[3]);
/* int u . n da over the faces (in the current configuration): the flux through an outlet. X is global. */
PetscErrorCode FluidFlux(DM dm, const FluidForms &fb, const std::vector<CellFace> &faces, Vec X, PetscReal *flux);
/* int |v|^2 dA over the faces in the reference configuration, v a P2 vector field on the fluid's
   cells (the mesh displacement fb.mesh, say), for the local state x; summed over the ranks. */
PetscErrorCode FluidFaceNormSquared(DM dm, const FluidForms &fb, const FieldCells &v, const std::vector<CellFace> &faces, const PetscScalar *x, PetscReal *norm2);

} // namespace fsi
