// SPDX-License-Identifier: BSD-2-Clause
#include "wall_frame.h"
#include "base/files.h"
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace fsi {

static std::string ReadPoints(const char *option, const std::string &file, Centerline &c)
{
  std::ifstream     in;
  const std::string why = OpenInput(option, file, in);
  if (!why.empty()) return why;
  const std::string at = std::string(option) + " " + file + " line ";
  PetscInt          branch = 0, inBranch = 0;
  long              number = 0;
  for (std::string line; std::getline(in, line);) {
    number++;
    std::istringstream words(line.substr(0, line.find('#')));
    std::string        w[3], extra;
    if (!(words >> w[0])) { /* a blank line ends a branch */
      if (inBranch && line.find('#') == std::string::npos) branch++, inBranch = 0;
      continue;
    }
    if (!(words >> w[1] >> w[2]) || (words >> extra)) return at + std::to_string(number) + ": give three numbers, x y z (got '" + line + "')";
    PetscReal X[3];
    for (int d = 0; d < 3; d++) {
      char *end;
      X[d] = std::strtod(w[d].c_str(), &end);
      if (*end || end == w[d].c_str() || !std::isfinite(X[d])) return at + std::to_string(number) + ": '" + line + "' is not three finite numbers";
    }
    const size_t n = c.branch.size();
    if (inBranch && X[0] == c.x[3 * n - 3] && X[1] == c.x[3 * n - 2] && X[2] == c.x[3 * n - 1]) return at + std::to_string(number) + ": the point repeats the previous one (a segment of length 0)";
    c.x.insert(c.x.end(), X, X + 3), c.branch.push_back(branch), inBranch++;
  }
  if (c.branch.empty()) return std::string(option) + " " + file + ": no points";
  for (PetscInt b = 0; b <= c.branch.back(); b++)
    if (std::count(c.branch.begin(), c.branch.end(), b) < 2) return std::string(option) + " " + file + ": branch " + std::to_string(b + 1) + " has fewer than 2 points";
  return "";
}

/* each point's tangent: the mean of the unit directions of its branch's segments at it */
static void Tangents(Centerline &c)
{
  const PetscInt n = (PetscInt)c.branch.size();
  c.tangent.assign(3 * n, 0.0);
  for (PetscInt i = 0; i + 1 < n; i++) {
    if (c.branch[i] != c.branch[i + 1]) continue;
    PetscReal e[3], len = 0;
    for (int d = 0; d < 3; d++) e[d] = c.x[3 * i + 3 + d] - c.x[3 * i + d], len += e[d] * e[d];
    for (int d = 0; d < 3; d++) c.tangent[3 * i + d] += e[d] / std::sqrt(len), c.tangent[3 * i + 3 + d] += e[d] / std::sqrt(len);
  }
  for (PetscInt i = 0; i < n; i++) {
    PetscReal *t = &c.tangent[3 * i], len = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    for (int d = 0; d < 3; d++) t[d] /= len; /* a branch turning back on itself would make it 0: refused below */
  }
}

PetscErrorCode CenterlineRead(MPI_Comm comm, const char *option, const std::string &file, Centerline &c)
{
  PetscInt n;

  PetscFunctionBegin;
  c = Centerline();
  PetscCall(CheckOnRankZero(comm, PETSC_ERR_FILE_UNEXPECTED, [&]() {
    std::string why = ReadPoints(option, file, c);
    if (!why.empty()) return why;
    Tangents(c);
    for (PetscInt i = 0; i < (PetscInt)c.branch.size(); i++)
      if (!std::isfinite(c.tangent[3 * i])) return std::string(option) + " " + file + ": the centreline turns back on itself at point " + std::to_string(i + 1);
    return std::string();
  }));
  n = (PetscInt)c.branch.size();
  PetscCallMPI(MPI_Bcast(&n, 1, MPIU_INT, 0, comm));
  c.x.resize(3 * n), c.branch.resize(n), c.tangent.resize(3 * n);
  PetscCallMPI(MPI_Bcast(c.x.data(), (PetscMPIInt)(3 * n), MPIU_REAL, 0, comm));
  PetscCallMPI(MPI_Bcast(c.branch.data(), (PetscMPIInt)n, MPIU_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(c.tangent.data(), (PetscMPIInt)(3 * n), MPIU_REAL, 0, comm));
  PetscFunctionReturn(0);
}

/* The projection of X on segment s: its parameter in [0, 1] and squared distance. */
static PetscReal Project(const Centerline &c, PetscInt s, const PetscReal X[3], PetscReal *dist2)
{
  const PetscReal *a = &c.x[3 * s], *b = &c.x[3 * s + 3];
  PetscReal        ab = 0, ax = 0, y = 0;
  for (int d = 0; d < 3; d++) ab += (b[d] - a[d]) * (b[d] - a[d]), ax += (b[d] - a[d]) * (X[d] - a[d]);
  const PetscReal t = std::min((PetscReal)1, std::max((PetscReal)0, ax / ab));
  for (int d = 0; d < 3; d++) y += PetscSqr(X[d] - a[d] - t * (b[d] - a[d]));
  *dist2 = y;
  return t;
}

static bool IsSegment(const Centerline &c, PetscInt s)
{
  return s >= 0 && s + 1 < (PetscInt)c.branch.size() && c.branch[s] == c.branch[s + 1];
}

PetscInt CenterlineNearest(const Centerline &c, const PetscReal X[3])
{
  PetscInt  best = -1;
  PetscReal d2best = PETSC_MAX_REAL, d2;
  for (PetscInt s = 0; s + 1 < (PetscInt)c.branch.size(); s++)
    if (IsSegment(c, s) && (Project(c, s, X, &d2), d2 < d2best)) best = s, d2best = d2;
  return best;
}

static PetscReal Length(const Centerline &c, PetscInt s)
{
  return std::sqrt(PetscSqr(c.x[3 * s + 3] - c.x[3 * s]) + PetscSqr(c.x[3 * s + 4] - c.x[3 * s + 1]) + PetscSqr(c.x[3 * s + 5] - c.x[3 * s + 2]));
}

/* The tangent at parameter t of segment s: its direction, turned towards the point's tangent
   within half the shorter segment's length of each end it shares with the branch's next
   segment, linearly: continuous along the branch, and a long straight segment keeps its own
   direction but near its ends. */
static void AxialDirection(const Centerline &c, PetscInt s, PetscReal t, PetscReal ea[3])
{
  const PetscReal l = Length(c, s);
  for (int d = 0; d < 3; d++) ea[d] = (c.x[3 * s + 3 + d] - c.x[3 * s + d]) / l;
  PetscReal dir[3] = {ea[0], ea[1], ea[2]};
  for (int end = 0; end < 2; end++) {
    const PetscInt other = end ? s + 1 : s - 1, at = end ? s + 1 : s; /* the neighbouring segment, the shared point */
    if (!IsSegment(c, other) || c.branch[other] != c.branch[s]) continue;
    const PetscReal w = std::min(l, Length(c, other)) / 2, dist = (end ? 1 - t : t) * l;
    if (dist >= w) continue;
    for (int d = 0; d < 3; d++) ea[d] += (1 - dist / w) * (c.tangent[3 * at + d] - dir[d]);
  }
}

/* A cell's points look this many segments either side of its own (a cell may span several). */
static const PetscInt Reach = 4;

/* (X - P(t)) . e_a(t) on segment s, P(t) its point at t: zero where X lies in the centreline's
   normal plane at P. */
static PetscReal NormalOffset(const Centerline &c, PetscInt s, PetscReal t, const PetscReal X[3], PetscReal P[3], PetscReal ea[3])
{
  PetscReal g = 0;
  AxialDirection(c, s, t, ea);
  for (int d = 0; d < 3; d++) P[d] = (1 - t) * c.x[3 * s + d] + t * c.x[3 * s + 3 + d], g += (X[d] - P[d]) * ea[d];
  return g;
}

bool CenterlineFrame(const Centerline &c, PetscInt s0, const PetscReal X[3], PetscReal frame[9])
{
  PetscReal *ea = frame, *er = frame + 3, *ec = frame + 6, P[3], best = PETSC_MAX_REAL, na = 0, nr = 0, along = 0;
  PetscBool  found = PETSC_FALSE;
  /* P: where X's normal plane meets the cell's segment or a neighbour (a bent branch's normal
     planes are its cross-sections; the nearest point of a chord is not), the nearest such */
  for (PetscInt j = s0 - Reach; j <= s0 + Reach; j++) {
    if (!IsSegment(c, j) || c.branch[j] != c.branch[s0]) continue;
    PetscReal a = 0, b = 1, ga, gb, t = 0, Pj[3], e[3];
    if ((ga = NormalOffset(c, j, a, X, Pj, e)) < 0 || (gb = NormalOffset(c, j, b, X, Pj, e)) > 0) continue;
    for (int it = 0; it < 60 && b - a > 1e-14; it++) { /* regula falsi (Illinois): g is nearly linear in t */
      t = ga - gb > 0 ? (a * (-gb) + b * ga) / (ga - gb) : (a + b) / 2;
      const PetscReal g = NormalOffset(c, j, t, X, Pj, e);
      if (PetscAbsReal(g) <= 1e-13 * Length(c, j)) break;
      if (g > 0) a = t, ga = g, gb /= 2;
      else b = t, gb = g, ga /= 2;
    }
    NormalOffset(c, j, t, X, Pj, e);
    const PetscReal dist = PetscSqr(X[0] - Pj[0]) + PetscSqr(X[1] - Pj[1]) + PetscSqr(X[2] - Pj[2]);
    if (dist >= best) continue;
    best = dist, found = PETSC_TRUE;
    for (int d = 0; d < 3; d++) P[d] = Pj[d], ea[d] = e[d];
  }
  if (!found) { /* beyond a branch's ends: the nearest point */
    PetscReal d2;
    const PetscReal t = Project(c, s0, X, &d2);
    NormalOffset(c, s0, t, X, P, ea);
  }
  for (int d = 0; d < 3; d++) na += ea[d] * ea[d];
  for (int d = 0; d < 3; d++) ea[d] /= std::sqrt(na), er[d] = X[d] - P[d], along += er[d] * ea[d];
  for (int d = 0; d < 3; d++) er[d] -= along * ea[d], nr += er[d] * er[d];
  if (!(nr > 0)) return false;
  for (int d = 0; d < 3; d++) er[d] /= std::sqrt(nr);
  ec[0] = ea[1] * er[2] - ea[2] * er[1], ec[1] = ea[2] * er[0] - ea[0] * er[2], ec[2] = ea[0] * er[1] - ea[1] * er[0];
  return true;
}

void FrameFibres(const PetscReal frame[9], PetscReal beta, PetscReal a[6])
{
  for (int d = 0; d < 3; d++) a[d] = std::cos(beta) * frame[6 + d] + std::sin(beta) * frame[d], a[3 + d] = std::cos(beta) * frame[6 + d] - std::sin(beta) * frame[d];
}

} // namespace fsi
