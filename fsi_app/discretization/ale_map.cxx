// SPDX-License-Identifier: BSD-2-Clause
#include "ale_map.h"

namespace fsi {

PetscReal DeformationGradient(const PetscReal de[30], const PetscReal dN[10][3], PetscReal F[9])
{
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) F[i * 3 + j] = (i == j);
  for (int a = 0; a < 10; a++)
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) F[i * 3 + j] += de[3 * a + i] * dN[a][j];
  return F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) + F[2] * (F[3] * F[7] - F[4] * F[6]);
}

PetscReal MovePoint(const CellGeometry &g, const PetscReal *de, const PetscReal l[4], const PetscReal N[10], MovedPoint &m)
{
  PetscReal dN[10][3], F[9], both[30];
  if (g.curved) {
    for (int k = 0; k < 30; k++) both[k] = g.bend[k] + (de ? de[k] : 0.0);
    de = both;
  }
  P2Gradients(g, l, dN);
  for (int d = 0; d < 3; d++) m.x[d] = l[0] * g.x[0][d] + l[1] * g.x[1][d] + l[2] * g.x[2][d] + l[3] * g.x[3][d];
  if (!de) {
    m.J = 1;
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) m.Finv[i][j] = (i == j);
    for (int a = 0; a < 10; a++)
      for (int d = 0; d < 3; d++) m.dN[a][d] = dN[a][d];
    for (int c = 0; c < 4; c++)
      for (int d = 0; d < 3; d++) m.dL[c][d] = g.gradLambda[c][d];
    return 1;
  }
  m.J = DeformationGradient(de, dN, F);
  for (int a = 0; a < 10; a++)
    for (int d = 0; d < 3; d++) m.x[d] += N[a] * de[3 * a + d];
  if (m.J <= 0) return m.J;
  m.Finv[0][0] = (F[4] * F[8] - F[5] * F[7]) / m.J, m.Finv[0][1] = (F[2] * F[7] - F[1] * F[8]) / m.J, m.Finv[0][2] = (F[1] * F[5] - F[2] * F[4]) / m.J;
  m.Finv[1][0] = (F[5] * F[6] - F[3] * F[8]) / m.J, m.Finv[1][1] = (F[0] * F[8] - F[2] * F[6]) / m.J, m.Finv[1][2] = (F[2] * F[3] - F[0] * F[5]) / m.J;
  m.Finv[2][0] = (F[3] * F[7] - F[4] * F[6]) / m.J, m.Finv[2][1] = (F[1] * F[6] - F[0] * F[7]) / m.J, m.Finv[2][2] = (F[0] * F[4] - F[1] * F[3]) / m.J;
  /* grad_x N_j = sum_i (F^-1)_ij grad_X N_i */
  for (int a = 0; a < 10; a++)
    for (int j = 0; j < 3; j++) m.dN[a][j] = m.Finv[0][j] * dN[a][0] + m.Finv[1][j] * dN[a][1] + m.Finv[2][j] * dN[a][2];
  for (int c = 0; c < 4; c++)
    for (int j = 0; j < 3; j++) m.dL[c][j] = m.Finv[0][j] * g.gradLambda[c][0] + m.Finv[1][j] * g.gradLambda[c][1] + m.Finv[2][j] * g.gradLambda[c][2];
  return m.J;
}

PetscReal ReferenceGradients(const CellGeometry &g, const P2Rule &rule, PetscInt q, PetscReal dN[10][3], PetscReal X[3])
{
  const PetscReal *l = &rule.lambda[4 * q];
  if (!g.curved) {
    P2Gradients(g, l, dN);
    if (X)
      for (int d = 0; d < 3; d++) X[d] = l[0] * g.x[0][d] + l[1] * g.x[1][d] + l[2] * g.x[2][d] + l[3] * g.x[3][d];
    return rule.w[q] * g.detE;
  }
  MovedPoint m;
  MovePoint(g, nullptr, l, &rule.N[10 * q], m);
  for (int a = 0; a < 10; a++)
    for (int d = 0; d < 3; d++) dN[a][d] = m.dN[a][d];
  if (X)
    for (int d = 0; d < 3; d++) X[d] = m.x[d];
  return rule.w[q] * g.detE * m.J;
}

} // namespace fsi
