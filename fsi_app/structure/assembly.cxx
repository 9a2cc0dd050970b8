#include "assembly.h"
#include "discretization/nodes.h"
#include "mesh/mesh.h"
#include "verification/mms.h"

namespace fsi {

/* Every cell of the block with its geometry, node offsets and the closure values of X. */
template <class Body>
static PetscErrorCode ForEachCell(DM dm, Vec X, const StructureBlock &sb, Body body)
{
  PetscSection section;
  PetscInt     cStart, cEnd;

  PetscFunctionBegin;
  PetscCall(DMGetLocalSection(dm, &section));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  for (PetscInt c = cStart; c < cEnd; c++) {
    if (sb.region) {
      PetscInt v;
      PetscCall(DMLabelGetValue(sb.region, c, &v));
      if (v != 1) continue;
    }
    CellGeometry g;
    PetscInt     off[10], n = 0;
    PetscScalar *x = nullptr;
    PetscCall(CellP2(dm, section, c, g, off, nullptr));
    PetscCall(DMPlexVecGetClosure(dm, section, X, c, &n, &x));
    PetscCall(body(c, g, off, x, n));
    PetscCall(DMPlexVecRestoreClosure(dm, section, X, c, &n, &x));
  }
  PetscFunctionReturn(0);
}

/* F = I + grad d at a point, from the nodal displacements; returns det F. */
static PetscReal DeformationGradient(const PetscScalar *x, const PetscInt off[10], const PetscReal dN[10][3], PetscReal F[9])
{
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) F[i * 3 + j] = (i == j);
  for (int a = 0; a < 10; a++)
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) F[i * 3 + j] += PetscRealPart(x[off[a] + i]) * dN[a][j];
  return F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) + F[2] * (F[3] * F[7] - F[4] * F[6]);
}

static PetscReal PointOf(const CellGeometry &g, const PetscReal l[4], int d)
{
  return l[0] * g.x[0][d] + l[1] * g.x[1][d] + l[2] * g.x[2][d] + l[3] * g.x[3][d];
}

/* + int_faces p n . v: the pressure p pushes the wall along -n, n its outward normal. */
static PetscErrorCode AddPressure(DM dm, const StructureBlock &sb, Vec Fl)
{
  PetscSection section;
  PetscInt     vStart, vEnd;

  PetscFunctionBegin;
  if (!sb.loaded || sb.pressure == 0) PetscFunctionReturn(0);
  PetscCall(DMGetLocalSection(dm, &section));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(ForEachLabelPoint(sb.loaded, {}, [&](PetscInt face) -> PetscErrorCode {
      const PetscInt *support;
      PetscInt        ns, cell = -1, *closure = nullptr, ncl, fv[3], nfv = 0;
      PetscFunctionBegin;
      PetscCall(DMPlexGetSupportSize(dm, face, &ns));
      PetscCall(DMPlexGetSupport(dm, face, &support));
      for (PetscInt s = 0; s < ns; s++) {
        PetscInt r = 1;
        if (sb.region) PetscCall(DMLabelGetValue(sb.region, support[s], &r));
        if (r == 1) cell = support[s];
      }
      if (cell < 0) PetscFunctionReturn(0); /* a face of another region */
      PetscCall(DMPlexGetTransitiveClosure(dm, face, PETSC_TRUE, &ncl, &closure));
      for (PetscInt j = 0; j < ncl; j++)
        if (closure[2 * j] >= vStart && closure[2 * j] < vEnd) fv[nfv++] = closure[2 * j];
      PetscCall(DMPlexRestoreTransitiveClosure(dm, face, PETSC_TRUE, &ncl, &closure));
      CellGeometry g;
      PetscInt     off[10], cv[4], n;
      PetscCall(CellP2(dm, section, cell, g, off, &n));
      { /* the cell's vertices in our order, to place the face in barycentric coordinates */
        PetscInt *cl = nullptr, nc, m = 0;
        PetscCall(DMPlexGetTransitiveClosure(dm, cell, PETSC_TRUE, &nc, &cl));
        for (PetscInt j = 0; j < nc; j++)
          if (cl[2 * j] >= vStart && cl[2 * j] < vEnd) cv[m++] = cl[2 * j];
        PetscCall(DMPlexRestoreTransitiveClosure(dm, cell, PETSC_TRUE, &nc, &cl));
      }
      int slot[3], opposite = 0 + 1 + 2 + 3;
      for (int a = 0; a < 3; a++)
        for (int b = 0; b < 4; b++)
          if (cv[b] == fv[a]) slot[a] = b;
      opposite -= slot[0] + slot[1] + slot[2];
      PetscReal e1[3], e2[3], nrm[3], out[3];
      for (int d = 0; d < 3; d++) e1[d] = g.x[slot[1]][d] - g.x[slot[0]][d], e2[d] = g.x[slot[2]][d] - g.x[slot[0]][d], out[d] = g.x[slot[0]][d] - g.x[opposite][d];
      nrm[0] = e1[1] * e2[2] - e1[2] * e2[1], nrm[1] = e1[2] * e2[0] - e1[0] * e2[2], nrm[2] = e1[0] * e2[1] - e1[1] * e2[0];
      const PetscReal sign = (nrm[0] * out[0] + nrm[1] * out[1] + nrm[2] * out[2]) > 0 ? 1 : -1;
      std::vector<PetscScalar> r(n, 0.0);
      for (PetscInt q = 0; q < sb.faceRule.nq; q++) {
        PetscReal l[4] = {0, 0, 0, 0}, N[10];
        for (int a = 0; a < 3; a++) l[slot[a]] = sb.faceRule.mu[3 * q + a];
        P2Values(l, N);
        /* dA = 2 area dmu and n = sign nrm / (2 area): the areas cancel */
        const PetscReal w = sb.faceRule.w[q] * sb.pressure * sign;
        for (int a = 0; a < 10; a++)
          for (int c = 0; c < 3; c++) r[off[a] + c] += w * N[a] * nrm[c];
      }
      PetscCall(DMPlexVecSetClosure(dm, section, Fl, cell, r.data(), ADD_ALL_VALUES));
      PetscFunctionReturn(0);
  }));
  PetscFunctionReturn(0);
}

PetscErrorCode StructureResidual(DM dm, Vec Xl, Vec Fl, void *ctx)
{
  const StructureBlock &sb = *(StructureBlock *)ctx;
  PetscSection          section;

  PetscFunctionBegin;
  PetscInt              inverted = 0;

  PetscCall(InsertEssentialValues(dm, 0.0, Xl));
  PetscCall(DMGetLocalSection(dm, &section));
  PetscCall(VecZeroEntries(Fl));
  PetscCall(ForEachCell(dm, Xl, sb, [&](PetscInt c, const CellGeometry &g, const PetscInt off[10], const PetscScalar *x, PetscInt n) -> PetscErrorCode {
    std::vector<PetscScalar> r(n, 0.0), accel(n, 0.0);
    PetscFunctionBegin;
    if (sb.inertia) { /* (d - 2 d^n + d^(n-1)) at the nodes of the cell */
      for (int k = 0; k < 2; k++) {
        PetscScalar *y = nullptr;
        PetscInt     m = 0;
        PetscCall(DMPlexVecGetClosure(dm, section, sb.previous[k], c, &m, &y));
        for (PetscInt i = 0; i < n; i++) accel[i] += (k == 0 ? -2.0 : 1.0) * y[i];
        PetscCall(DMPlexVecRestoreClosure(dm, section, sb.previous[k], c, &m, &y));
      }
      for (PetscInt i = 0; i < n; i++) accel[i] += x[i];
    }
    for (PetscInt q = 0; q < sb.rule.nq; q++) {
      const PetscReal *l = &sb.rule.lambda[4 * q], *N = &sb.rule.N[10 * q], wq = sb.rule.w[q] * g.detE;
      PetscReal        dN[10][3], F[9], P[9], b[3] = {0, 0, 0};
      P2Gradients(g, l, dN);
      if (DeformationGradient(x, off, dN, F) <= 0) { /* inverted: no stress exists, say so below */
        inverted++;
        continue;
      }
      sb.law.stress(F, sb.param, P);
      if (sb.mms) {
        const PetscReal xq[3] = {PointOf(g, l, 0), PointOf(g, l, 1), PointOf(g, l, 2)};
        MMSElasticityDivStress(xq, sb.param[0], sb.param[1], b); /* body force -div sigma */
        for (int i = 0; i < 3; i++) b[i] = -b[i];
      }
      PetscReal acc[3] = {0, 0, 0};
      if (sb.inertia)
        for (int a = 0; a < 10; a++)
          for (int i = 0; i < 3; i++) acc[i] += sb.inertia * N[a] * PetscRealPart(accel[off[a] + i]);
      for (int a = 0; a < 10; a++)
        for (int i = 0; i < 3; i++) {
          PetscReal v = (acc[i] - b[i]) * N[a];
          for (int j = 0; j < 3; j++) v += P[i * 3 + j] * dN[a][j];
          r[off[a] + i] += wq * v;
        }
    }
    PetscCall(DMPlexVecSetClosure(dm, section, Fl, c, r.data(), ADD_ALL_VALUES));
    PetscFunctionReturn(0);
  }));
  PetscCall(AddPressure(dm, sb, Fl));
  if (inverted) {
    PetscCall(PetscInfo(dm, "%" PetscInt_FMT " quadrature points with det F <= 0: the step is outside the domain of the law\n", inverted));
    if (sb.snes) PetscCall(SNESSetFunctionDomainError(sb.snes));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode StructureJacobian(DM dm, Vec Xl, Mat J, Mat P, void *ctx)
{
  const StructureBlock &sb = *(StructureBlock *)ctx;
  PetscSection          section, global;

  PetscFunctionBegin;
  PetscCall(InsertEssentialValues(dm, 0.0, Xl));
  PetscCall(DMGetLocalSection(dm, &section));
  PetscCall(DMGetGlobalSection(dm, &global));
  PetscCall(MatZeroEntries(P));
  PetscCall(ForEachCell(dm, Xl, sb, [&](PetscInt c, const CellGeometry &g, const PetscInt off[10], const PetscScalar *x, PetscInt n) -> PetscErrorCode {
    std::vector<PetscScalar> K(n * n, 0.0);
    PetscFunctionBegin;
    for (PetscInt q = 0; q < sb.rule.nq; q++) {
      const PetscReal *l = &sb.rule.lambda[4 * q], *N = &sb.rule.N[10 * q], wq = sb.rule.w[q] * g.detE;
      PetscReal        dN[10][3], F[9], A[81], G[10][3][9];
      if (sb.inertia)
        for (int a = 0; a < 10; a++)
          for (int b = 0; b < 10; b++)
            for (int i = 0; i < 3; i++) K[(off[a] + i) * n + off[b] + i] += wq * sb.inertia * N[a] * N[b];
      P2Gradients(g, l, dN);
      if (DeformationGradient(x, off, dN, F) <= 0) continue; /* the residual reported it */
      sb.law.tangent(F, sb.param, A);
      /* G[a][i][k*3+l] = sum_j dN_a,j A_ijkl: then K_(ai)(bk) = sum_l G[a][i][kl] dN_b,l */
      for (int a = 0; a < 10; a++)
        for (int i = 0; i < 3; i++)
          for (int kl = 0; kl < 9; kl++) {
            PetscReal s = 0;
            for (int j = 0; j < 3; j++) s += dN[a][j] * A[(i * 3 + j) * 9 + kl];
            G[a][i][kl] = wq * s;
          }
      for (int a = 0; a < 10; a++)
        for (int i = 0; i < 3; i++) {
          PetscScalar *row = &K[(off[a] + i) * n];
          for (int b = 0; b < 10; b++)
            for (int k = 0; k < 3; k++) row[off[b] + k] += G[a][i][k * 3] * dN[b][0] + G[a][i][k * 3 + 1] * dN[b][1] + G[a][i][k * 3 + 2] * dN[b][2];
        }
    }
    PetscCall(DMPlexMatSetClosure(dm, section, global, P, c, K.data(), ADD_VALUES));
    PetscFunctionReturn(0);
  }));
  PetscCall(MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY));
  if (J != P) {
    PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  }
  PetscFunctionReturn(0);
}

} // namespace fsi
