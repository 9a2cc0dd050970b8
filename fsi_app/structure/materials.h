/* Constitutive laws of the wall: the first Piola-Kirchhoff stress P(F) and its exact
   derivative A = dP/dF (A[((i*3 + j)*3 + k)*3 + l] = dP_ij/dF_kl), F = I + grad d. */
#pragma once

#include <petscsys.h>

namespace fsi {

enum Material { LINEAR_ELASTIC = 0, NEO_HOOKE = 1, ARTERIAL = 2 };
extern const char *const MaterialNames[];

struct MaterialLaw {
  void (*stress)(const PetscReal F[9], const PetscReal *param, PetscReal P[9]);
  void (*tangent)(const PetscReal F[9], const PetscReal *param, PetscReal A[81]);
};

/* Parameters: linear {mu, lambda}; Neo-Hooke {mu, kappa} with
   Psi = mu/2 (J^(-2/3) I1 - 3) + kappa/4 (J^2 - 1 - 2 ln J). */
PetscErrorCode GetMaterialLaw(Material m, MaterialLaw *law);

} // namespace fsi
