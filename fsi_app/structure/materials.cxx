#include "materials.h"

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

PetscErrorCode GetMaterialLaw(Material m, MaterialLaw *law)
{
  PetscFunctionBegin;
  PetscCheck(m == LINEAR_ELASTIC, PETSC_COMM_SELF, PETSC_ERR_SUP, "-material %s is not implemented yet (available: linear)", MaterialNames[m]);
  law->stress  = StressLinear;
  law->tangent = TangentLinear;
  PetscFunctionReturn(0);
}

} // namespace fsi
