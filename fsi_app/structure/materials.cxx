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

/* Hyperelastic laws are written once, as their energy Psi(F); P = dPsi/dF and A = d2Psi/dF2
   come from forward-mode differentiation, exact to round-off. */
template <class S>
static S PsiNeoHooke(const S F[9], const PetscReal *p)
{
  const S J  = F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) + F[2] * (F[3] * F[7] - F[4] * F[6]);
  S       I1 = F[0] * F[0];
  for (int k = 1; k < 9; k++) I1 = I1 + F[k] * F[k];
  return p[0] / 2 * (pow(J, -2.0 / 3.0) * I1 - 3.0) + p[1] / 4 * (J * J - 1.0 - 2.0 * log(J));
}

template <class S>
struct NeoHookeEnergy {
  static S Eval(const S F[9], const PetscReal *p) { return PsiNeoHooke(F, p); }
};

/* C = F^T F as the 6 entries C00 C11 C22 C01 C02 C12, and the invariants the laws use. */
template <class S>
static void RightCauchyGreen(const S F[9], S C[6])
{
  const int ij[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
  for (int k = 0; k < 6; k++) C[k] = F[ij[k][0]] * F[ij[k][1]] + F[3 + ij[k][0]] * F[3 + ij[k][1]] + F[6 + ij[k][0]] * F[6 + ij[k][1]];
}

/* The polyconvex arterial wall of Balzani et al. (FSI.md): isotropic matrix, a penalty on the
   volume change, and two fibre families a (reference, unit) that only resist stretching:
   Psi = c1 (I1 I3^(-1/3) - 3) + eps1 (I3^eps2 + I3^(-eps2) - 2)
         + sum_a alpha1 <I1 J4_a - J5_a - 2>^alpha2, J4 = a.C a, J5 = |C a|^2.
   p = {c1, eps1, eps2, alpha1, alpha2, a1 (3), a2 (3)}. */
template <class S>
static S PsiArterial(const S F[9], const PetscReal *p)
{
  S C[6];
  RightCauchyGreen(F, C);
  const S I1 = C[0] + C[1] + C[2];
  const S I3 = C[0] * (C[1] * C[2] - C[5] * C[5]) - C[3] * (C[3] * C[2] - C[5] * C[4]) + C[4] * (C[3] * C[5] - C[1] * C[4]);
  S       psi = p[0] * (I1 * pow(I3, -1.0 / 3.0) - 3.0) + p[1] * (pow(I3, p[2]) + pow(I3, -p[2]) - 2.0);
  for (int f = 0; f < 2; f++) {
    const PetscReal *a  = &p[5 + 3 * f];
    const S          Ca[3] = {C[0] * a[0] + C[3] * a[1] + C[4] * a[2], C[3] * a[0] + C[1] * a[1] + C[5] * a[2], C[4] * a[0] + C[5] * a[1] + C[2] * a[2]};
    const S          J4 = a[0] * Ca[0] + a[1] * Ca[1] + a[2] * Ca[2], J5 = Ca[0] * Ca[0] + Ca[1] * Ca[1] + Ca[2] * Ca[2];
    const S          m  = I1 * J4 - J5 - 2.0;
    if (m > 0) psi = psi + p[3] * pow(m, p[4]); /* the Macaulay bracket: fibres carry no compression */
  }
  return psi;
}

template <class S>
struct ArterialEnergy {
  static S Eval(const S F[9], const PetscReal *p) { return PsiArterial(F, p); }
};

void ArterialFibres(const PetscReal x[3], PetscReal beta, PetscReal a[6])
{
  const PetscReal r = std::sqrt(x[0] * x[0] + x[1] * x[1]);
  const PetscReal t[3] = {r > 0 ? -x[1] / r : 1.0, r > 0 ? x[0] / r : 0.0, 0}; /* circumferential */
  for (int d = 0; d < 3; d++) a[d] = std::cos(beta) * t[d] + (d == 2) * std::sin(beta), a[3 + d] = std::cos(beta) * t[d] - (d == 2) * std::sin(beta);
}

template <template <class> class Energy>
static void StressFromEnergy(const PetscReal F[9], const PetscReal *p, PetscReal P[9])
{
  using D = Dual<9>;
  D Fd[9];
  for (int k = 0; k < 9; k++) Fd[k] = D(F[k]), Fd[k].d[k] = 1;
  const D psi = Energy<D>::Eval(Fd, p);
  for (int k = 0; k < 9; k++) P[k] = psi.d[k];
}

template <template <class> class Energy>
static void TangentFromEnergy(const PetscReal F[9], const PetscReal *p, PetscReal A[81])
{
  using D  = Dual<9>;
  using DD = Dual<9, D>;
  DD Fd[9];
  for (int k = 0; k < 9; k++) {
    D inner(F[k]);
    inner.d[k] = 1;
    Fd[k]      = DD(inner, 0);
    Fd[k].d[k] = D(1.0);
  }
  const DD psi = Energy<DD>::Eval(Fd, p);
  for (int a = 0; a < 9; a++)
    for (int b = 0; b < 9; b++) A[a * 9 + b] = psi.d[a].d[b];
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
