// SPDX-License-Identifier: BSD-2-Clause
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
  PetscBool finiteStrain; /* defined only for det F > 0 (the linear law is defined for every F) */
};

/* Parameters: linear {mu, lambda}; Neo-Hooke {mu, kappa} with
   Psi = mu/2 (J^(-2/3) I1 - 3) + kappa/4 (J^2 - 1 - 2 ln J); arterial {c1, eps1, eps2,
   alpha1, alpha2, a1, a2} (materials.cxx), the fibre directions a1, a2 set per point. */
PetscErrorCode GetMaterialLaw(Material m, MaterialLaw *law);
enum { MATERIAL_MAX_PARAM = 11, ARTERIAL_FIBRES = 5 /* offset of a1 in the parameters */ };

/* The two fibre families of a tube wall with axis z at reference point x: in the tangent plane,
   at +-beta (radians) from the circumferential direction. */
void ArterialFibres(const PetscReal x[3], PetscReal beta, PetscReal a[6]);

} // namespace fsi
