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
    law->stress = StressLinear, law->tangent = TangentLinear;
    break;
  case NEO_HOOKE:
    law->stress = StressFromEnergy<NeoHookeEnergy>, law->tangent = TangentFromEnergy<NeoHookeEnergy>;
    break;
  default:
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_SUP, "-material %s is not implemented yet (available: linear, neohooke)", MaterialNames[m]);
  }
  PetscFunctionReturn(0);
}

} // namespace fsi
