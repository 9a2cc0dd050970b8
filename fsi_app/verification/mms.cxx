#include "mms.h"

namespace fsi {

PetscErrorCode MMSElasticityExact(PetscInt dim, PetscReal, const PetscReal x[], PetscInt nc, PetscScalar *u, void *)
{
  PetscReal phi = 1;
  for (PetscInt d = 0; d < dim; d++) phi *= PetscSinReal(PETSC_PI * x[d]);
  for (PetscInt c = 0; c < nc; c++) u[c] = phi;
  return 0;
}

/* div sigma = (lambda + mu) grad div d + mu lap d with d_c = phi for every c:
   lap d_c = -3 pi^2 phi, (grad div d)_j = sum_k d_j d_k phi. */
void MMSElasticityDivStress(const PetscReal x[3], PetscReal mu, PetscReal lambda, PetscReal div[3])
{
  const PetscReal pi = PETSC_PI;
  PetscReal       s[3], co[3], phi = 1;
  for (int d = 0; d < 3; d++) s[d] = PetscSinReal(pi * x[d]), co[d] = PetscCosReal(pi * x[d]), phi *= s[d];
  for (int j = 0; j < 3; j++) {
    PetscReal graddiv = -pi * pi * phi;
    for (int k = 0; k < 3; k++)
      if (k != j) graddiv += pi * pi * co[j] * co[k] * s[3 - j - k];
    div[j] = (lambda + mu) * graddiv - 3 * mu * pi * pi * phi;
  }
}

Lame LameCylinder(PetscReal E, PetscReal nu, PetscReal p, PetscReal Ri, PetscReal Ro)
{
  const PetscReal c = (1 + nu) * p * Ri * Ri / (E * (Ro * Ro - Ri * Ri));
  return {c * (1 - 2 * nu), c * Ro * Ro};
}

PetscErrorCode LameDisplacement(PetscInt, PetscReal, const PetscReal x[], PetscInt nc, PetscScalar *u, void *ctx)
{
  const Lame     *l  = (const Lame *)ctx;
  const PetscReal r2 = x[0] * x[0] + x[1] * x[1], ur_over_r = l->A + l->B / r2;
  u[0] = ur_over_r * x[0], u[1] = ur_over_r * x[1];
  for (PetscInt c = 2; c < nc; c++) u[c] = 0;
  return 0;
}

} // namespace fsi
