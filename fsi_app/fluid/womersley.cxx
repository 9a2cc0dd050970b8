// SPDX-License-Identifier: BSD-2-Clause
#include "womersley.h"

namespace fsi {

/* sum_m (-z^2/4)^m / (m! (m + n)!) (z/2)^n, n = 0 or 1 */
static std::complex<long double> BesselSeries(std::complex<long double> z, int n)
{
  const std::complex<long double> q = -z * z / 4.0L;
  std::complex<long double>       term = n ? z / 2.0L : 1.0L, sum = term;
  for (int m = 1; m < 400; m++) {
    term *= q / ((long double)m * (long double)(m + n));
    sum += term;
    if (std::abs(term) < 1e-21L * std::abs(sum) && m > std::abs(z)) break;
  }
  return sum;
}

std::complex<long double> BesselJ0(std::complex<long double> z) { return BesselSeries(z, 0); }
std::complex<long double> BesselJ1(std::complex<long double> z) { return BesselSeries(z, 1); }

void Womersley::SetUp(const std::vector<PetscReal> &ab, PetscReal T, PetscReal radius, PetscReal rho, PetscReal mu)
{
  const std::complex<long double> i32 = std::complex<long double>(-1.0L, 1.0L) / std::sqrt(2.0L); /* i^(3/2) */
  const size_t                    K   = ab.size() / 2;
  R = radius, omega = 2 * PETSC_PI / T;
  c.assign(K + 1, 0.0), lambda.assign(K + 1, 0.0L);
  c[0] = ab[0] / (PETSC_PI * R * R / 2);
  for (size_t k = 1; k <= K; k++) {
    const std::complex<PetscReal> Qk(ab[2 * k - 1], -ab[2 * k]); /* a cos + b sin = Re (a - i b) e^(i w t) */
    lambda[k]                             = i32 * (long double)(R * PetscSqrtReal(k * omega * rho / mu));
    const std::complex<long double> ratio = 2.0L * BesselJ1(lambda[k]) / (lambda[k] * BesselJ0(lambda[k]));
    const std::complex<PetscReal>   area  = PETSC_PI * R * R * std::complex<PetscReal>(1.0L - ratio);
    c[k]                                  = Qk / area;
  }
}

std::complex<PetscReal> Womersley::Shape(PetscInt k, PetscReal r) const
{
  if (k == 0) return 1 - r * r / (R * R);
  return std::complex<PetscReal>(1.0L - BesselJ0(lambda[k] * (long double)(r / R)) / BesselJ0(lambda[k]));
}

PetscReal Womersley::Velocity(PetscReal r, PetscReal t) const
{
  PetscReal u = 0;
  for (size_t k = 0; k < c.size(); k++) u += std::real(c[k] * Shape((PetscInt)k, r) * std::exp(std::complex<PetscReal>(0, k * omega * t)));
  return u;
}

PetscReal Womersley::RadialDerivative(PetscReal r, PetscReal t) const
{
  PetscReal du = 0;
  for (size_t k = 0; k < c.size(); k++) {
    const std::complex<PetscReal> dg = k == 0 ? std::complex<PetscReal>(-2 * r / (R * R)) : std::complex<PetscReal>(lambda[k] / (long double)R * BesselJ1(lambda[k] * (long double)(r / R)) / BesselJ0(lambda[k]));
    du += std::real(c[k] * dg * std::exp(std::complex<PetscReal>(0, k * omega * t)));
  }
  return du;
}

} // namespace fsi
