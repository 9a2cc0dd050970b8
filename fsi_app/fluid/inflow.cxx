// SPDX-License-Identifier: BSD-2-Clause
#include "inflow.h"
#include "base/ramp.h"
#include "discretization/nodes.h"
#include "discretization/p2tet.h"
#include <petscksp.h>

namespace fsi {

const char *const InflowProfileNames[] = {"plug", "parabolic", "womersley", "InflowProfileKind", "INFLOW_", nullptr};

using Node = std::array<PetscReal, 3>;

/* The inlet as P2 triangles, the same on every rank: 6 nodes each (vertices, then the edges
   01, 12, 20), numbered by position, ordered so that (x1 - x0) x (x2 - x0) points out of the fluid. */
struct Inlet {
  std::vector<Node>     node;
  std::vector<PetscInt> tri;  /* 6 per triangle */
  std::vector<char>     rim;  /* per node: on the inlet's boundary */
};

static PetscErrorCode GatherInlet(DM dm, const FieldCells &cells, const char *group, Inlet &in)
{
  MPI_Comm              comm = PetscObjectComm((PetscObject)dm);
  DMLabel               label;
  std::vector<CellFace> faces;
  std::vector<PetscReal> mine, all;
  PetscMPIInt           size, n;

  PetscFunctionBegin;
  PetscCall(DMGetLabel(dm, group, &label));
  PetscCall(CellFacesCreate(dm, cells, label, faces));
  for (const CellFace &f : faces) {
    int       s[3] = {f.slot[0], f.slot[1], f.slot[2]};
    PetscInt  nodes[6];
    PetscReal x[3];
    if (f.sign < 0) std::swap(s[1], s[2]);
    for (int a = 0; a < 3; a++) {
      nodes[a] = s[a];
      for (int e = 0; e < 6; e++)
        if ((EdgeVertex[e][0] == s[a] && EdgeVertex[e][1] == s[(a + 1) % 3]) || (EdgeVertex[e][1] == s[a] && EdgeVertex[e][0] == s[(a + 1) % 3])) nodes[3 + a] = 4 + e;
    }
    for (int a = 0; a < 6; a++) {
      PetscCall(NodePosition(dm, cells.point[10 * f.k + nodes[a]], x));
      mine.insert(mine.end(), x, x + 3);
    }
  }
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<PetscMPIInt> counts(size), offsets(size + 1, 0);
  n = (PetscMPIInt)mine.size();
  PetscCallMPI(MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
  for (PetscMPIInt r = 0; r < size; r++) offsets[r + 1] = offsets[r] + counts[r];
  all.resize(offsets[size]);
  PetscCallMPI(MPI_Allgatherv(mine.data(), n, MPIU_REAL, all.data(), counts.data(), offsets.data(), MPIU_REAL, comm));
  PetscCheck(!all.empty(), comm, PETSC_ERR_ARG_WRONG, "-fluid_inlet %s: no face of the group bounds a fluid cell; the inflow needs the inlet's faces", group);
  std::map<Node, PetscInt> number;
  for (size_t k = 0; k < all.size(); k += 3) {
    const Node x = {all[k], all[k + 1], all[k + 2]};
    auto       it = number.find(x);
    if (it == number.end()) it = number.insert({x, (PetscInt)in.node.size()}).first, in.node.push_back(x);
    in.tri.push_back(it->second);
  }
  std::map<std::pair<PetscInt, PetscInt>, int> edges; /* vertex pairs: an edge of one triangle is on the rim */
  for (size_t t = 0; t < in.tri.size(); t += 6)
    for (int a = 0; a < 3; a++) edges[std::minmax(in.tri[t + a], in.tri[t + (a + 1) % 3])]++;
  in.rim.assign(in.node.size(), 0);
  for (size_t t = 0; t < in.tri.size(); t += 6)
    for (int a = 0; a < 3; a++)
      if (edges[std::minmax(in.tri[t + a], in.tri[t + (a + 1) % 3])] == 1) in.rim[in.tri[t + a]] = in.rim[in.tri[t + (a + 1) % 3]] = in.rim[in.tri[t + 3 + a]] = 1;
  PetscFunctionReturn(0);
}

/* The P2 triangle at barycentric point l = (l0, l1, l2): basis values and their derivatives
   in (xi, eta) = (l1, l2); the map x(xi, eta) of the curved triangle through its 6 nodes. */
static void TriangleP2(const PetscReal l[3], PetscReal N[6], PetscReal dN[6][2])
{
  N[0] = l[0] * (2 * l[0] - 1), N[1] = l[1] * (2 * l[1] - 1), N[2] = l[2] * (2 * l[2] - 1);
  N[3] = 4 * l[0] * l[1], N[4] = 4 * l[1] * l[2], N[5] = 4 * l[2] * l[0];
  const PetscReal d[6][2] = {{1 - 4 * l[0], 1 - 4 * l[0]}, {4 * l[1] - 1, 0}, {0, 4 * l[2] - 1}, {4 * (l[0] - l[1]), -4 * l[1]}, {4 * l[2], 4 * l[1]}, {-4 * l[2], 4 * (l[0] - l[2])}};
  for (int a = 0; a < 6; a++) dN[a][0] = d[a][0], dN[a][1] = d[a][1];
}

/* body(t, N, dN, x, J, n da) at each point of the rule on each triangle: J the 3 x 2 tangent
   map, n da the outward area vector. */
template <class Body>
static void ForEachTrianglePoint(const Inlet &in, const FaceRule &rule, Body body)
{
  for (size_t t = 0; t < in.tri.size(); t += 6)
    for (PetscInt q = 0; q < rule.nq; q++) {
      PetscReal N[6], dN[6][2], x[3] = {0, 0, 0}, J[3][2] = {{0}}, n[3];
      TriangleP2(&rule.mu[3 * q], N, dN);
      for (int a = 0; a < 6; a++)
        for (int d = 0; d < 3; d++) {
          const PetscReal xa = in.node[in.tri[t + a]][d];
          x[d] += N[a] * xa, J[d][0] += dN[a][0] * xa, J[d][1] += dN[a][1] * xa;
        }
      n[0] = J[1][0] * J[2][1] - J[2][0] * J[1][1], n[1] = J[2][0] * J[0][1] - J[0][0] * J[2][1], n[2] = J[0][0] * J[1][1] - J[1][0] * J[0][1];
      for (int d = 0; d < 3; d++) n[d] *= rule.w[q];
      body(t, N, dN, x, J, n);
    }
}

/* -Delta phi = 1 on the inlet, phi = 0 on its rim: P2 on its triangles, solved on each rank. */
static PetscErrorCode SolvePoisson(const Inlet &in, const FaceRule &rule, std::vector<PetscReal> &phi)
{
  const PetscInt n = (PetscInt)in.node.size();
  Mat            K;
  Vec            b, x;
  KSP            ksp;
  PC             pc;

  PetscFunctionBegin;
  PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 40, nullptr, &K));
  PetscCall(MatSetOption(K, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, n, &b));
  PetscCall(VecDuplicate(b, &x));
  ForEachTrianglePoint(in, rule, [&](size_t t, const PetscReal N[6], const PetscReal dN[6][2], const PetscReal *, const PetscReal J[3][2], const PetscReal nda[3]) {
    const PetscReal g00 = J[0][0] * J[0][0] + J[1][0] * J[1][0] + J[2][0] * J[2][0], g01 = J[0][0] * J[0][1] + J[1][0] * J[1][1] + J[2][0] * J[2][1], g11 = J[0][1] * J[0][1] + J[1][1] * J[1][1] + J[2][1] * J[2][1];
    const PetscReal det = g00 * g11 - g01 * g01, da = PetscSqrtReal(nda[0] * nda[0] + nda[1] * nda[1] + nda[2] * nda[2]);
    const PetscReal inv[2][2] = {{g11 / det, -g01 / det}, {-g01 / det, g00 / det}}; /* the surface gradient's metric */
    for (int a = 0; a < 6; a++) {
      const PetscInt i = in.tri[t + a];
      if (in.rim[i]) continue;
      PetscScalar fa = N[a] * da;
      VecSetValue(b, i, fa, ADD_VALUES);
      for (int c = 0; c < 6; c++) {
        const PetscInt j = in.tri[t + c];
        if (in.rim[j]) continue;
        PetscScalar kac = da * (dN[a][0] * (inv[0][0] * dN[c][0] + inv[0][1] * dN[c][1]) + dN[a][1] * (inv[1][0] * dN[c][0] + inv[1][1] * dN[c][1]));
        MatSetValue(K, i, j, kac, ADD_VALUES);
      }
    }
  });
  for (PetscInt i = 0; i < n; i++)
    if (in.rim[i]) PetscCall(MatSetValue(K, i, i, 1.0, ADD_VALUES)); /* its row and column are otherwise empty */
  PetscCall(MatAssemblyBegin(K, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(K, MAT_FINAL_ASSEMBLY));
  PetscCall(VecAssemblyBegin(b));
  PetscCall(VecAssemblyEnd(b));
  PetscCall(KSPCreate(PETSC_COMM_SELF, &ksp));
  PetscCall(KSPSetOperators(ksp, K, K));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCCHOLESKY));
  PetscCall(KSPSolve(ksp, b, x));
  const PetscScalar *xa;
  PetscCall(VecGetArrayRead(x, &xa));
  phi.assign(xa, xa + n);
  PetscCall(VecRestoreArrayRead(x, &xa));
  PetscCall(KSPDestroy(&ksp));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  PetscCall(MatDestroy(&K));
  PetscFunctionReturn(0);
}

PetscErrorCode InflowProfileSetUp(DM dm, const FieldCells &velocity, const char *group, InflowProfile &p)
{
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  Inlet    in;
  FaceRule rule;

  PetscFunctionBegin;
  PetscCall(GatherInlet(dm, velocity, group, in));
  PetscCall(CreateFaceRule(4, rule));
  PetscReal c[3] = {0, 0, 0}, nda[3] = {0, 0, 0}; /* the area-weighted centre and normal */
  p.area = 0;
  ForEachTrianglePoint(in, rule, [&](size_t, const PetscReal *, const PetscReal(*)[2], const PetscReal x[3], const PetscReal(*)[2], const PetscReal n[3]) {
    const PetscReal da = PetscSqrtReal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int d = 0; d < 3; d++) c[d] += da * x[d], nda[d] += n[d];
    p.area += da;
  });
  const PetscReal len = PetscSqrtReal(nda[0] * nda[0] + nda[1] * nda[1] + nda[2] * nda[2]);
  for (int d = 0; d < 3; d++) p.centre[d] = c[d] / p.area, p.normal[d] = -nda[d] / len; /* into the fluid */
  PetscCheck(len > 0.99 * p.area, comm, PETSC_ERR_ARG_WRONG, "-fluid_inlet %s: the inflow needs a planar inlet (its faces' normals differ: |int n da| / area = %g)", group, (double)(len / p.area));

  const size_t n = in.node.size();
  std::vector<std::vector<std::complex<PetscReal>>> g(n); /* per node, per harmonic (one for plug and parabolic) */
  std::vector<PetscReal> radius(n);
  PetscReal              rimMin = PETSC_MAX_REAL, rimMax = 0, rimSum = 0, rimCount = 0;
  for (size_t i = 0; i < n; i++) {
    PetscReal y[3], along = 0;
    for (int d = 0; d < 3; d++) y[d] = in.node[i][d] - p.centre[d], along += y[d] * p.normal[d];
    radius[i] = PetscSqrtReal(PetscMax(y[0] * y[0] + y[1] * y[1] + y[2] * y[2] - along * along, 0.0));
    if (in.rim[i]) rimMin = PetscMin(rimMin, radius[i]), rimMax = PetscMax(rimMax, radius[i]), rimSum += radius[i], rimCount++;
  }
  if (p.kind == INFLOW_WOMERSLEY) {
    p.radius = rimSum / rimCount;
    PetscCheck(rimMax - rimMin < 0.03 * p.radius, comm, PETSC_ERR_ARG_WRONG, "-fluid_inflow_profile womersley: the inlet %s is not a circle (its rim nodes lie %g to %g from its centre); Womersley's profile needs a circular inlet: use parabolic", group, (double)rimMin, (double)rimMax);
    const std::vector<PetscReal> ab = p.flow.Harmonics(p.flow.fourier.empty() ? 20 : (PetscInt)(p.flow.fourier.size() / 2));
    p.womersley.SetUp(ab, p.flow.period, p.radius, p.rho, p.mu);
    for (size_t i = 0; i < n; i++)
      for (size_t k = 0; k < p.womersley.c.size(); k++) g[i].push_back(in.rim[i] ? 0.0 : p.womersley.Shape((PetscInt)k, radius[i]));
  } else {
    std::vector<PetscReal> phi(n, 1.0);
    if (p.kind == INFLOW_PARABOLIC) PetscCall(SolvePoisson(in, rule, phi));
    for (size_t i = 0; i < n; i++) g[i] = {in.rim[i] ? 0.0 : phi[i]};
  }
  /* each harmonic's flux through the inlet: its P2 interpolant's integral */
  std::vector<std::complex<PetscReal>> flux(g[0].size(), 0.0);
  ForEachTrianglePoint(in, rule, [&](size_t t, const PetscReal N[6], const PetscReal(*)[2], const PetscReal *, const PetscReal(*)[2], const PetscReal nv[3]) {
    const PetscReal da = PetscSqrtReal(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
    for (int a = 0; a < 6; a++)
      for (size_t k = 0; k < flux.size(); k++) flux[k] += N[a] * da * g[in.tri[t + a]][k];
  });
  if (p.kind == INFLOW_WOMERSLEY) { /* c_k = Q_k / (discrete flux of g_k) */
    const std::vector<PetscReal> ab = p.flow.Harmonics((PetscInt)flux.size() - 1);
    for (size_t k = 0; k < flux.size(); k++) p.womersley.c[k] = (k ? std::complex<PetscReal>(ab[2 * k - 1], -ab[2 * k]) : ab[0]) / flux[k];
    for (size_t i = 0; i < n; i++) p.values[in.node[i]] = g[i];
  } else
    for (size_t i = 0; i < n; i++) p.values[in.node[i]] = {g[i][0] / flux[0]};
  PetscFunctionReturn(0);
}

void InflowProfile::Velocity(const PetscReal x[3], PetscReal t, PetscScalar u[3]) const
{
  const auto it    = values.find({x[0], x[1], x[2]});
  PetscReal  speed = 0;
  if (it != values.end()) {
    if (kind == INFLOW_WOMERSLEY)
      for (size_t k = 0; k < it->second.size(); k++) speed += std::real(womersley.c[k] * it->second[k] * std::exp(std::complex<PetscReal>(0, k * womersley.omega * t)));
    else speed = flow.Value(t) * std::real(it->second[0]);
    speed *= SmoothRamp(t, ramp);
  }
  for (int d = 0; d < 3; d++) u[d] = speed * normal[d];
}

} // namespace fsi
