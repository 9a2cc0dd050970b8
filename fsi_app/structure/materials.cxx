// SPDX-License-Identifier: BSD-2-Clause
#include "materials.h"
#include "dual.h"

namespace fsi {

const char *const MaterialNames[] = {"linear", "neohooke", "arterial", "Material", "", nullptr};

/* Linear elasticity: P = lambda tr(eps) I + 2 mu eps, eps = sym(F - I). */
static void StressLinear(const PetscReal F[9], const PetscReal *p, PetscReal P[9])
{
  const PetscReal mu = p[0], lambda = p[1], tr = F[0] + F[4] + F[8] - 3;
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) P[i * 3 + j] = mu * (F[i * 3 + j] + F[j * 3 + i] - 2 * (i == j)) + (i == j ? lambda * tr : 0.0);
}

static void TangentLinear(const PetscReal[9], const PetscReal *p, PetscReal A[81])
{
  const PetscReal mu = p[0], lambda = p[1];
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      for (int k = 0; k < 3; k++)
        for (int l = 0; l < 3; l++) A[((i * 3 + j) * 3 + k) * 3 + l] = lambda * (i == j) * (k == l) + mu * ((i == k) * (j == l) + (i == l) * (j == k));
}

/* Hyperelastic laws are written once, as their energy Psi(C) of the right Cauchy-Green tensor
   C = F^T F, stored as c = (C00, C11, C22, C01, C02, C12); forward-mode differentiation gives
   dPsi/dc and d2Psi/dc2 exact to round-off (6 directions rather than 9 for Psi(F): twice as fast). */
template <class S>
static S Det(const S c[6])
{
  return c[0] * (c[1] * c[2] - c[5] * c[5]) - c[3] * (c[3] * c[2] - c[5] * c[4]) + c[4] * (c[3] * c[5] - c[1] * c[4]);
}

/* Psi = mu/2 (J^(-2/3) I1 - 3) + kappa/4 (J^2 - 1 - 2 ln J), J^2 = det C */
template <class S>
struct NeoHookeEnergy {
  static S Eval(const S c[6], const PetscReal *p)
  {
    const S I3 = Det(c);
    return p[0] / 2 * ((c[0] + c[1] + c[2]) * pow(I3, -1.0 / 3.0) - 3.0) + p[1] / 4 * (I3 - 1.0 - log(I3));
  }
};

/* The polyconvex arterial wall of Balzani et al. (FSI.md): isotropic matrix, a penalty on the
   volume change, and two fibre families a (reference, unit) that only resist stretching:
   Psi = c1 (I1 I3^(-1/3) - 3) + eps1 (I3^eps2 + I3^(-eps2) - 2)
         + sum_a alpha1 <I1 J4_a - J5_a - 2>^alpha2, J4 = a.C a, J5 = |C a|^2.
   p = {c1, eps1, eps2, alpha1, alpha2, a1 (3), a2 (3)}. */
template <class S>
struct ArterialEnergy {
  static S Eval(const S c[6], const PetscReal *p)
  {
    const S I1 = c[0] + c[1] + c[2], I3 = Det(c);
    S       psi = p[0] * (I1 * pow(I3, -1.0 / 3.0) - 3.0) + p[1] * (pow(I3, p[2]) + pow(I3, -p[2]) - 2.0);
    for (int f = 0; f < 2; f++) {
      const PetscReal *a     = &p[ARTERIAL_FIBRES + 3 * f];
      const S          Ca[3] = {c[0] * a[0] + c[3] * a[1] + c[4] * a[2], c[3] * a[0] + c[1] * a[1] + c[5] * a[2], c[4] * a[0] + c[5] * a[1] + c[2] * a[2]};
      const S          J4 = a[0] * Ca[0] + a[1] * Ca[1] + a[2] * Ca[2], J5 = Ca[0] * Ca[0] + Ca[1] * Ca[1] + Ca[2] * Ca[2];
      const S          m  = I1 * J4 - J5 - 2.0;
      if (m > 0) psi = psi + p[3] * pow(m, p[4]); /* the Macaulay bracket: fibres carry no compression */
    }
    return psi;
  }
};

void ArterialFibres(const PetscReal x[3], PetscReal beta, PetscReal a[6])
{
  const PetscReal r    = std::sqrt(x[0] * x[0] + x[1] * x[1]);
  const PetscReal t[3] = {r > 0 ? -x[1] / r : 1.0, r > 0 ? x[0] / r : 0.0, 0}; /* circumferential */
  for (int d = 0; d < 3; d++) a[d] = std::cos(beta) * t[d] + (d == 2) * std::sin(beta), a[3 + d] = std::cos(beta) * t[d] - (d == 2) * std::sin(beta);
}

static const int Pair[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
static const int Voigt[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};

static void RightCauchyGreen(const PetscReal F[9], PetscReal c[6])
{
  for (int k = 0; k < 6; k++) c[k] = F[Pair[k][0]] * F[Pair[k][1]] + F[3 + Pair[k][0]] * F[3 + Pair[k][1]] + F[6 + Pair[k][0]] * F[6 + Pair[k][1]];
}

/* S = 2 dPsi/dC: an off-diagonal c_k stands for C_IJ and C_JI, so S_IJ = dPsi/dc_k there. */
static void SecondPiola(const PetscReal g[6], PetscReal S[9])
{
  for (int I = 0; I < 3; I++)
    for (int J = 0; J < 3; J++) S[I * 3 + J] = (I == J ? 2.0 : 1.0) * g[Voigt[I][J]];
}

/* P = F S */
static void FirstPiola(const PetscReal F[9], const PetscReal S[9], PetscReal P[9])
{
  for (int i = 0; i < 3; i++)
    for (int J = 0; J < 3; J++) P[i * 3 + J] = F[i * 3] * S[J] + F[i * 3 + 1] * S[3 + J] + F[i * 3 + 2] * S[6 + J];
}

template <template <class> class Energy>
static void StressFromEnergy(const PetscReal F[9], const PetscReal *p, PetscReal P[9])
{
  using D = Dual<6>;
  PetscReal c[6], g[6], S[9];
  D         cd[6];
  RightCauchyGreen(F, c);
  for (int k = 0; k < 6; k++) cd[k] = D(c[k]), cd[k].d[k] = 1;
  const D psi = Energy<D>::Eval(cd, p);
  for (int k = 0; k < 6; k++) g[k] = psi.d[k];
  SecondPiola(g, S);
  FirstPiola(F, S, P);
}

/* dPsi/dc (g) and d2Psi/dc2 (H) by nested forward-mode differentiation. */
template <template <class> class Energy>
struct EnergyDerivatives {
  static void Eval(const PetscReal c[6], const PetscReal *p, PetscReal g[6], PetscReal H[6][6])
  {
    using D  = Dual<6>;
    using DD = Dual<6, D>;
    DD cd[6];
    for (int k = 0; k < 6; k++) {
      D inner(c[k]);
      inner.d[k] = 1;
      cd[k]      = DD(inner, 0);
      cd[k].d[k] = D(1.0);
    }
    const DD psi = Energy<DD>::Eval(cd, p);
    for (int a = 0; a < 6; a++) {
      g[a] = psi.d[a].v;
      for (int b = 0; b < 6; b++) H[a][b] = psi.d[a].d[b];
    }
  }
};

/* The arterial energy's by the chain rule through its invariants, about 10 times cheaper than
   nested duals (the wall's tangent at every quadrature point of every Newton step): for each
   term f(I) of invariants I(c), grad f = f' grad I and H f = f'' grad I grad I^T + f' H I, with
   grad I1 = (1,1,1,0,0,0); I3 = det C: grad the cofactors, H linear in c; J4 = a.C a linear;
   J5 = |B c|^2 with (B c)_i = (C a)_i, so H J5 = 2 B^T B. The same g and H as the energy's
   nested duals to round-off. */
template <>
struct EnergyDerivatives<ArterialEnergy> {
  static void AddOuter(PetscReal H[6][6], PetscReal s, const PetscReal u[6], const PetscReal v[6])
  {
    for (int a = 0; a < 6; a++)
      for (int b = 0; b < 6; b++) H[a][b] += s * u[a] * v[b];
  }
  static void Eval(const PetscReal c[6], const PetscReal *p, PetscReal g[6], PetscReal H[6][6])
  {
    const PetscReal I1 = c[0] + c[1] + c[2], I3 = Det(c), e = p[2];
    const PetscReal dI1[6] = {1, 1, 1, 0, 0, 0};
    const PetscReal dI3[6] = {c[1] * c[2] - c[5] * c[5], c[0] * c[2] - c[4] * c[4], c[0] * c[1] - c[3] * c[3], 2 * (c[4] * c[5] - c[2] * c[3]), 2 * (c[3] * c[5] - c[1] * c[4]), 2 * (c[3] * c[4] - c[0] * c[5])};
    const PetscReal HI3[6][6] = {{0, c[2], c[1], 0, 0, -2 * c[5]}, {c[2], 0, c[0], 0, -2 * c[4], 0}, {c[1], c[0], 0, -2 * c[3], 0, 0}, {0, 0, -2 * c[3], -2 * c[2], 2 * c[5], 2 * c[4]}, {0, -2 * c[4], 0, 2 * c[5], -2 * c[1], 2 * c[3]}, {-2 * c[5], 0, 0, 2 * c[4], 2 * c[3], -2 * c[0]}};
    /* c1 I1 q - 3 c1, q = I3^(-1/3); eps1 (I3^e + I3^(-e) - 2) */
    const PetscReal q = 1 / std::cbrt(I3), dq = -q / (3 * I3), ddq = 4 * q / (9 * I3 * I3);
    const PetscReal Ie = std::pow(I3, e), dh = e * (Ie - 1 / Ie) / I3, ddh = (e * (e - 1) * Ie + e * (e + 1) / Ie) / (I3 * I3);
    const PetscReal c1 = p[0], eps1 = p[1], s3 = c1 * I1 * dq + eps1 * dh; /* the factor of grad I3 and of H I3 */
    for (int a = 0; a < 6; a++) {
      g[a] = c1 * q * dI1[a] + s3 * dI3[a];
      for (int b = 0; b < 6; b++) H[a][b] = s3 * HI3[a][b] + (c1 * I1 * ddq + eps1 * ddh) * dI3[a] * dI3[b];
    }
    AddOuter(H, c1 * dq, dI1, dI3);
    AddOuter(H, c1 * dq, dI3, dI1);
    for (int f = 0; f < 2; f++) { /* alpha1 <m>^alpha2, m = I1 J4 - J5 - 2 */
      const PetscReal *a     = &p[ARTERIAL_FIBRES + 3 * f];
      const PetscReal  B[3][6] = {{a[0], 0, 0, a[1], a[2], 0}, {0, a[1], 0, a[0], 0, a[2]}, {0, 0, a[2], 0, a[0], a[1]}}; /* C a = B c */
      PetscReal        Ca[3], dJ4[6], dm[6];
      for (int i = 0; i < 3; i++) Ca[i] = B[i][0] * c[0] + B[i][1] * c[1] + B[i][2] * c[2] + B[i][3] * c[3] + B[i][4] * c[4] + B[i][5] * c[5];
      const PetscReal J4 = a[0] * Ca[0] + a[1] * Ca[1] + a[2] * Ca[2], J5 = Ca[0] * Ca[0] + Ca[1] * Ca[1] + Ca[2] * Ca[2], m = I1 * J4 - J5 - 2;
      if (!(m > 0)) continue; /* the Macaulay bracket: fibres carry no compression */
      for (int k = 0; k < 6; k++) {
        dJ4[k] = 0;
        for (int i = 0; i < 3; i++) dJ4[k] += a[i] * B[i][k];
      }
      for (int k = 0; k < 6; k++) dm[k] = J4 * dI1[k] + I1 * dJ4[k] - 2 * (B[0][k] * Ca[0] + B[1][k] * Ca[1] + B[2][k] * Ca[2]);
      const PetscReal mp = p[3] * std::pow(m, p[4]), dk = p[4] * mp / m, ddk = p[4] * (p[4] - 1) * mp / (m * m);
      for (int k = 0; k < 6; k++) g[k] += dk * dm[k];
      AddOuter(H, ddk, dm, dm);
      AddOuter(H, dk, dI1, dJ4);
      AddOuter(H, dk, dJ4, dI1);
      for (int k = 0; k < 6; k++)
        for (int l = 0; l < 6; l++) H[k][l] -= 2 * dk * (B[0][k] * B[0][l] + B[1][k] * B[1][l] + B[2][k] * B[2][l]);
    }
  }
};

/* A_iJkL = d P_iJ / d F_kL = delta_ik S_JL + F_iI F_kK 4 d2Psi/dC_IJ dC_KL. */
template <template <class> class Energy>
static void TangentFromEnergy(const PetscReal F[9], const PetscReal *p, PetscReal A[81])
{
  PetscReal c[6], g[6], S[9], H[6][6], C4[81], FC[81];
  RightCauchyGreen(F, c);
  EnergyDerivatives<Energy>::Eval(c, p, g, H);
  SecondPiola(g, S);
  for (int I = 0; I < 3; I++) /* C4_IJKL = 4 w_IJ w_KL H, w = 1/2 off the diagonal */
    for (int J = 0; J < 3; J++)
      for (int K = 0; K < 3; K++)
        for (int L = 0; L < 3; L++) C4[((I * 3 + J) * 3 + K) * 3 + L] = 4 * (I == J ? 1.0 : 0.5) * (K == L ? 1.0 : 0.5) * H[Voigt[I][J]][Voigt[K][L]];
  for (int i = 0; i < 3; i++) /* FC_iJKL = F_iI C4_IJKL */
    for (int JKL = 0; JKL < 27; JKL++) FC[i * 27 + JKL] = F[i * 3] * C4[JKL] + F[i * 3 + 1] * C4[27 + JKL] + F[i * 3 + 2] * C4[54 + JKL];
  for (int i = 0; i < 3; i++)
    for (int J = 0; J < 3; J++)
      for (int k = 0; k < 3; k++)
        for (int L = 0; L < 3; L++) {
          PetscReal a = (i == k) * S[J * 3 + L];
          for (int K = 0; K < 3; K++) a += F[k * 3 + K] * FC[((i * 3 + J) * 3 + K) * 3 + L];
          A[((i * 3 + J) * 3 + k) * 3 + L] = a;
        }
}

PetscErrorCode GetMaterialLaw(Material m, MaterialLaw *law)
{
  PetscFunctionBegin;
  switch (m) {
  case LINEAR_ELASTIC:
    law->stress = StressLinear, law->tangent = TangentLinear, law->finiteStrain = PETSC_FALSE;
    break;
  case NEO_HOOKE:
    law->stress = StressFromEnergy<NeoHookeEnergy>, law->tangent = TangentFromEnergy<NeoHookeEnergy>, law->finiteStrain = PETSC_TRUE;
    break;
  case ARTERIAL:
    law->stress = StressFromEnergy<ArterialEnergy>, law->tangent = TangentFromEnergy<ArterialEnergy>, law->finiteStrain = PETSC_TRUE;
    break;
  }
  PetscFunctionReturn(0);
}

} // namespace fsi
