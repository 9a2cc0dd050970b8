// SPDX-License-Identifier: BSD-2-Clause
#include "assembly.h"
#include "discretization/ale_map.h"
#include "verification/mms.h"

namespace fsi {

static void Cross(const PetscReal a[3], const PetscReal b[3], PetscReal c[3])
{
  c[0] = a[1] * b[2] - a[2] * b[1], c[1] = a[2] * b[0] - a[0] * b[2], c[2] = a[0] * b[1] - a[1] * b[0];
}

/* At face point q: basis values N, their d/ds and d/dt (dN[a][0], dN[a][1]) for the face
   parametrised by (s, t) = (l[slot[1]], l[slot[2]]), and the tangents d/ds x, d/dt x of the
   reference face (dead pressure) or of the deformed one (follower). */
static void FacePoint(const StructureForms &sb, const CellGeometry &g, const CellFace &f, const PetscReal de[30], PetscInt q, PetscReal N[10], PetscReal dN[10][3], PetscReal ts[3], PetscReal tt[3])
{
  PetscReal    l[4] = {0, 0, 0, 0};
  CellGeometry st   = g; /* "gradients" of the barycentric coordinates in (s, t) */
  for (int a = 0; a < 3; a++) l[f.slot[a]] = sb.faceRule.mu[3 * q + a];
  for (int k = 0; k < 4; k++) st.gradLambda[k][0] = (k == f.slot[1]) - (k == f.slot[0]), st.gradLambda[k][1] = (k == f.slot[2]) - (k == f.slot[0]), st.gradLambda[k][2] = 0;
  P2Values(l, N);
  P2Gradients(st, l, dN);
  for (int d = 0; d < 3; d++) {
    ts[d] = tt[d] = 0;
    for (int a = 0; a < 10; a++) {
      const PetscReal X = a < 4 ? g.x[a][d] : (g.x[EdgeVertex[a - 4][0]][d] + g.x[EdgeVertex[a - 4][1]][d]) / 2 + (g.curved ? g.bend[3 * a + d] : 0.0);
      const PetscReal y = X + (sb.follower ? de[3 * a + d] : 0.0);
      ts[d] += dN[a][0] * y, tt[d] += dN[a][1] * y;
    }
  }
}

/* + int_faces p n . v: the pressure p pushes the wall along -n; n da = sign ts x tt ds dt. */
static void PressureResidual(const StructureForms &sb, const CellFace &f, const PetscReal de[30], PetscReal re[30])
{
  const CellGeometry &g = sb.cells.geom[f.k];
  for (PetscInt q = 0; q < sb.faceRule.nq; q++) {
    PetscReal N[10], dN[10][3], ts[3], tt[3], nda[3];
    FacePoint(sb, g, f, de, q, N, dN, ts, tt);
    Cross(ts, tt, nda);
    const PetscReal w = sb.faceRule.w[q] * sb.pressure * f.sign;
    for (int a = 0; a < 10; a++)
      for (int c = 0; c < 3; c++) re[3 * a + c] += w * N[a] * nda[c];
  }
}

/* The follower pressure's derivative: d(ts x tt)/d d_bk = dN_b,s e_k x tt + dN_b,t ts x e_k. */
static void PressureTangent(const StructureForms &sb, const CellFace &f, const PetscReal de[30], PetscReal K[900])
{
  const CellGeometry &g = sb.cells.geom[f.k];
  for (PetscInt q = 0; q < sb.faceRule.nq; q++) {
    PetscReal N[10], dN[10][3], ts[3], tt[3];
    FacePoint(sb, g, f, de, q, N, dN, ts, tt);
    const PetscReal w = sb.faceRule.w[q] * sb.pressure * f.sign;
    for (int k = 0; k < 3; k++) {
      PetscReal ek[3] = {0, 0, 0}, ekxtt[3], tsxek[3];
      ek[k]           = 1;
      Cross(ek, tt, ekxtt);
      Cross(ts, ek, tsxek);
      for (int a = 0; a < 10; a++)
        for (int b = 0; b < 10; b++)
          for (int i = 0; i < 3; i++) K[(3 * a + i) * 30 + 3 * b + k] += w * N[a] * (dN[b][0] * ekxtt[i] + dN[b][1] * tsxek[i]);
    }
  }
}

/* The tissue support on face f: + int (k_s d + c_s d_t) . v dA on the reference face (or only
   the components along its unit normal). s holds k_s d + c_s d_t at the cell's nodes; with
   s = 0 and kappa = k_s + c_s c_0 / dt it adds the tangent kappa int N_a N_b (I or n n^T). */
static void SupportTerms(const StructureForms &sb, const CellFace &f, const PetscReal s[30], PetscReal kappa, PetscReal re[30], PetscReal K[900])
{
  const CellGeometry &g = sb.cells.geom[f.k];
  const PetscReal     zero[30] = {0};
  for (PetscInt q = 0; q < sb.faceRule.nq; q++) {
    PetscReal N[10], dN[10][3], ts[3], tt[3], nda[3], P[9];
    FacePoint(sb, g, f, zero, q, N, dN, ts, tt); /* the reference face, also for a follower load */
    Cross(ts, tt, nda);
    const PetscReal da = PetscSqrtReal(nda[0] * nda[0] + nda[1] * nda[1] + nda[2] * nda[2]), w = sb.faceRule.w[q] * da;
    for (int i = 0; i < 3; i++)
      for (int k = 0; k < 3; k++) P[i * 3 + k] = sb.supportNormal ? nda[i] * nda[k] / (da * da) : (PetscReal)(i == k);
    PetscReal sq[3] = {0, 0, 0}, Psq[3];
    for (int b = 0; b < 10; b++)
      for (int k = 0; k < 3; k++) sq[k] += N[b] * s[3 * b + k];
    for (int i = 0; i < 3; i++) Psq[i] = P[i * 3] * sq[0] + P[i * 3 + 1] * sq[1] + P[i * 3 + 2] * sq[2];
    for (int a = 0; a < 10; a++)
      for (int i = 0; i < 3; i++) {
        re[3 * a + i] += w * N[a] * Psq[i];
        if (kappa != 0)
          for (int b = 0; b < 10; b++)
            for (int k = 0; k < 3; k++) K[(3 * a + i) * 30 + 3 * b + k] += w * kappa * N[a] * N[b] * P[i * 3 + k];
      }
  }
}

/* The damper's coefficient c_0 / dt of d^(n+1) in d_t (0 in statics: no past states). */
static PetscReal DamperRate(const StructureForms &sb)
{
  return sb.history && !sb.history->past.empty() ? sb.history->first[0] / sb.history->dt : 0.0;
}

/* The law's parameters at quadrature point q (reference point X) of cell k: the fibre
   directions of the arterial wall, about the z-axis or in the frame of the vessel's centreline. */
static void PointParameters(const StructureForms &sb, PetscInt k, PetscInt q, const PetscReal X[3], PetscReal p[MATERIAL_MAX_PARAM])
{
  for (int i = 0; i < MATERIAL_MAX_PARAM; i++) p[i] = sb.param[i];
  if (sb.fibreAngle < 0) return;
  if (!sb.centerline) ArterialFibres(X, sb.fibreAngle, &p[ARTERIAL_FIBRES]);
  else
    for (int i = 0; i < 6; i++) p[ARTERIAL_FIBRES + i] = sb.fibres[sb.fibresAt[k] + 6 * q + i]; /* the set-up's */
}

/* The rule of cell g: a curved cell's integrands are rational in l, and take a rule of higher
   degree than the straight cell's polynomials. */
static const P2Rule &CellRule(const StructureForms &sb, const CellGeometry &g)
{
  return g.curved ? sb.curvedRule : sb.rule;
}

void StructureCurvedMasses(StructureForms &sb)
{
  sb.curvedAt.assign(sb.cells.Size(), -1);
  sb.curvedMass.clear();
  for (PetscInt k = 0; k < sb.cells.Size(); k++) {
    const CellGeometry &g = sb.cells.geom[k];
    if (!g.curved) continue;
    sb.curvedAt[k] = (PetscInt)sb.curvedMass.size();
    sb.curvedMass.resize(sb.curvedMass.size() + 100, 0.0);
    PetscReal *M = &sb.curvedMass[sb.curvedAt[k]];
    for (PetscInt q = 0; q < sb.curvedRule.nq; q++) {
      PetscReal       dN[10][3], X[3];
      const PetscReal w = ReferenceGradients(g, sb.curvedRule, q, dN, X), *N = &sb.curvedRule.N[10 * q];
      for (int a = 0; a < 10; a++)
        for (int b = 0; b < 10; b++) M[a * 10 + b] += w * N[a] * N[b];
    }
  }
}

/* The consistent mass matrix of cell k: the reference one times |det E|, or the curved cell's. */
static void CellMass(const StructureForms &sb, PetscInt k, PetscReal M[100])
{
  const PetscInt at = sb.curvedAt.empty() ? -1 : sb.curvedAt[k];
  for (int i = 0; i < 100; i++) M[i] = at < 0 ? sb.cells.geom[k].detE * sb.mass[i] : sb.curvedMass[at + i];
}

/* rho / dt^2: the inertia term is rho M (sum_j c_j d^(n+1-j)) / dt^2 (0 in statics). */
static PetscReal Inertia(const StructureForms &sb)
{
  return sb.history && !sb.history->past.empty() ? sb.rho / (sb.history->dt * sb.history->dt) : 0.0;
}

PetscErrorCode StructureResidual(StructureForms &sb, const PetscScalar *x, PetscScalar *f)
{
  const PetscReal            inertia = Inertia(sb);
  std::vector<const PetscScalar *> past;
  PetscInt                   inverted = 0;

  PetscFunctionBegin;
  if (inertia) PetscCall(TimeHistoryGetPast(sb.history, past));
  for (PetscInt k = 0; k < sb.cells.Size(); k++) {
    const CellGeometry &g = sb.cells.geom[k];
    PetscReal           de[30], re[30] = {0};
    Gather(sb.cells, k, x, de);
    if (inertia) {
      PetscReal acc[30], y[30];
      for (int i = 0; i < 30; i++) acc[i] = sb.history->second[0] * de[i];
      for (size_t j = 0; j < past.size(); j++) {
        Gather(sb.cells, k, past[j], y);
        for (int i = 0; i < 30; i++) acc[i] += sb.history->second[j + 1] * y[i];
      }
      PetscReal M[100];
      CellMass(sb, k, M);
      for (int a = 0; a < 10; a++)
        for (int b = 0; b < 10; b++)
          for (int i = 0; i < 3; i++) re[3 * a + i] += inertia * M[a * 10 + b] * acc[3 * b + i];
    }
    const P2Rule &rule = CellRule(sb, g);
    for (PetscInt q = 0; q < rule.nq; q++) {
      const PetscReal *N = &rule.N[10 * q];
      PetscReal        dN[10][3], X[3], F[9], P[9], b[3] = {0, 0, 0}, p[MATERIAL_MAX_PARAM];
      const PetscReal  wq = ReferenceGradients(g, rule, q, dN, X);
      if (DeformationGradient(de, dN, F) <= 0 && sb.law.finiteStrain) { /* inverted: no stress exists, say so below */
        inverted++;
        continue;
      }
      PointParameters(sb, k, q, X, p);
      sb.law.stress(F, p, P);
      if (sb.mms) MMSBodyForce(X, sb.mms, sb.law.tangent, p, b);
      for (int i = 0; i < 3; i++) b[i] += sb.load * sb.bodyForce[i];
      for (int a = 0; a < 10; a++)
        for (int i = 0; i < 3; i++) re[3 * a + i] += wq * (P[i * 3] * dN[a][0] + P[i * 3 + 1] * dN[a][1] + P[i * 3 + 2] * dN[a][2] - b[i] * N[a]);
    }
    Scatter(sb.cells, k, re, f);
  }
  for (const CellFace &face : sb.tractionFaces) { /* - int t . v over the reference faces */
    const CellGeometry &g = sb.cells.geom[face.k];
    PetscReal           de[30] = {0}, re[30] = {0};
    for (PetscInt q = 0; q < sb.faceRule.nq; q++) {
      PetscReal N[10], dN[10][3], ts[3], tt[3], nda[3];
      FacePoint(sb, g, face, de, q, N, dN, ts, tt); /* de = 0: the reference face */
      Cross(ts, tt, nda);
      const PetscReal w = sb.faceRule.w[q] * sb.load * PetscSqrtReal(nda[0] * nda[0] + nda[1] * nda[1] + nda[2] * nda[2]);
      for (int a = 0; a < 10; a++)
        for (int i = 0; i < 3; i++) re[3 * a + i] -= w * N[a] * sb.traction[i];
    }
    Scatter(sb.cells, face.k, re, f);
  }
  if (sb.pressure != 0)
    for (const CellFace &face : sb.loaded) {
      PetscReal de[30], re[30] = {0};
      Gather(sb.cells, face.k, x, de);
      PressureResidual(sb, face, de, re);
      Scatter(sb.cells, face.k, re, f);
    }
  if (sb.spring != 0 || sb.damper != 0) {
    const PetscReal rate = DamperRate(sb);
    if (rate && past.empty()) PetscCall(TimeHistoryGetPast(sb.history, past));
    for (const CellFace &face : sb.supported) {
      PetscReal de[30], s[30], y[30], re[30] = {0};
      Gather(sb.cells, face.k, x, de);
      for (int i = 0; i < 30; i++) s[i] = (sb.spring + sb.damper * rate) * de[i];
      for (size_t j = 0; rate && j < past.size() && sb.history->first[j + 1] != 0; j++) {
        Gather(sb.cells, face.k, past[j], y);
        for (int i = 0; i < 30; i++) s[i] += sb.damper * sb.history->first[j + 1] / sb.history->dt * y[i];
      }
      SupportTerms(sb, face, s, 0, re, nullptr);
      Scatter(sb.cells, face.k, re, f);
    }
  }
  PetscCall(TimeHistoryRestorePast(sb.history, past));
  sb.inverted = inverted;
  if (inverted) PetscCall(PetscInfo(sb.snes, "%" PetscInt_FMT " quadrature points with det F <= 0: the step is outside the domain of the law\n", inverted));
  PetscFunctionReturn(0);
}

PetscErrorCode StructureJacobian(const StructureForms &sb, const PetscScalar *x, Mat P)
{
  const PetscReal       mass = Inertia(sb) * (sb.history ? sb.history->second[0] : 0.0);

  PetscFunctionBegin;
  for (PetscInt k = 0; k < sb.cells.Size(); k++) {
    const CellGeometry &g = sb.cells.geom[k];
    PetscReal           de[30], K[900] = {0};
    Gather(sb.cells, k, x, de);
    if (mass) {
      PetscReal M[100];
      CellMass(sb, k, M);
      for (int a = 0; a < 10; a++)
        for (int b = 0; b < 10; b++)
          for (int i = 0; i < 3; i++) K[(3 * a + i) * 30 + 3 * b + i] += mass * M[a * 10 + b];
    }
    const P2Rule &rule = CellRule(sb, g);
    for (PetscInt q = 0; q < rule.nq; q++) {
      PetscReal       dN[10][3], X[3], F[9], A[81], G[10][3][9], p[MATERIAL_MAX_PARAM];
      const PetscReal wq = ReferenceGradients(g, rule, q, dN, X);
      if (DeformationGradient(de, dN, F) <= 0 && sb.law.finiteStrain) continue; /* the residual reported it */
      PointParameters(sb, k, q, X, p);
      sb.law.tangent(F, p, A);
      /* G[a][i][k*3+l] = sum_j dN_a,j A_ijkl: then K_(ai)(bk) = sum_l G[a][i][kl] dN_b,l */
      for (int a = 0; a < 10; a++)
        for (int i = 0; i < 3; i++)
          for (int kl = 0; kl < 9; kl++) G[a][i][kl] = wq * (dN[a][0] * A[(i * 3) * 9 + kl] + dN[a][1] * A[(i * 3 + 1) * 9 + kl] + dN[a][2] * A[(i * 3 + 2) * 9 + kl]);
      for (int a = 0; a < 10; a++)
        for (int i = 0; i < 3; i++) {
          PetscReal *row = &K[(3 * a + i) * 30];
          for (int b = 0; b < 10; b++)
            for (int c = 0; c < 3; c++) row[3 * b + c] += G[a][i][c * 3] * dN[b][0] + G[a][i][c * 3 + 1] * dN[b][1] + G[a][i][c * 3 + 2] * dN[b][2];
        }
    }
    PetscCall(AddElementMatrix(P, 30, &sb.cells.global[30 * k], 30, &sb.cells.global[30 * k], K));
  }
  if (sb.follower && sb.pressure != 0)
    for (const CellFace &face : sb.loaded) {
      PetscReal de[30], K[900] = {0};
      Gather(sb.cells, face.k, x, de);
      PressureTangent(sb, face, de, K);
      PetscCall(AddElementMatrix(P, 30, &sb.cells.global[30 * face.k], 30, &sb.cells.global[30 * face.k], K));
    }
  if (sb.spring != 0 || sb.damper != 0)
    for (const CellFace &face : sb.supported) {
      PetscReal s[30] = {0}, re[30] = {0}, K[900] = {0};
      SupportTerms(sb, face, s, sb.spring + sb.damper * DamperRate(sb), re, K);
      PetscCall(AddElementMatrix(P, 30, &sb.cells.global[30 * face.k], 30, &sb.cells.global[30 * face.k], K));
    }
  PetscFunctionReturn(0);
}

/* (the follower load's and the support's faces add to their cell's entries) */
void StructureCouplings(const StructureForms &sb, Sparsity &s)
{
  for (PetscInt k = 0; k < sb.cells.Size(); k++) s.Couple(30, &sb.cells.global[30 * k], 30, &sb.cells.global[30 * k]);
}

} // namespace fsi
