// SPDX-License-Identifier: BSD-2-Clause
#include "mms.h"
#include "base/ramp.h"

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

void MMSElasticitySolution(const PetscReal x[3], PetscReal, const void *ctx, PetscReal u[3], PetscReal G[9])
{
  const PetscReal a = *(const PetscReal *)ctx;
  PetscReal       H[9];
  MMSElasticityDerivatives(x, a, G, H);
  u[0] = u[1] = u[2] = a * PetscSinReal(PETSC_PI * x[0]) * PetscSinReal(PETSC_PI * x[1]) * PetscSinReal(PETSC_PI * x[2]);
}

/* sigma_rr(Ri) = -p and sigma_rr(Ro) + k u_r(Ro) = 0: two equations for A, B (Cramer) */
Lame LameCylinder(PetscReal E, PetscReal nu, PetscReal p, PetscReal Ri, PetscReal Ro, PetscReal k)
{
  const PetscReal mu = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const PetscReal a11 = 2 * (lambda + mu), a12 = -2 * mu / (Ri * Ri), a21 = 2 * (lambda + mu) + k * Ro, a22 = -2 * mu / (Ro * Ro) + k / Ro;
  const PetscReal det = a11 * a22 - a12 * a21;
  return {-p * a22 / det, p * a21 / det};
}

/* u = (A + B / r^2)(x, y, 0) */
void LameSolution(const PetscReal x[3], PetscReal, const void *ctx, PetscReal u[3], PetscReal G[9])
{
  const Lame     *l  = (const Lame *)ctx;
  const PetscReal r2 = x[0] * x[0] + x[1] * x[1], f = l->A + l->B / r2, g = -2 * l->B / (r2 * r2);
  u[0] = f * x[0], u[1] = f * x[1], u[2] = 0;
  for (int k = 0; k < 9; k++) G[k] = 0;
  G[0] = f + g * x[0] * x[0], G[1] = G[3] = g * x[0] * x[1], G[4] = f + g * x[1] * x[1];
}

void PoiseuilleVelocity(const PetscReal x[3], PetscReal, const void *ctx, PetscReal u[3], PetscReal G[9])
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
  PoiseuilleVelocity(x, 0, &f, u, G);
  const PetscReal p = f.dp * (1 - x[2] / f.L);
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) s[i * 3 + j] = -p * (i == j) + f.mu * (G[i * 3 + j] + G[j * 3 + i]);
  for (int i = 0; i < 3; i++) t[i] = s[i * 3] * n[0] + s[i * 3 + 1] * n[1] + s[i * 3 + 2] * n[2];
}

void PrescribedDisplacement(const PrescribedMotion &m, const PetscReal X[3], PetscReal t, PetscReal d[3], PetscReal G[9])
{
  const PetscReal a = m.a * (m.dynamic ? SmoothRamp(t, m.ramp) : 1.0);
  d[0] = a * (X[0] * X[0] - X[1] * X[1]), d[1] = -2 * a * X[0] * X[1], d[2] = 0;
  for (int k = 0; k < 9; k++) G[k] = 0;
  G[0] = 2 * a * X[0], G[1] = -2 * a * X[1], G[3] = -2 * a * X[1], G[4] = -2 * a * X[0];
}

void PrescribedDisplacementSolution(const PetscReal X[3], PetscReal t, const void *ctx, PetscReal u[3], PetscReal G[9])
{
  PrescribedDisplacement(*(const PrescribedMotion *)ctx, X, t, u, G);
}

PetscErrorCode PrescribedDisplacementBC(PetscInt, PetscReal t, const PetscReal X[], PetscInt nc, PetscScalar *u, void *ctx)
{
  PetscReal d[3], G[9];
  PrescribedDisplacement(*(const PrescribedMotion *)ctx, X, t, d, G);
  for (PetscInt c = 0; c < nc; c++) u[c] = d[c];
  return 0;
}

const char *const FlowMMSKindNames[] = {"trigonometric", "uniform", "FlowMMSKind", "FLOW_MMS_", nullptr};

/* u, G = grad u, p, grad p, and the body force at x, t */
struct FlowState {
  PetscReal u[3], G[9], p, gp[3], f[3];
};

static FlowState FlowMMSState(const FlowMMS &m, const PetscReal x[3], PetscReal t)
{
  FlowState s = {};
  if (m.kind == FLOW_MMS_UNIFORM) {
    s.u[0] = 1, s.u[1] = 0.5, s.u[2] = 0.25;
    return s;
  }
  const PetscReal pi = PETSC_PI;
  PetscReal       rate = 0, sn[3], cs[3];
  const PetscReal a    = m.dynamic ? SmoothRamp(t, m.ramp, &rate) : 1.0;
  for (int d = 0; d < 3; d++) sn[d] = PetscSinReal(pi * x[d]), cs[d] = PetscCosReal(pi * x[d]);
  PetscReal U[3];
  for (int i = 0; i < 3; i++) { /* U_i = sin(pi x_j) sin(pi x_k), j, k the other two */
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    U[i] = sn[j] * sn[k], s.u[i] = a * U[i];
    s.G[i * 3 + i] = 0, s.G[i * 3 + j] = a * pi * cs[j] * sn[k], s.G[i * 3 + k] = a * pi * sn[j] * cs[k];
    s.gp[i] = -a * pi * sn[i] * cs[j] * cs[k];
  }
  s.p = a * cs[0] * cs[1] * cs[2];
  for (int i = 0; i < 3; i++) { /* rho (s' U + (u . grad) u) - mu Lap u + grad p, Lap U = -2 pi^2 U */
    s.f[i] = m.rho * rate * U[i] + 2 * pi * pi * m.mu * s.u[i] + s.gp[i];
    for (int j = 0; j < 3; j++) s.f[i] += m.rho * s.u[j] * s.G[i * 3 + j];
  }
  return s;
}

void FlowMMSForce(const FlowMMS &m, const PetscReal x[3], PetscReal t, PetscReal f[3])
{
  const FlowState s = FlowMMSState(m, x, t);
  for (int i = 0; i < 3; i++) f[i] = s.f[i];
}

void FlowMMSTraction(const FlowMMS &m, const PetscReal x[3], const PetscReal n[3], PetscReal t, PetscReal traction[3])
{
  const FlowState s = FlowMMSState(m, x, t);
  for (int i = 0; i < 3; i++) {
    traction[i] = -s.p * n[i];
    for (int j = 0; j < 3; j++) traction[i] += m.mu * (s.G[i * 3 + j] + s.G[j * 3 + i]) * n[j];
  }
}

PetscErrorCode FlowMMSVelocityBC(PetscInt, PetscReal t, const PetscReal X[], PetscInt nc, PetscScalar *u, void *ctx)
{
  const FlowMMS &m = *(const FlowMMS *)ctx;
  PetscReal      x[3] = {X[0], X[1], X[2]}, d[3], G[9];
  if (m.motion) {
    PrescribedDisplacement(*m.motion, X, t, d, G);
    for (int k = 0; k < 3; k++) x[k] += d[k];
  }
  const FlowState s = FlowMMSState(m, x, t);
  for (PetscInt c = 0; c < nc; c++) u[c] = s.u[c];
  return 0;
}

void FlowMMSVelocity(const PetscReal x[3], PetscReal t, const void *ctx, PetscReal u[3], PetscReal G[9])
{
  const FlowState s = FlowMMSState(*(const FlowMMS *)ctx, x, t);
  for (int k = 0; k < 3; k++) u[k] = s.u[k];
  for (int k = 0; k < 9; k++) G[k] = s.G[k];
}

void FlowMMSPressure(const PetscReal x[3], PetscReal t, const void *ctx, PetscReal p[3], PetscReal G[9])
{
  const FlowState s = FlowMMSState(*(const FlowMMS *)ctx, x, t);
  p[0] = s.p, p[1] = p[2] = 0;
  for (int k = 0; k < 3; k++) G[k] = s.gp[k];
}

} // namespace fsi
