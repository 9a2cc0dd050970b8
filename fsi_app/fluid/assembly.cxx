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

/* The traction groups: at face point q of the face in the current configuration (de: the
   cell's mesh displacement, or nullptr), the basis values, the point, the outward unit normal
   and the area weight; n da = J F^-T N dA (Nanson). */
template <class Body>
static void ForEachFacePoint(const FluidForms &fb, const CellFace &f, const PetscReal *de, Body body)
{
  const CellGeometry &g = fb.velocity.geom[f.k];
  PetscReal           e1[3], e2[3], N0[3];
  for (int d = 0; d < 3; d++) e1[d] = g.x[f.slot[1]][d] - g.x[f.slot[0]][d], e2[d] = g.x[f.slot[2]][d] - g.x[f.slot[0]][d];
  N0[0] = e1[1] * e2[2] - e1[2] * e2[1], N0[1] = e1[2] * e2[0] - e1[0] * e2[2], N0[2] = e1[0] * e2[1] - e1[1] * e2[0];
  const PetscReal area2 = PetscSqrtReal(N0[0] * N0[0] + N0[1] * N0[1] + N0[2] * N0[2]); /* twice the reference face's area */
  for (int d = 0; d < 3; d++) N0[d] *= f.sign / area2;
  for (PetscInt q = 0; q < fb.faceRule.nq; q++) {
    PetscReal  l[4] = {0, 0, 0, 0}, N[10], n[3];
    MovedPoint m;
    for (int a = 0; a < 3; a++) l[f.slot[a]] = fb.faceRule.mu[3 * q + a];
    P2Values(l, N);
    MovePoint(g, de, l, N, m);
    for (int j = 0; j < 3; j++) n[j] = m.J * (m.Finv[0][j] * N0[0] + m.Finv[1][j] * N0[1] + m.Finv[2][j] * N0[2]);
    const PetscReal ratio = PetscSqrtReal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]); /* da / dA */
    for (int d = 0; d < 3; d++) n[d] /= ratio;
    body(N, m.x, n, fb.faceRule.w[q] * area2 * ratio);
  }
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

PetscErrorCode FluidResidual(void *ctx, const PetscScalar *x, PetscScalar *f)
{
  const FluidForms                &fb = *(FluidForms *)ctx;
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
  PetscCall(TimeHistoryRestorePast(fb.history, past));
  ((FluidForms *)ctx)->inverted = inverted;
  PetscCall(ReportInverted(fb, inverted));
  PetscFunctionReturn(0);
}

/* The shape derivatives D_{d_f} R of cell k: the derivative of its volume and traction terms
   (rows: 30 velocity, 4 pressure dofs) in its 30 mesh displacement dofs, by forward
   differences of the element residual (the mesh velocity w moves with d_f by c_0 / dt). The
   step is sqrt(machine epsilon) of the cell's size, where truncation and round-off are both
   ~1e-8 relative: Newton stays quadratic down to the coupled tolerance, at half the cost of
   central differences (31 cell residuals instead of 60). */
static void ShapeDerivatives(const FluidForms &fb, PetscInt k, const CellState &s, const std::vector<std::pair<const TractionGroup *, const CellFace *>> &faces, PetscReal K[34 * 30])
{
  const CellGeometry &g = fb.velocity.geom[k];
  const PetscReal     h = PetscSqrtReal(PETSC_MACHINE_EPSILON) * PetscCbrtReal(g.detE), wRate = fb.history && !fb.history->past.empty() ? fb.history->first[0] / fb.history->dt : 0.0;
  auto residual = [&](const CellState &t, PetscReal r[34]) {
    for (int i = 0; i < 34; i++) r[i] = 0;
    CellResidual(fb, k, t, r, r + 30);
    for (const auto &tf : faces) FaceResidual(fb, *tf.first, *tf.second, t.d, r);
  };
  PetscReal r0[34];
  residual(s, r0);
  for (int j = 0; j < 30; j++) {
    PetscReal r[34];
    CellState t = s;
    t.d[j] += h, t.w[j] += wRate * h;
    residual(t, r);
    for (int i = 0; i < 34; i++) K[i * 30 + j] = (r[i] - r0[i]) / h;
  }
}

/* Element matrix of the 30 velocity and 4 pressure dofs (rows and columns in that order). */
PetscErrorCode FluidJacobian(void *ctx, const PetscScalar *x, Mat P)
{
  const FluidForms                &fb = *(FluidForms *)ctx;
  const int                        n  = 34;
  std::vector<const PetscScalar *> past;

  PetscFunctionBegin;
  PetscCall(TimeHistoryGetPast(fb.history, past));
  const PetscReal mass = past.empty() ? 0.0 : fb.rho * fb.history->first[0] / fb.history->dt; /* d(rho d_t u)/du */
  std::vector<std::vector<std::pair<const TractionGroup *, const CellFace *>>> cellFaces(fb.shapeDerivatives ? fb.velocity.Size() : 0);
  for (const TractionGroup &tg : fb.tractions) /* the traction faces of each cell: they move with its d_f */
    for (const CellFace &face : tg.faces)
      if (fb.shapeDerivatives) cellFaces[face.k].push_back({&tg, &face});
  for (PetscInt k = 0; k < fb.velocity.Size(); k++) {
    const CellGeometry &g = fb.velocity.geom[k];
    CellState           s;
    PetscReal           K[34 * 34] = {0};
    PetscInt            idx[34];
    GatherState(fb, k, x, past, s);
    for (int i = 0; i < 30; i++) idx[i] = fb.velocity.global[30 * k + i];
    for (int c = 0; c < 4; c++) idx[30 + c] = fb.pressure.global[4 * k + c];
    for (PetscInt q = 0; q < fb.rule.nq; q++) {
      const PetscReal *l = &fb.rule.lambda[4 * q], *N = &fb.rule.N[10 * q];
      MovedPoint       m;
      FlowPoint        p;
      if (MovePoint(g, fb.mesh ? s.d : nullptr, l, N, m) <= 0) continue; /* the residual reported it */
      Evaluate(s, N, l, m, p);
      const PetscReal w = fb.rule.w[q] * g.detE * m.J;
      PetscReal cGradN[10]; /* (u - w) . grad N_b */
      for (int b = 0; b < 10; b++) cGradN[b] = (p.u[0] - p.w[0]) * m.dN[b][0] + (p.u[1] - p.w[1]) * m.dN[b][1] + (p.u[2] - p.w[2]) * m.dN[b][2];
      /* K_(ai)(bk) = delta_ik [N_a (mass N_b + rho (u - w).grad N_b) + mu grad N_a . grad N_b] + rho N_a N_b du_i/dx_k + mu dN_b/dx_i dN_a/dx_k */
      for (int a = 0; a < 10; a++)
        for (int b = 0; b < 10; b++) {
          const PetscReal gg   = m.dN[a][0] * m.dN[b][0] + m.dN[a][1] * m.dN[b][1] + m.dN[a][2] * m.dN[b][2];
          const PetscReal diag = w * (N[a] * (mass * N[b] + fb.rho * cGradN[b]) + fb.mu * gg), nn = w * fb.rho * N[a] * N[b], wmu = w * fb.mu;
          PetscReal      *Kab  = &K[3 * a * n + 3 * b];
          for (int i = 0; i < 3; i++) {
            for (int kk = 0; kk < 3; kk++) Kab[i * n + kk] += nn * p.G[i][kk] + wmu * m.dN[b][i] * m.dN[a][kk];
            Kab[i * n + i] += diag;
          }
        }
      for (int a = 0; a < 10; a++)
        for (int i = 0; i < 3; i++)
          for (int c = 0; c < 4; c++) {
            K[(3 * a + i) * n + 30 + c] -= w * l[c] * m.dN[a][i]; /* - p div v */
            K[(30 + c) * n + 3 * a + i] -= w * l[c] * m.dN[a][i]; /* - q div u */
          }
    }
    PetscCall(MatSetValues(P, n, idx, n, idx, K, ADD_VALUES));
    if (fb.shapeDerivatives && fb.mesh) {
      PetscReal S[34 * 30];
      ShapeDerivatives(fb, k, s, cellFaces[k], S);
      PetscCall(MatSetValues(P, n, idx, 30, &fb.mesh->global[30 * k], S, ADD_VALUES));
    }
  }
  PetscCall(TimeHistoryRestorePast(fb.history, past));
  PetscFunctionReturn(0);
}

PetscErrorCode FluidFlux(DM dm, const FluidForms &fb, const std::vector<CellFace> &faces, Vec X, PetscReal *flux)
{
  Vec                Xl;
  const PetscScalar *x;
  PetscReal          sum = 0;

  PetscFunctionBegin;
  PetscCall(DMGetLocalVector(dm, &Xl));
  PetscCall(DMGlobalToLocal(dm, X, INSERT_VALUES, Xl));
  PetscCall(InsertEssentialValues(dm, fb.time, Xl));
  PetscCall(VecGetArrayRead(Xl, &x));
  for (const CellFace &face : faces) {
    PetscReal ue[30], de[30];
    Gather(fb.velocity, face.k, x, ue);
    if (fb.mesh) Gather(*fb.mesh, face.k, x, de);
    ForEachFacePoint(fb, face, fb.mesh ? de : nullptr, [&](const PetscReal N[10], const PetscReal *, const PetscReal n[3], PetscReal w) {
      for (int a = 0; a < 10; a++) sum += w * N[a] * (ue[3 * a] * n[0] + ue[3 * a + 1] * n[1] + ue[3 * a + 2] * n[2]);
    });
  }
  PetscCall(VecRestoreArrayRead(Xl, &x));
  PetscCall(DMRestoreLocalVector(dm, &Xl));
  PetscCallMPI(MPIU_Allreduce(&sum, flux, 1, MPIU_REAL, MPIU_SUM, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

} // namespace fsi
