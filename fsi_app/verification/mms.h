// SPDX-License-Identifier: BSD-2-Clause
/* Exact solutions: a manufactured one (any material: its body force comes from the law's
   tangent) and Lame's thick-walled cylinder. */
#pragma once

#include <petscsys.h>

namespace fsi {

/* d = a phi (1, 1, 1), phi = sin(pi x) sin(pi y) sin(pi z) on the unit cube (zero on its
   boundary); ctx points to a. The signature of PETSc's boundary-value functions. */
PetscErrorCode MMSElasticityExact(PetscInt dim, PetscReal t, const PetscReal x[], PetscInt nc, PetscScalar *u, void *ctx);

/* Its gradient G[i*3+j] = d d_i / dx_j and the Hessian a d2 phi / dx_j dx_l (every component). */
void MMSElasticityDerivatives(const PetscReal x[3], PetscReal a, PetscReal G[9], PetscReal H[9]);

/* The body force b = -div P(F) that makes the manufactured d a solution of law P with tangent
   A: b_i = -sum_jkl A_ijkl d2 d_k / dx_j dx_l. */
void MMSBodyForce(const PetscReal x[3], PetscReal a, void (*tangent)(const PetscReal[9], const PetscReal *, PetscReal[81]), const PetscReal *param, PetscReal b[3]);

/* Lame's thick-walled cylinder (axis z) under internal pressure p, plane strain, its outer
   surface held by a spring k (sigma_rr(Ro) = -k u_r(Ro); k = 0: free): u = (A r + B / r) e_r with
   sigma_rr = 2 (lambda + mu) A - 2 mu B / r^2. Free: A = (1+nu)(1-2nu) p Ri^2 / (E (Ro^2 - Ri^2)),
   B = (1+nu) p Ri^2 Ro^2 / (E (Ro^2 - Ri^2)). */
struct Lame {
  PetscReal A, B;
};
Lame LameCylinder(PetscReal E, PetscReal nu, PetscReal p, PetscReal Ri, PetscReal Ro, PetscReal k = 0);

/* Hagen-Poiseuille flow along z in a tube of radius R, length L: u_z = G (R^2 - r^2) / (4 mu),
   p = dp (1 - z / L), G = dp / L; flux pi R^4 dp / (8 mu L). */
struct Poiseuille {
  PetscReal R, L, dp, mu;
};
/* sigma n = (-p I + mu (grad u + grad u^T)) n of the exact flow */
void PoiseuilleTraction(const Poiseuille &f, const PetscReal x[3], const PetscReal n[3], PetscReal t[3]);
void PoiseuilleVelocity(const PetscReal x[3], PetscReal t, const void *ctx, PetscReal u[3], PetscReal G[9]);

/* The prescribed interface displacement d = a s(t) (x^2 - y^2, -2 x y, 0): harmonic, zero in z
   on planes z = c, with s the smooth ramp of base/ramp.h (s = 1 in statics). */
struct PrescribedMotion {
  PetscReal a, ramp;
  PetscBool dynamic;
};
void           PrescribedDisplacement(const PrescribedMotion &m, const PetscReal X[3], PetscReal t, PetscReal d[3], PetscReal G[9]);
PetscErrorCode PrescribedDisplacementBC(PetscInt dim, PetscReal t, const PetscReal X[], PetscInt nc, PetscScalar *u, void *ctx);
void           PrescribedDisplacementSolution(const PetscReal X[3], PetscReal t, const void *ctx, PetscReal u[3], PetscReal G[9]);

/* A manufactured flow on a fixed or moving mesh. Trigonometric: u = s(t) U(x), p = s(t) P(x),
   U = (sin(pi y) sin(pi z), sin(pi z) sin(pi x), sin(pi x) sin(pi y)) (divergence-free: no
   component depends on its own coordinate), P = cos(pi x) cos(pi y) cos(pi z), s the smooth ramp
   of base/ramp.h over `ramp` (s = 1 in statics). Uniform: u = (1, 1/2, 1/4), p = 0 at all times
   (geometric conservation: it must stay so on any moving mesh). The body force
   f = rho (d_t u + (u . grad) u) - mu Lap u + grad p, with d_t at fixed x, makes either a
   solution of the ALE equations whatever the mesh does. */
enum FlowMMSKind { FLOW_MMS_TRIGONOMETRIC = 0, FLOW_MMS_UNIFORM = 1 };
extern const char *const FlowMMSKindNames[];
struct FlowMMS {
  FlowMMSKind             kind = FLOW_MMS_TRIGONOMETRIC;
  PetscReal               rho = 1, mu = 1, ramp = 0;
  PetscBool               dynamic = PETSC_FALSE;
  const PrescribedMotion *motion  = nullptr; /* where the boundary nodes are at time t (nullptr: fixed) */
};
void FlowMMSForce(const FlowMMS &m, const PetscReal x[3], PetscReal t, PetscReal f[3]);
void FlowMMSTraction(const FlowMMS &m, const PetscReal x[3], const PetscReal n[3], PetscReal t, PetscReal traction[3]);
/* the exact velocity at the node X moved to X + d(X, t): PETSc's boundary-value signature */
PetscErrorCode FlowMMSVelocityBC(PetscInt dim, PetscReal t, const PetscReal X[], PetscInt nc, PetscScalar *u, void *ctx);

/* Value and gradient of an exact solution at x (and time t): the form verification/errors.h integrates. */
void MMSElasticitySolution(const PetscReal x[3], PetscReal t, const void *ctx, PetscReal u[3], PetscReal G[9]);
void LameSolution(const PetscReal x[3], PetscReal t, const void *ctx, PetscReal u[3], PetscReal G[9]);
void FlowMMSVelocity(const PetscReal x[3], PetscReal t, const void *ctx, PetscReal u[3], PetscReal G[9]);
void FlowMMSPressure(const PetscReal x[3], PetscReal t, const void *ctx, PetscReal p[3], PetscReal G[9]);

} // namespace fsi
