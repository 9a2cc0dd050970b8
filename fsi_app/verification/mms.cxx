#include "mms.h"

namespace fsi {

PetscErrorCode MMSElasticityExact(PetscInt dim, PetscReal, const PetscReal x[], PetscInt nc, PetscScalar *u, void *ctx)
{
  PetscReal phi = *(const PetscReal *)ctx;
  for (PetscInt d = 0; d < dim; d++) phi *= PetscSinReal(PETSC_PI * x[d]);
  for (PetscInt c = 0; c < nc; c++) u[c] = phi;
  return 0;
}

void MMSElasticityDerivatives(const PetscReal x[3], PetscReal a, PetscReal G[9], PetscReal H[9])
{
  const PetscReal pi = PETSC_PI;
  PetscReal       s[3], c[3];
  for (int d = 0; d < 3; d++) s[d] = PetscSinReal(pi * x[d]), c[d] = PetscCosReal(pi * x[d]);
  for (int j = 0; j < 3; j++) {
    const int k = (j + 1) % 3, l = (j + 2) % 3;
    for (int i = 0; i < 3; i++) G[i * 3 + j] = a * pi * c[j] * s[k] * s[l];
    H[j * 3 + j] = -a * pi * pi * s[0] * s[1] * s[2];
    H[j * 3 + k] = H[k * 3 + j] = a * pi * pi * c[j] * c[k] * s[l];
  }
}

void MMSBodyForce(const PetscReal x[3], PetscReal a, void (*tangent)(const PetscReal[9], const PetscReal *, PetscReal[81]), const PetscReal *param, PetscReal b[3])
{
  PetscReal F[9], H[9], A[81];
  MMSElasticityDerivatives(x, a, F, H);
  for (int d = 0; d < 3; d++) F[d * 3 + d] += 1;
  tangent(F, param, A);
  for (int i = 0; i < 3; i++) {
    b[i] = 0;
    for (int j = 0; j < 3; j++)
      for (int k = 0; k < 3; k++)
        for (int l = 0; l < 3; l++) b[i] -= A[((i * 3 + j) * 3 + k) * 3 + l] * H[j * 3 + l];
  }
}

void MMSElasticitySolution(const PetscReal x[3], const void *ctx, PetscReal u[3], PetscReal G[9])
{
  const PetscReal a = *(const PetscReal *)ctx;
  PetscReal       H[9];
  MMSElasticityDerivatives(x, a, G, H);
  u[0] = u[1] = u[2] = a * PetscSinReal(PETSC_PI * x[0]) * PetscSinReal(PETSC_PI * x[1]) * PetscSinReal(PETSC_PI * x[2]);
}

Lame LameCylinder(PetscReal E, PetscReal nu, PetscReal p, PetscReal Ri, PetscReal Ro)
{
  const PetscReal c = (1 + nu) * p * Ri * Ri / (E * (Ro * Ro - Ri * Ri));
  return {c * (1 - 2 * nu), c * Ro * Ro};
}

/* u = (A + B / r^2)(x, y, 0) */
void LameSolution(const PetscReal x[3], const void *ctx, PetscReal u[3], PetscReal G[9])
{
  const Lame     *l  = (const Lame *)ctx;
  const PetscReal r2 = x[0] * x[0] + x[1] * x[1], f = l->A + l->B / r2, g = -2 * l->B / (r2 * r2);
  u[0] = f * x[0], u[1] = f * x[1], u[2] = 0;
  for (int k = 0; k < 9; k++) G[k] = 0;
  G[0] = f + g * x[0] * x[0], G[1] = G[3] = g * x[0] * x[1], G[4] = f + g * x[1] * x[1];
}

void PoiseuilleVelocity(const PetscReal x[3], const void *ctx, PetscReal u[3], PetscReal G[9])
{
  const Poiseuille &f = *(const Poiseuille *)ctx;
  const PetscReal   c = f.dp / f.L / (4 * f.mu);
  u[0] = u[1] = 0, u[2] = c * (f.R * f.R - x[0] * x[0] - x[1] * x[1]);
  for (int k = 0; k < 9; k++) G[k] = 0;
  G[6] = -2 * c * x[0], G[7] = -2 * c * x[1];
}

void PoiseuilleTraction(const Poiseuille &f, const PetscReal x[3], const PetscReal n[3], PetscReal t[3])
{
  PetscReal u[3], G[9], s[9];
  PoiseuilleVelocity(x, &f, u, G);
  const PetscReal p = f.dp * (1 - x[2] / f.L);
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) s[i * 3 + j] = -p * (i == j) + f.mu * (G[i * 3 + j] + G[j * 3 + i]);
  for (int i = 0; i < 3; i++) t[i] = s[i * 3] * n[0] + s[i * 3 + 1] * n[1] + s[i * 3 + 2] * n[2];
}

} // namespace fsi
