#include "assembly.h"
#include "discretization/nodes.h"

namespace fsi {

/* Velocity, its gradient G[i][j] = du_i/dx_j, and pressure at one point of a cell. */
struct FlowPoint {
  PetscReal u[3], G[3][3], p;
};

static void Evaluate(const PetscReal ue[30], const PetscReal pe[4], const PetscReal N[10], const PetscReal dN[10][3], const PetscReal l[4], FlowPoint &f)
{
  f.p = l[0] * pe[0] + l[1] * pe[1] + l[2] * pe[2] + l[3] * pe[3];
  for (int i = 0; i < 3; i++) {
    f.u[i] = 0;
    for (int j = 0; j < 3; j++) f.G[i][j] = 0;
    for (int a = 0; a < 10; a++) {
      f.u[i] += N[a] * ue[3 * a + i];
      for (int j = 0; j < 3; j++) f.G[i][j] += dN[a][j] * ue[3 * a + i];
    }
  }
}

/* The traction groups: at face point q the outward normal, the point, and the area weight. */
template <class Body>
static void ForEachFacePoint(const FluidBlock &fb, const CellFace &f, Body body)
{
  const CellGeometry &g = fb.velocity.geom[f.k];
  PetscReal           e1[3], e2[3], n[3];
  for (int d = 0; d < 3; d++) e1[d] = g.x[f.slot[1]][d] - g.x[f.slot[0]][d], e2[d] = g.x[f.slot[2]][d] - g.x[f.slot[0]][d];
  n[0] = e1[1] * e2[2] - e1[2] * e2[1], n[1] = e1[2] * e2[0] - e1[0] * e2[2], n[2] = e1[0] * e2[1] - e1[1] * e2[0];
  const PetscReal area2 = PetscSqrtReal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]); /* twice the face's area */
  for (int d = 0; d < 3; d++) n[d] *= f.sign / area2;
  for (PetscInt q = 0; q < fb.faceRule.nq; q++) {
    PetscReal l[4] = {0, 0, 0, 0}, N[10], x[3];
    for (int a = 0; a < 3; a++) l[f.slot[a]] = fb.faceRule.mu[3 * q + a];
    P2Values(l, N);
    for (int d = 0; d < 3; d++) x[d] = l[0] * g.x[0][d] + l[1] * g.x[1][d] + l[2] * g.x[2][d] + l[3] * g.x[3][d];
    body(N, x, n, fb.faceRule.w[q] * area2);
  }
}

/* rho c_0 / dt: the coefficient of u^(n+1) in rho d_t u (0 for a steady flow) */
static PetscReal MassFactor(const FluidBlock &fb)
{
  return fb.history && !fb.history->past.empty() ? fb.rho * fb.history->first[0] / fb.history->dt : 0.0;
}

PetscErrorCode FluidResidual(DM dm, Vec Xl, Vec Fl, void *ctx)
{
  const FluidBlock                &fb = *(FluidBlock *)ctx;
  const PetscScalar               *x;
  PetscScalar                     *f;
  std::vector<const PetscScalar *> past;

  PetscFunctionBegin;
  PetscCall(InsertEssentialValues(dm, fb.time, Xl));
  PetscCall(VecZeroEntries(Fl));
  PetscCall(VecGetArrayRead(Xl, &x));
  PetscCall(VecGetArray(Fl, &f));
  if (MassFactor(fb))
    for (Vec v : fb.history->past) {
      const PetscScalar *y;
      PetscCall(VecGetArrayRead(v, &y));
      past.push_back(y);
    }
  for (PetscInt k = 0; k < fb.velocity.Size(); k++) {
    const CellGeometry &g = fb.velocity.geom[k];
    PetscReal           ue[30], pe[4], ru[30] = {0}, rp[4] = {0};
    Gather(fb.velocity, k, x, ue);
    Gather(fb.pressure, k, x, pe);
    if (!past.empty()) { /* rho M sum_j c_j u^(n+1-j) / dt */
      PetscReal dudt[30], y[30];
      for (int i = 0; i < 30; i++) dudt[i] = fb.history->first[0] * ue[i];
      for (size_t j = 0; j < past.size() && fb.history->first[j + 1] != 0; j++) {
        Gather(fb.velocity, k, past[j], y);
        for (int i = 0; i < 30; i++) dudt[i] += fb.history->first[j + 1] * y[i];
      }
      for (int a = 0; a < 10; a++)
        for (int b = 0; b < 10; b++)
          for (int i = 0; i < 3; i++) ru[3 * a + i] += fb.rho / fb.history->dt * g.detE * fb.mass[a * 10 + b] * dudt[3 * b + i];
    }
    for (PetscInt q = 0; q < fb.rule.nq; q++) {
      const PetscReal *l = &fb.rule.lambda[4 * q], *N = &fb.rule.N[10 * q], w = fb.rule.w[q] * g.detE;
      PetscReal        dN[10][3];
      FlowPoint        s;
      P2Gradients(g, l, dN);
      Evaluate(ue, pe, N, dN, l, s);
      const PetscReal div = s.G[0][0] + s.G[1][1] + s.G[2][2];
      PetscReal       conv[3];
      for (int i = 0; i < 3; i++) conv[i] = fb.rho * (s.u[0] * s.G[i][0] + s.u[1] * s.G[i][1] + s.u[2] * s.G[i][2]);
      for (int a = 0; a < 10; a++)
        for (int i = 0; i < 3; i++) {
          PetscReal v = conv[i] * N[a] - s.p * dN[a][i];
          for (int j = 0; j < 3; j++) v += fb.mu * (s.G[i][j] + s.G[j][i]) * dN[a][j];
          ru[3 * a + i] += w * v;
        }
      for (int c = 0; c < 4; c++) rp[c] -= w * l[c] * div;
    }
    Scatter(fb.velocity, k, ru, f);
    Scatter(fb.pressure, k, rp, f);
  }
  for (const TractionGroup &tg : fb.tractions)
    for (const CellFace &face : tg.faces) {
      PetscReal ru[30] = {0};
      ForEachFacePoint(fb, face, [&](const PetscReal N[10], const PetscReal xq[3], const PetscReal n[3], PetscReal w) {
        PetscReal t[3];
        tg.traction(xq, n, fb.time, t);
        for (int a = 0; a < 10; a++)
          for (int i = 0; i < 3; i++) ru[3 * a + i] -= w * t[i] * N[a];
      });
      Scatter(fb.velocity, face.k, ru, f);
    }
  for (size_t j = 0; j < past.size(); j++) PetscCall(VecRestoreArrayRead(fb.history->past[j], &past[j]));
  PetscCall(VecRestoreArray(Fl, &f));
  PetscCall(VecRestoreArrayRead(Xl, &x));
  PetscFunctionReturn(0);
}

/* Element matrix of the 30 velocity and 4 pressure dofs (rows and columns in that order). */
PetscErrorCode FluidJacobian(DM dm, Vec Xl, Mat J, Mat P, void *ctx)
{
  const FluidBlock  &fb   = *(FluidBlock *)ctx;
  const PetscReal    mass = MassFactor(fb);
  const PetscScalar *x;
  const int          n = 34;

  PetscFunctionBegin;
  PetscCall(InsertEssentialValues(dm, fb.time, Xl));
  PetscCall(MatZeroEntries(P));
  PetscCall(VecGetArrayRead(Xl, &x));
  for (PetscInt k = 0; k < fb.velocity.Size(); k++) {
    const CellGeometry &g = fb.velocity.geom[k];
    PetscReal           ue[30], pe[4], K[34 * 34] = {0};
    PetscInt            idx[34];
    Gather(fb.velocity, k, x, ue);
    Gather(fb.pressure, k, x, pe);
    for (int i = 0; i < 30; i++) idx[i] = fb.velocity.global[30 * k + i];
    for (int c = 0; c < 4; c++) idx[30 + c] = fb.pressure.global[4 * k + c];
    if (mass)
      for (int a = 0; a < 10; a++)
        for (int b = 0; b < 10; b++)
          for (int i = 0; i < 3; i++) K[(3 * a + i) * n + 3 * b + i] += mass * g.detE * fb.mass[a * 10 + b];
    for (PetscInt q = 0; q < fb.rule.nq; q++) {
      const PetscReal *l = &fb.rule.lambda[4 * q], *N = &fb.rule.N[10 * q], w = fb.rule.w[q] * g.detE;
      PetscReal        dN[10][3];
      FlowPoint        s;
      P2Gradients(g, l, dN);
      Evaluate(ue, pe, N, dN, l, s);
      for (int a = 0; a < 10; a++)
        for (int b = 0; b < 10; b++) {
          const PetscReal uGradNb = s.u[0] * dN[b][0] + s.u[1] * dN[b][1] + s.u[2] * dN[b][2];
          const PetscReal gg      = dN[a][0] * dN[b][0] + dN[a][1] * dN[b][1] + dN[a][2] * dN[b][2];
          for (int i = 0; i < 3; i++)
            for (int kk = 0; kk < 3; kk++) /* rho N_a (N_b du_i/dx_k + delta_ik u.grad N_b) + mu (delta_ik grad N_a.grad N_b + dN_b/dx_i dN_a/dx_k) */
              K[(3 * a + i) * n + 3 * b + kk] += w * (fb.rho * N[a] * (N[b] * s.G[i][kk] + (i == kk) * uGradNb) + fb.mu * ((i == kk) * gg + dN[b][i] * dN[a][kk]));
        }
      for (int a = 0; a < 10; a++)
        for (int i = 0; i < 3; i++)
          for (int c = 0; c < 4; c++) {
            K[(3 * a + i) * n + 30 + c] -= w * l[c] * dN[a][i]; /* - p div v */
            K[(30 + c) * n + 3 * a + i] -= w * l[c] * dN[a][i]; /* - q div u */
          }
    }
    PetscCall(MatSetValues(P, n, idx, n, idx, K, ADD_VALUES));
  }
  PetscCall(VecRestoreArrayRead(Xl, &x));
  PetscCall(AssembleOperators(J, P));
  PetscFunctionReturn(0);
}

PetscErrorCode FluidFlux(DM dm, const FluidBlock &fb, const std::vector<CellFace> &faces, Vec X, PetscReal *flux)
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
    PetscReal ue[30];
    Gather(fb.velocity, face.k, x, ue);
    ForEachFacePoint(fb, face, [&](const PetscReal N[10], const PetscReal *, const PetscReal n[3], PetscReal w) {
      for (int a = 0; a < 10; a++) sum += w * N[a] * (ue[3 * a] * n[0] + ue[3 * a + 1] * n[1] + ue[3 * a + 2] * n[2]);
    });
  }
  PetscCall(VecRestoreArrayRead(Xl, &x));
  PetscCall(DMRestoreLocalVector(dm, &Xl));
  PetscCallMPI(MPIU_Allreduce(&sum, flux, 1, MPIU_REAL, MPIU_SUM, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

} // namespace fsi
