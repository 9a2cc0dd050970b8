// SPDX-License-Identifier: BSD-2-Clause
/* Womersley's flow: fully developed pulsatile flow in a rigid straight tube of radius R driven
   by a flow rate Q(t) = Re sum_k Q_k e^(i k w t) (Womersley 1955). Its axial velocity is
     u(r, t) = Re sum_k c_k g_k(r) e^(i k w t),
     g_0 = 1 - r^2/R^2,  g_k = 1 - J_0(Lambda_k r/R) / J_0(Lambda_k),  Lambda_k = i^(3/2) alpha_k,
     alpha_k = R sqrt(k w rho / mu) (Womersley's number of harmonic k),
   with c_k = Q_k / int g_k da; int g_0 da = pi R^2 / 2, int g_k da = pi R^2 (1 - 2 J_1(Lambda_k) /
   (Lambda_k J_0(Lambda_k))). J_0 and J_1 of complex argument by their power series in long
   double (|Lambda| < 40: the terms' cancellation costs at most 17 of its 19 digits there). */
#pragma once

#include <petscsys.h>
#include <complex>
#include <vector>

namespace fsi {

struct Womersley {
  PetscReal                              R = 0, omega = 0; /* radius, angular frequency of the first harmonic */
  std::vector<std::complex<PetscReal>>   c;                /* c_k, k = 0..K */
  std::vector<std::complex<long double>> lambda;           /* Lambda_k (lambda[0] unused) */

  /* the harmonics of Q (a_0, a_1, b_1, ...: Waveform::Harmonics) in a tube of radius R,
     period T, for a fluid of density rho and viscosity mu; c_k from the exact integrals */
  void           SetUp(const std::vector<PetscReal> &ab, PetscReal T, PetscReal R, PetscReal rho, PetscReal mu);
  PetscReal      Velocity(PetscReal r, PetscReal t) const;
  /* d u / d r */
  PetscReal      RadialDerivative(PetscReal r, PetscReal t) const;
  /* g_k(r) */
  std::complex<PetscReal> Shape(PetscInt k, PetscReal r) const;
};

/* J_0(z) and J_1(z) */
std::complex<long double> BesselJ0(std::complex<long double> z);
std::complex<long double> BesselJ1(std::complex<long double> z);

} // namespace fsi
