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

/* Lame's thick-walled cylinder (axis z) under internal pressure p, plane strain:
   u = (A r + B / r) e_r with A = (1+nu)(1-2nu) p Ri^2 / (E (Ro^2 - Ri^2)), B = (1+nu) p Ri^2 Ro^2 / (E (Ro^2 - Ri^2)). */
struct Lame {
  PetscReal A, B;
};
Lame LameCylinder(PetscReal E, PetscReal nu, PetscReal p, PetscReal Ri, PetscReal Ro);

/* Hagen-Poiseuille flow along z in a tube of radius R, length L: u_z = G (R^2 - r^2) / (4 mu),
   p = dp (1 - z / L), G = dp / L; flux pi R^4 dp / (8 mu L). */
struct Poiseuille {
  PetscReal R, L, dp, mu;
};
/* sigma n = (-p I + mu (grad u + grad u^T)) n of the exact flow */
void PoiseuilleTraction(const Poiseuille &f, const PetscReal x[3], const PetscReal n[3], PetscReal t[3]);
void PoiseuilleVelocity(const PetscReal x[3], const void *ctx, PetscReal u[3], PetscReal G[9]);

/* Value and gradient of an exact solution at x: the form verification/errors.h integrates. */
void MMSElasticitySolution(const PetscReal x[3], const void *ctx, PetscReal u[3], PetscReal G[9]);
void LameSolution(const PetscReal x[3], const void *ctx, PetscReal u[3], PetscReal G[9]);

} // namespace fsi
