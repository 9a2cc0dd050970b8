/* Manufactured solutions: exact fields and the body forces that make them solutions. */
#pragma once

#include <petscsys.h>

namespace fsi {

/* d = sin(pi x) sin(pi y) sin(pi z) (1, 1, 1) on the unit cube (zero on its boundary); the
   signature of PETSc's projection and error functions. */
PetscErrorCode MMSElasticityExact(PetscInt dim, PetscReal t, const PetscReal x[], PetscInt nc, PetscScalar *u, void *ctx);

/* div sigma(d) for linear elasticity with Lame parameters mu, lambda: the body force b with
   -div sigma = b is its negative. */
void MMSElasticityDivStress(const PetscReal x[3], PetscReal mu, PetscReal lambda, PetscReal div[3]);

/* Lame's thick-walled cylinder (axis z) under internal pressure p, plane strain:
   u = (A r + B / r) e_r with A = (1+nu)(1-2nu) p Ri^2 / (E (Ro^2 - Ri^2)), B = (1+nu) p Ri^2 Ro^2 / (E (Ro^2 - Ri^2)). */
struct Lame {
  PetscReal A, B;
};
Lame LameCylinder(PetscReal E, PetscReal nu, PetscReal p, PetscReal Ri, PetscReal Ro);
PetscErrorCode LameDisplacement(PetscInt dim, PetscReal t, const PetscReal x[], PetscInt nc, PetscScalar *u, void *ctx);

} // namespace fsi
