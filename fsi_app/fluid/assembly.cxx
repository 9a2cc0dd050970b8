// SPDX-License-Identifier: BSD-2-Clause
#include "assembly.h"
#include "discretization/ale_map.h"
#include "discretization/conditions.h"

namespace fsi {

/* One cell's nodal values: velocity, pressure, mesh displacement, and the differences in time
   of velocity and mesh displacement (zero in statics). */
struct CellState {
  PetscReal u[30], p[4], d[30], dudt[30], w[30];
};

static void GatherState(const FluidForms &fb, PetscInt k, const PetscScalar *x, const std::vector<const PetscScalar *> &past, CellState &s)
{
  Gather(fb.velocity, k, x, s.u);
  Gather(fb.pressure, k, x, s.p);
  for (int i = 0; i < 30; i++) s.d[i] = s.dudt[i] = s.w[i] = 0;
  if (fb.mesh) Gather(*fb.mesh, k, x, s.d);
  if (past.empty()) return;
  const PetscReal *c = fb.history->first, dt = fb.history->dt;
  PetscReal        y[30];
  for (int i = 0; i < 30; i++) s.dudt[i] = c[0] * s.u[i] / dt, s.w[i] = c[0] * s.d[i] / dt;
  for (size_t j = 0; j < past.size() && c[j + 1] != 0; j++) {
    Gather(fb.velocity, k, past[j], y);
    for (int i = 0; i < 30; i++) s.dudt[i] += c[j + 1] * y[i] / dt;
    if (!fb.mesh) continue;
    Gather(*fb.mesh, k, past[j], y);
    for (int i = 0; i < 30; i++) s.w[i] += c[j + 1] * y[i] / dt;
  }
}

/* Velocity, its gradient G[i][j] = du_i/dx_j, its difference in time, the mesh velocity and the
   pressure at one point. */
struct FlowPoint {
  PetscReal u[3], G[3][3], dudt[3], w[3], p;
};

static void Evaluate(const CellState &s, const PetscReal N[10], const PetscReal l[4], const MovedPoint &m, FlowPoint &f)
{
  f.p = l[0] * s.p[0] + l[1] * s.p[1] + l[2] * s.p[2] + l[3] * s.p[3];
  for (int i = 0; i < 3; i++) {
    f.u[i] = f.dudt[i] = f.w[i] = 0;
    for (int j = 0; j < 3; j++) f.G[i][j] = 0;
    for (int a = 0; a < 10; a++) {
      f.u[i] += N[a] * s.u[3 * a + i], f.dudt[i] += N[a] * s.dudt[3 * a + i], f.w[i] += N[a] * s.w[3 * a + i];
      for (int j = 0; j < 3; j++) f.G[i][j] += m.dN[a][j] * s.u[3 * a + i];
    }
  }
}

/* The traction and flux faces' points (discretization/ale_map.h). */
template <class Body>
static void ForEachFacePoint(const FluidForms &fb, const CellFace &f, const PetscReal *de, Body body)
{
  ForEachFacePoint(fb.velocity.geom[f.k], fb.faceRule, f, de, body);
}

static PetscErrorCode ReportInverted(const FluidForms &fb, PetscInt inverted)
{
  PetscFunctionBegin;
  if (!inverted) PetscFunctionReturn(0);
  PetscCall(PetscInfo(fb.snes, "%" PetscInt_FMT " quadrature points of the moved fluid mesh with J <= 0\n", inverted));
  PetscFunctionReturn(0);
}

/* The volume terms of cell k for state s: ru (30) and rp (4); returns the number of
   quadrature points where the moved cell is inverted. */
static PetscInt CellResidual(const FluidForms &fb, PetscInt k, const CellState &s, PetscReal ru[30], PetscReal rp[4])
{
  const CellGeometry &g        = fb.velocity.geom[k];
  PetscInt            inverted = 0;
  for (PetscInt q = 0; q < fb.rule.nq; q++) {
    const PetscReal *l = &fb.rule.lambda[4 * q], *N = &fb.rule.N[10 * q];
    MovedPoint       m;
    FlowPoint        p;
    if (MovePoint(g, fb.mesh ? s.d : nullptr, l, N, m) <= 0) {
      inverted++;
      continue;
    }
    Evaluate(s, N, l, m, p);
    const PetscReal w   = fb.rule.w[q] * g.detE * m.J;
    const PetscReal div = p.G[0][0] + p.G[1][1] + p.G[2][2];
    PetscReal       r[3], b[3] = {0, 0, 0};
    if (fb.force) fb.force(m.x, fb.time, b);
    for (int i = 0; i < 3; i++) r[i] = fb.rho * (p.dudt[i] + (p.u[0] - p.w[0]) * p.G[i][0] + (p.u[1] - p.w[1]) * p.G[i][1] + (p.u[2] - p.w[2]) * p.G[i][2]) - b[i];
    for (int a = 0; a < 10; a++)
      for (int i = 0; i < 3; i++) {
        PetscReal v = r[i] * N[a] - p.p * m.dN[a][i];
        for (int j = 0; j < 3; j++) v += fb.mu * (p.G[i][j] + p.G[j][i]) * m.dN[a][j];
        ru[3 * a + i] += w * v;
      }
    for (int c = 0; c < 4; c++) rp[c] -= w * l[c] * div;
  }
  return inverted;
}

/* - int t . v over one traction face of the mesh moved by de (nullptr: fixed). */
static void FaceResidual(const FluidForms &fb, const TractionGroup &tg, const CellFace &face, const PetscReal *de, PetscReal ru[30])
{
  ForEachFacePoint(fb, face, de, [&](const PetscReal N[10], const PetscReal xq[3], const PetscReal n[3], PetscReal w) {
    PetscReal t[3];
    tg.traction(xq, n, fb.time, t);
    for (int a = 0; a < 10; a++)
      for (int i = 0; i < 3; i++) ru[3 * a + i] -= w * t[i] * N[a];
  });
}

/* The backflow term on one outlet face: its residual (ru) and, if K is given, its derivative
   in the cell's 30 velocity dofs (K, 30 x 30). */
static void BackflowFace(const FluidForms &fb, const CellFace &face, const PetscReal ue[30], const PetscReal *de, PetscReal ru[30], PetscReal *K)
{
  const PetscReal c = fb.backflowBeta * fb.rho;
  ForEachFacePoint(fb, face, de, [&](const PetscReal N[10], const PetscReal *, const PetscReal n[3], PetscReal w) {
    PetscReal u[3] = {0, 0, 0};
    for (int a = 0; a < 10; a++)
      for (int i = 0; i < 3; i++) u[i] += N[a] * ue[3 * a + i];
    const PetscReal un = u[0] * n[0] + u[1] * n[1] + u[2] * n[2];
    if (un >= 0) return;
    for (int a = 0; a < 10; a++)
      for (int i = 0; i < 3; i++) {
        ru[3 * a + i] -= w * c * un * u[i] * N[a];
        if (K)
          for (int b = 0; b < 10; b++)
            for (int k = 0; k < 3; k++) K[(3 * a + i) * 30 + 3 * b + k] -= w * c * N[a] * N[b] * (n[k] * u[i] + (i == k ? un : 0));
      }
  });
}

PetscErrorCode FluidResidual(FluidForms &fb, const PetscScalar *x, PetscScalar *f)
{
  std::vector<const PetscScalar *> past;
  PetscInt                         inverted = 0;

  PetscFunctionBegin;
  PetscCall(TimeHistoryGetPast(fb.history, past));
  for (PetscInt k = 0; k < fb.velocity.Size(); k++) {
    CellState s;
    PetscReal ru[30] = {0}, rp[4] = {0};
    GatherState(fb, k, x, past, s);
    inverted += CellResidual(fb, k, s, ru, rp);
    Scatter(fb.velocity, k, ru, f);
    Scatter(fb.pressure, k, rp, f);
  }
  for (const TractionGroup &tg : fb.tractions)
    for (const CellFace &face : tg.faces) {
      PetscReal ru[30] = {0}, de[30];
      if (fb.mesh) Gather(*fb.mesh, face.k, x, de);
      FaceResidual(fb, tg, face, fb.mesh ? de : nullptr, ru);
      Scatter(fb.velocity, face.k, ru, f);
    }
  if (fb.backflowBeta > 0)
    for (const CellFace &face : fb.backflow) {
      PetscReal ru[30] = {0}, ue[30], de[30];
      Gather(fb.velocity, face.k, x, ue);
      if (fb.mesh) Gather(*fb.mesh, face.k, x, de);
      BackflowFace(fb, face, ue, fb.mesh ? de : nullptr, ru, nullptr);
      Scatter(fb.velocity, face.k, ru, f);
    }
  PetscCall(TimeHistoryRestorePast(fb.history, past));
  fb.inverted = inverted;
  PetscCall(ReportInverted(fb, inverted));
  PetscFunctionReturn(0);
}

/* The forward-difference step in positions for cell g: sqrt(machine epsilon) of its size, where
   truncation and round-off are both ~1e-8 relative (Newton stays quadratic down to the coupled
   tolerance). */
static PetscReal DifferenceStep(const CellGeometry &g)
{
  return PetscSqrtReal(PETSC_MACHINE_EPSILON) * PetscCbrtReal(g.detE);
}

/* The global indices of cell k's 30 velocity and 4 pressure dofs, in the element matrix's order. */
static void CellIndices(const FluidForms &fb, PetscInt k, PetscInt idx[34])
{
  for (int i = 0; i < 30; i++) idx[i] = fb.velocity.global[30 * k + i];
  for (int c = 0; c < 4; c++) idx[30 + c] = fb.pressure.global[4 * k + c];
}

/* The shape derivatives of the traction terms of cell k's faces: rows its 30 velocity dofs,
   columns its 30 mesh displacement dofs, added to S (34 x 30), by forward differences of the
   face residual (the traction is data of the moved point and normal). */
static void FaceShapeDerivatives(const FluidForms &fb, PetscInt k, const PetscReal d[30], const std::vector<std::pair<const TractionGroup *, const CellFace *>> &faces, PetscReal S[34 * 30])
{
  const PetscReal h = DifferenceStep(fb.velocity.geom[k]);
  auto residual = [&](const PetscReal *de, PetscReal r[30]) {
    for (int i = 0; i < 30; i++) r[i] = 0;
    for (const auto &tf : faces) FaceResidual(fb, *tf.first, *tf.second, de, r);
  };
  PetscReal r0[30];
  residual(d, r0);
  for (int j = 0; j < 30; j++) {
    PetscReal r[30], de[30];
    for (int i = 0; i < 30; i++) de[i] = d[i];
    de[j] += h;
    residual(de, r);
    for (int i = 0; i < 30; i++) S[i * 30 + j] += (r[i] - r0[i]) / h;
  }
}

/* The factors of the element matrices at one quadrature point that depend on the column
   j = 3 b + k (node b, component k) and the row's component i only, laid out over j: each row of
   K and S is then one update of 30 contiguous entries, which the compiler vectorises. */
struct Columns {
  PetscReal G[3][30];  /* G_ik */
  PetscReal dN[3][30]; /* dN_b[i] */
  PetscReal N[30];     /* N_b */
};

static void ColumnsAt(const PetscReal N[10], const MovedPoint &m, const FlowPoint &p, Columns &cols)
{
  for (int b = 0; b < 10; b++)
    for (int k = 0; k < 3; k++) {
      cols.N[3 * b + k] = N[b];
      for (int i = 0; i < 3; i++) cols.G[i][3 * b + k] = p.G[i][k], cols.dN[i][3 * b + k] = m.dN[b][i];
    }
}

/* The shape derivatives of the volume terms at one quadrature point (weight w, moved point m,
   flow p), added to S (34 x 30). Moving node b in direction m changes dN_a by
   -dN_a[m] dN_b, the weight by w dN_b[m], the gradient G_ij by -G_im dN_b[j], the mesh velocity
   by wRate N_b e_m and the point by N_b e_m (the body force; db[i][m] = db_i/dx_m). */
static void VolumeShapeDerivatives(const FluidForms &fb, const PetscReal N[10], const PetscReal l[4], const MovedPoint &m, const FlowPoint &p, const Columns &cols, const PetscReal cGradN[10], PetscReal w, PetscReal wRate, const PetscReal b[3], const PetscReal db[3][3], PetscReal S[34 * 30])
{
  const PetscReal  div = p.G[0][0] + p.G[1][1] + p.G[2][2];
  const PetscReal *dN  = &m.dN[0][0]; /* dN_b[m] over the columns j = 3 b + m */
  PetscReal        r[3], GtdN[10][3], GsdN[10][3];
  for (int i = 0; i < 3; i++) r[i] = fb.rho * (p.dudt[i] + (p.u[0] - p.w[0]) * p.G[i][0] + (p.u[1] - p.w[1]) * p.G[i][1] + (p.u[2] - p.w[2]) * p.G[i][2]) - b[i];
  for (int a = 0; a < 10; a++) {
    const PetscReal *g = m.dN[a];
    for (int i = 0; i < 3; i++) {
      GtdN[a][i] = p.G[0][i] * g[0] + p.G[1][i] * g[1] + p.G[2][i] * g[2];                               /* (G^T dN_a)_i */
      GsdN[a][i] = (p.G[i][0] + p.G[0][i]) * g[0] + (p.G[i][1] + p.G[1][i]) * g[1] + (p.G[i][2] + p.G[2][i]) * g[2]; /* ((G + G^T) dN_a)_i */
    }
  }
  /* S_(ai)(bm) = w [dN_b[m] v_ai + N_a dr_i/dd_bm + p dN_a[m] dN_b[i]
                      - mu (G_im dN_a.dN_b + dN_b[i] (G^T dN_a)_m + dN_a[m] ((G + G^T) dN_b)_i)]
     with v_ai the residual's integrand and dr_i/dd_bm = -rho G_im (wRate N_b + (u - w).dN_b) - db_i/dx_m N_b */
  PetscReal X[3][30], D[3][30]; /* p dN_b[i] - mu ((G + G^T) dN_b)_i;  db_i/dx_m */
  for (int bb = 0; bb < 10; bb++)
    for (int mm = 0; mm < 3; mm++)
      for (int i = 0; i < 3; i++) X[i][3 * bb + mm] = p.p * m.dN[bb][i] - fb.mu * GsdN[bb][i], D[i][3 * bb + mm] = db[i][mm];
  for (int a = 0; a < 10; a++) {
    const PetscReal *ga = m.dN[a];
    PetscReal        wga[30], wGtdN[30], cG[30], cb[30];
    for (int bb = 0; bb < 10; bb++) {
      const PetscReal *gb = m.dN[bb];
      const PetscReal  g  = -w * (fb.rho * N[a] * (wRate * N[bb] + cGradN[bb]) + fb.mu * (ga[0] * gb[0] + ga[1] * gb[1] + ga[2] * gb[2]));
      for (int mm = 0; mm < 3; mm++) wga[3 * bb + mm] = w * ga[mm], wGtdN[3 * bb + mm] = w * fb.mu * GtdN[a][mm], cG[3 * bb + mm] = g, cb[3 * bb + mm] = -w * N[a] * N[bb];
    }
    for (int i = 0; i < 3; i++) {
      const PetscReal wv  = w * (r[i] * N[a] - p.p * ga[i] + fb.mu * GsdN[a][i]);
      PetscReal      *row = &S[(3 * a + i) * 30];
      for (int j = 0; j < 30; j++) row[j] += wv * dN[j] + wga[j] * X[i][j] - cols.dN[i][j] * wGtdN[j] + cG[j] * cols.G[i][j] + cb[j] * D[i][j];
    }
  }
  for (int k = 0; k < 4; k++)
    for (int j = 0; j < 30; j++) S[(30 + k) * 30 + j] -= w * l[k] * (dN[j] * div - GtdN[j / 3][j % 3]);
}

/* db_i/dx_j of the body force at x, by forward differences (manufactured data only) */
static void ForceGradient(const FluidForms &fb, const PetscReal x[3], PetscReal h, const PetscReal b[3], PetscReal db[3][3])
{
  for (int j = 0; j < 3; j++) {
    PetscReal y[3] = {x[0], x[1], x[2]}, bj[3] = {0, 0, 0};
    y[j] += h;
    fb.force(y, fb.time, bj);
    for (int i = 0; i < 3; i++) db[i][j] = (bj[i] - b[i]) / h;
  }
}

/* Element matrix of the 30 velocity and 4 pressure dofs (rows and columns in that order), and
   with the shape derivatives their derivative in the cell's 30 mesh displacement dofs. */
PetscErrorCode FluidJacobian(const FluidForms &fb, const PetscScalar *x, Mat P)
{
  const int                        n  = 34;
  std::vector<const PetscScalar *> past;

  PetscFunctionBegin;
  PetscCall(TimeHistoryGetPast(fb.history, past));
  const PetscReal mass  = past.empty() ? 0.0 : fb.rho * fb.history->first[0] / fb.history->dt; /* d(rho d_t u)/du */
  const PetscReal wRate = past.empty() ? 0.0 : fb.history->first[0] / fb.history->dt;          /* d w / d d_f */
  const PetscBool shape = (PetscBool)(fb.shapeDerivatives && fb.mesh);
  std::vector<std::vector<std::pair<const TractionGroup *, const CellFace *>>> cellFaces(shape ? fb.velocity.Size() : 0);
  for (const TractionGroup &tg : fb.tractions) /* the traction faces of each cell: they move with its d_f */
    for (const CellFace &face : tg.faces)
      if (shape) cellFaces[face.k].push_back({&tg, &face});
  for (PetscInt k = 0; k < fb.velocity.Size(); k++) {
    const CellGeometry &g = fb.velocity.geom[k];
    CellState           s;
    PetscReal           K[34 * 34] = {0}, S[34 * 30] = {0};
    PetscInt            idx[34];
    GatherState(fb, k, x, past, s);
    CellIndices(fb, k, idx);
    for (PetscInt q = 0; q < fb.rule.nq; q++) {
      const PetscReal *l = &fb.rule.lambda[4 * q], *N = &fb.rule.N[10 * q];
      MovedPoint       m;
      FlowPoint        p;
      if (MovePoint(g, fb.mesh ? s.d : nullptr, l, N, m) <= 0) continue; /* the residual reported it */
      Evaluate(s, N, l, m, p);
      const PetscReal w = fb.rule.w[q] * g.detE * m.J;
      PetscReal cGradN[10]; /* (u - w) . grad N_b */
      for (int b = 0; b < 10; b++) cGradN[b] = (p.u[0] - p.w[0]) * m.dN[b][0] + (p.u[1] - p.w[1]) * m.dN[b][1] + (p.u[2] - p.w[2]) * m.dN[b][2];
      Columns cols;
      ColumnsAt(N, m, p, cols);
      /* K_(ai)(bk) = delta_ik [N_a (mass N_b + rho (u - w).grad N_b) + mu grad N_a . grad N_b] + rho N_a N_b du_i/dx_k + mu dN_b/dx_i dN_a/dx_k */
      for (int a = 0; a < 10; a++) {
        const PetscReal wrN = w * fb.rho * N[a];
        PetscReal       wmudNa[30], diag[10];
        for (int b = 0; b < 10; b++) {
          const PetscReal gg = m.dN[a][0] * m.dN[b][0] + m.dN[a][1] * m.dN[b][1] + m.dN[a][2] * m.dN[b][2];
          diag[b]            = w * (N[a] * (mass * N[b] + fb.rho * cGradN[b]) + fb.mu * gg);
          for (int kk = 0; kk < 3; kk++) wmudNa[3 * b + kk] = w * fb.mu * m.dN[a][kk];
        }
        for (int i = 0; i < 3; i++) {
          PetscReal *row = &K[(3 * a + i) * n];
          for (int j = 0; j < 30; j++) row[j] += wrN * cols.N[j] * cols.G[i][j] + cols.dN[i][j] * wmudNa[j];
          for (int b = 0; b < 10; b++) row[3 * b + i] += diag[b];
        }
      }
      for (int a = 0; a < 10; a++)
        for (int i = 0; i < 3; i++)
          for (int c = 0; c < 4; c++) {
            K[(3 * a + i) * n + 30 + c] -= w * l[c] * m.dN[a][i]; /* - p div v */
            K[(30 + c) * n + 3 * a + i] -= w * l[c] * m.dN[a][i]; /* - q div u */
          }
      if (shape) {
        PetscReal b[3] = {0, 0, 0}, db[3][3] = {{0}};
        if (fb.force) {
          fb.force(m.x, fb.time, b);
          ForceGradient(fb, m.x, DifferenceStep(g), b, db);
        }
        VolumeShapeDerivatives(fb, N, l, m, p, cols, cGradN, w, wRate, b, db, S);
      }
    }
    PetscCall(AddElementMatrix(P, n, idx, n, idx, K));
    if (shape) {
      if (!cellFaces[k].empty()) FaceShapeDerivatives(fb, k, s.d, cellFaces[k], S);
      PetscCall(AddElementMatrix(P, n, idx, 30, &fb.mesh->global[30 * k], S));
    }
  }
  if (fb.backflowBeta > 0)
    for (const CellFace &face : fb.backflow) {
      PetscReal ru[30] = {0}, ue[30], de[30], K[30 * 30] = {0};
      Gather(fb.velocity, face.k, x, ue);
      if (fb.mesh) Gather(*fb.mesh, face.k, x, de);
      BackflowFace(fb, face, ue, fb.mesh ? de : nullptr, ru, K);
      PetscCall(AddElementMatrix(P, 30, &fb.velocity.global[30 * face.k], 30, &fb.velocity.global[30 * face.k], K));
    }
  PetscCall(TimeHistoryRestorePast(fb.history, past));
  PetscFunctionReturn(0);
}

void FluidCouplings(const FluidForms &fb, Sparsity &s)
{
  for (PetscInt k = 0; k < fb.velocity.Size(); k++) {
    PetscInt idx[34];
    CellIndices(fb, k, idx);
    s.Couple(34, idx, 34, idx);
    if (fb.shapeDerivatives && fb.mesh) s.Couple(34, idx, 30, &fb.mesh->global[30 * k]);
  }
}

PetscErrorCode FluidFaceIntegrals(DM dm, const FluidForms &fb, const std::vector<CellFace> &faces, const PetscScalar *x, PetscReal v[3])
{
  PetscReal sum[3] = {0, 0, 0};

  PetscFunctionBegin;
  for (const CellFace &face : faces) {
    PetscReal ue[30], de[30], pv[4], pe[10];
    Gather(fb.velocity, face.k, x, ue);
    Gather(fb.pressure, face.k, x, pv);
    for (int a = 0; a < 10; a++) pe[a] = a < 4 ? pv[a] : (pv[EdgeVertex[a - 4][0]] + pv[EdgeVertex[a - 4][1]]) / 2; /* P1 in the P2 basis */
    if (fb.mesh) Gather(*fb.mesh, face.k, x, de);
    ForEachFacePoint(fb, face, fb.mesh ? de : nullptr, [&](const PetscReal N[10], const PetscReal *, const PetscReal n[3], PetscReal w) {
      for (int a = 0; a < 10; a++) sum[0] += w * N[a] * (ue[3 * a] * n[0] + ue[3 * a + 1] * n[1] + ue[3 * a + 2] * n[2]), sum[1] += w * N[a] * pe[a];
      sum[2] += w;
    });
  }
  PetscCallMPI(MPIU_Allreduce(sum, v, 3, MPIU_REAL, MPIU_SUM, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

PetscErrorCode FluidFlux(DM dm, const FluidForms &fb, const std::vector<CellFace> &faces, Vec X, PetscReal *flux)
{
  Vec                Xl;
  const PetscScalar *x;
  PetscReal          v[3];

  PetscFunctionBegin;
  PetscCall(DMGetLocalVector(dm, &Xl));
  PetscCall(DMGlobalToLocal(dm, X, INSERT_VALUES, Xl));
  PetscCall(InsertEssentialValues(dm, fb.time, Xl));
  PetscCall(VecGetArrayRead(Xl, &x));
  PetscCall(FluidFaceIntegrals(dm, fb, faces, x, v));
  PetscCall(VecRestoreArrayRead(Xl, &x));
  PetscCall(DMRestoreLocalVector(dm, &Xl));
  *flux = v[0];
  PetscFunctionReturn(0);
}

PetscErrorCode FluidFaceNormSquared(DM dm, const FluidForms &fb, const FieldCells &v, const std::vector<CellFace> &faces, const PetscScalar *x, PetscReal *norm2)
{
  PetscReal sum = 0;

  PetscFunctionBegin;
  for (const CellFace &face : faces) {
    PetscReal ve[30];
    Gather(v, face.k, x, ve);
    ForEachFacePoint(fb, face, nullptr, [&](const PetscReal N[10], const PetscReal *, const PetscReal *, PetscReal w) {
      for (int c = 0; c < 3; c++) {
        PetscReal vc = 0;
        for (int a = 0; a < 10; a++) vc += N[a] * ve[3 * a + c];
        sum += w * vc * vc;
      }
    });
  }
  PetscCallMPI(MPIU_Allreduce(&sum, norm2, 1, MPIU_REAL, MPIU_SUM, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

} // namespace fsi
