// SPDX-License-Identifier: BSD-2-Clause
#include "block.h"
#include "base/options.h"
#include "io/csv.h"
#include "discretization/ale_map.h"
#include "discretization/fields.h"
#include "mesh/mesh.h"
#include <petscsf.h>
#include <algorithm>
#include <sstream>

namespace fsi {

enum { Q = 0, P = 1, PI = 2 }; /* an outlet's unknowns, in this order at its cell */

PetscErrorCode OutletsBlock::Wire(const std::vector<Block *> &scene)
{
  PetscFunctionBegin;
  fluid    = FindBlock(scene, "fluid");
  geometry = FindBlock(scene, "geometry");
  PetscCheck(fluid, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-blocks: the outlets block models the vessels beyond the fluid's outlets; name fluid too");
  PetscFunctionReturn(0);
}

/* The options of a block the scene leaves out are read into nothing, but a 0D model ignored
   would change the answer without a word: refuse them. */
static PetscErrorCode RefuseWithoutBlock()
{
  char *all;

  PetscFunctionBegin;
  PetscCall(PetscOptionsGetAll(nullptr, &all));
  std::istringstream in(all);
  std::string        word, bad;
  while (in >> word)
    if (bad.empty() && word.rfind("-outlets_", 0) == 0 && word.find('<') == std::string::npos) bad = word;
  PetscCall(PetscFree(all));
  PetscCheck(bad.empty(), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s: the 0D outlet models are the outlets block's; add outlets to -blocks (with fluid)", bad.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode OutletsBlock::ReadOptions(std::map<std::string, std::string> &problem)
{
  PetscFunctionBegin;
  PetscOptionsBegin(PETSC_COMM_WORLD, nullptr, "fsi_app: the outlets block (0D models beyond the outlets of -fluid_outlet)", nullptr);
  const OptionReader       r{PetscOptionsObject, problem};
  std::vector<std::string> groups;
  if (fluid) groups = SplitList(fluid->Group("outlet").c_str());
  else groups = {"<group>"}; /* -help: the pattern */
  for (const std::string &g : groups) {
    const std::string rName = "-outlets_" + g + "_resistance", rcrName = "-outlets_" + g + "_rcr";
    std::vector<PetscReal> v, w; /* no model unless given */
    PetscCall(r.Numbers(rName.c_str(), "the outlet's resistance: P = R Q + P_d; R,P_d (dyn s/cm^5, dyn/cm^2; P_d 0 if left out)", v, 2, "numbers separated by commas", PROBLEM));
    PetscCall(r.Numbers(rcrName.c_str(), "three-element Windkessel: P = R_p Q + Pi, C dPi/dt + (Pi - P_d)/R_d = Q; R_p,C,R_d,P_d,Pi_0 (dyn s/cm^5, cm^5/dyn, dyn s/cm^5, dyn/cm^2, dyn/cm^2; P_d 0 and Pi_0 = P_d if left out): Pi_0 the capacitor's pressure at t = 0", w, 5, "numbers separated by commas", PROBLEM));
    const PetscBool isR = (PetscBool)!v.empty(), isRCR = (PetscBool)!w.empty();
    const PetscInt  nr = (PetscInt)v.size(), nrcr = (PetscInt)w.size();
    v.resize(2, 0.0), w.resize(5, 0.0);
    const std::string      waveName = "-outlets_" + g + "_pressure_waveform", fourierName = "-outlets_" + g + "_pressure_fourier";
    char                   wave[PETSC_MAX_PATH_LEN] = "";
    std::vector<PetscReal> fourier;
    PetscCall(r.String(waveName.c_str(), "a prescribed outlet pressure P(t) from a file of samples 't p' (s, dyn/cm^2) over one period, the last repeating the first; periodic cubic spline (named in an options file: relative to that file)", wave, sizeof(wave), PROBLEM));
    PetscCall(r.Numbers(fourierName.c_str(), "a prescribed outlet pressure P(t) = a0 + sum_k a_k cos(2 pi k t/T) + b_k sin(2 pi k t/T) as T,a0,a1,b1,... (s, dyn/cm^2)", fourier, 41, "numbers separated by commas; T, then at most 20 harmonics", PROBLEM));
    if (!fluid) continue;
    const PetscBool isP = (PetscBool)(wave[0] || !fourier.empty());
    PetscCheck((int)isR + (int)isRCR + (int)(wave[0] != 0) + (int)!fourier.empty() <= 1, PETSC_COMM_WORLD, PETSC_ERR_ARG_INCOMP, "-outlets_%s_*: one condition per outlet (a resistance, an RCR, or a pressure waveform or Fourier series)", g.c_str());
    Outlet o;
    o.group = g;
    if (isP) {
      PetscCheck(sc.Dynamic(), PETSC_COMM_WORLD, PETSC_ERR_ARG_INCOMP, "%s: the outlet pressure is a function of time: give a time step (-dt)", wave[0] ? waveName.c_str() : fourierName.c_str());
      if (wave[0]) PetscCall(WaveformRead(PETSC_COMM_WORLD, waveName.c_str(), wave, o.pressure));
      else PetscCall(WaveformFourier(fourierName.c_str(), fourier.data(), (PetscInt)fourier.size(), o.pressure));
      o.model = OUTLET_PRESSURE, o.P0 = o.pressure.Value(0);
    } else if (isR) {
      PetscCheck(nr >= 1 && v[0] > 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "%s: give R > 0 (and optionally P_d): R,P_d", rName.c_str());
      o.model = OUTLET_RESISTANCE, o.Rp = v[0], o.Pd = o.P0 = v[1];
    } else if (isRCR) {
      PetscCheck(nrcr >= 3 && w[0] >= 0 && w[1] > 0 && w[2] > 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "%s: give R_p >= 0, C > 0 and R_d > 0 (and optionally P_d and Pi_0): R_p,C,R_d,P_d,Pi_0", rcrName.c_str());
      o.model = OUTLET_RCR, o.Rp = w[0], o.C = w[1], o.Rd = w[2], o.Pd = w[3], o.P0 = nrcr == 5 ? w[4] : w[3];
    } else continue; /* traction-free */
    outlets.push_back(o);
  }
  PetscOptionsEnd();
  if (!fluid) PetscCall(RefuseWithoutBlock());
  else PetscCheck(!outlets.empty(), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-blocks ...,outlets: no outlet of -fluid_outlet %s has a model; give -outlets_<group>_resistance, _rcr, _pressure_waveform or _pressure_fourier, or leave outlets out of -blocks (traction-free outlets)", fluid->Group("outlet").c_str());
  if (fluid) {
    const std::string inlet = fluid->Group("inlet"), interface = geometry ? geometry->Group("interface") : "";
    for (const Outlet &o : outlets) PetscCheck(o.group != inlet && o.group != interface, PETSC_COMM_WORLD, PETSC_ERR_ARG_INCOMP, "-fluid_outlet %s: the outlet with a 0D model is also the %s; an outlet is a group of its own", o.group.c_str(), o.group == inlet ? "inlet (-fluid_inlet)" : "fluid-wall interface (-geometry_interface)");
  }
  PetscFunctionReturn(0);
}

/* One fluid cell this rank owns next to each outlet holds its unknowns: the outlet's rows then
   live where most of its velocity rows do. The lowest rank with such a cell takes it. */
PetscErrorCode OutletsBlock::AddFields(DM dm)
{
  MPI_Comm        comm = PetscObjectComm((PetscObject)dm);
  PetscMPIInt     rank;
  DMLabel           region, cells;
  std::vector<char> owned;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(GetRegionLabel(dm, fluid->Region(), &region));
  PetscCall(OwnedPoints(dm, owned));
  PetscCall(DMCreateLabel(dm, "outlet_cells"));
  PetscCall(DMGetLabel(dm, "outlet_cells", &cells));
  std::vector<PetscInt> taken;
  for (Outlet &o : outlets) {
    DMLabel     faces;
    PetscInt    mine = -1;
    PetscMPIInt first, candidate;
    PetscCall(DMGetLabel(dm, o.group.c_str(), &faces));
    if (faces) PetscCall(ForEachLabelPoint(faces, {}, [&](PetscInt face) -> PetscErrorCode {
      const PetscInt *support;
      PetscInt        n;
      PetscFunctionBegin;
      PetscCall(DMPlexGetSupportSize(dm, face, &n));
      PetscCall(DMPlexGetSupport(dm, face, &support));
      for (PetscInt s = 0; s < n && mine < 0; s++) {
        PetscInt v;
        PetscCall(DMLabelGetValue(region, support[s], &v));
        if (v == 1 && owned[support[s]] && std::find(taken.begin(), taken.end(), support[s]) == taken.end()) mine = support[s];
      }
      PetscFunctionReturn(0);
    }));
    candidate = mine >= 0 ? rank : PETSC_MPI_INT_MAX;
    PetscCallMPI(MPI_Allreduce(&candidate, &first, 1, MPI_INT, MPI_MIN, comm));
    PetscCheck(first != PETSC_MPI_INT_MAX, comm, PETSC_ERR_ARG_WRONG, "-fluid_outlet %s: no face of the group bounds a cell of -fluid_region %s; an outlet is a group of the fluid's boundary faces", o.group.c_str(), fluid->Region().c_str());
    if (first == rank) {
      PetscCall(DMLabelSetValue(cells, mine, 1));
      taken.push_back(mine);
      o.local = mine; /* the cell, until SetUp finds its offset */
    }
  }
  PetscCall(AddLagrangeField(dm, "outlets", "outlet_cells", 3, 0, &field));
  PetscFunctionReturn(0);
}

PetscErrorCode OutletsBlock::SetUp(DM dm)
{
  MPI_Comm     comm = PetscObjectComm((PetscObject)dm);
  PetscSection local, global;

  PetscFunctionBegin;
  velocity = fluid->Cells("velocity");
  mesh     = geometry ? geometry->Cells("geometry") : nullptr;
  PetscCall(CreateFaceRule(4, rule));
  PetscCall(DMGetLocalSection(dm, &local));
  PetscCall(DMGetGlobalSection(dm, &global));
  for (Outlet &o : outlets) {
    DMLabel   label;
    PetscInt  g = -1;
    PetscReal c[4] = {0, 0, 0, 0}; /* area-weighted centre, area */
    if (o.local >= 0) {
      const PetscInt cell = o.local;
      PetscCall(PetscSectionGetFieldOffset(local, cell, field, &o.local));
      PetscCall(PetscSectionGetOffset(global, cell, &g));
    }
    PetscCallMPI(MPIU_Allreduce(&g, &o.global, 1, MPIU_INT, MPI_MAX, comm));
    PetscCall(DMGetLabel(dm, o.group.c_str(), &label));
    PetscCall(CellFacesCreate(dm, *velocity, label, o.faces));
    for (const CellFace &face : o.faces)
      ForEachFacePoint(velocity->geom[face.k], rule, face, nullptr, [&](const PetscReal *, const PetscReal x[3], const PetscReal *, PetscReal w) {
        for (int d = 0; d < 3; d++) c[d] += w * x[d];
        c[3] += w;
      });
    PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, c, 4, MPIU_REAL, MPIU_SUM, comm));
    o.series.X = {c[0] / c[3], c[1] / c[3], c[2] / c[3]};
    o.series.nc = 3;
  }
  PetscFunctionReturn(0);
}

/* b[30 j + 3 a + i] = int phi_a n_i da over face j of the outlet, on the mesh moved by d_f. */
PetscErrorCode OutletsBlock::FaceWeights(const Outlet &o, const PetscScalar *x, std::vector<PetscReal> &b) const
{
  PetscFunctionBegin;
  b.assign(30 * o.faces.size(), 0.0);
  for (size_t j = 0; j < o.faces.size(); j++) {
    const CellFace &face = o.faces[j];
    PetscReal       de[30];
    if (mesh) Gather(*mesh, face.k, x, de);
    ForEachFacePoint(velocity->geom[face.k], rule, face, mesh ? de : nullptr, [&](const PetscReal N[10], const PetscReal *, const PetscReal n[3], PetscReal w) {
      for (int a = 0; a < 10; a++)
        for (int i = 0; i < 3; i++) b[30 * j + 3 * a + i] += w * N[a] * n[i];
    });
  }
  PetscFunctionReturn(0);
}

/* d/dt x_off = (c_0 x_off + sum_j c_j past_j[off]) / dt (0 in statics), and its derivative in x_off. */
static PetscReal RateCoefficient(const TimeHistory *h)
{
  return h && !h->past.empty() ? h->first[0] / h->dt : 0.0;
}

static PetscReal Rate(const TimeHistory *h, const PetscScalar *x, const std::vector<const PetscScalar *> &past, PetscInt off)
{
  if (!h || past.empty()) return 0.0;
  PetscReal r = h->first[0] * PetscRealPart(x[off]);
  for (size_t j = 0; j < past.size() && h->first[j + 1] != 0; j++) r += h->first[j + 1] * PetscRealPart(past[j][off]);
  return r / h->dt;
}

PetscErrorCode OutletsBlock::Residual(const PetscScalar *x, PetscScalar *f)
{
  const size_t                     K = outlets.size();
  std::vector<PetscReal>           sum(2 * K, 0.0); /* per outlet: int u . n, P */
  std::vector<std::vector<PetscReal>> b(K);
  std::vector<const PetscScalar *> past;

  PetscFunctionBegin;
  for (size_t k = 0; k < K; k++) {
    const Outlet &o = outlets[k];
    PetscCall(FaceWeights(o, x, b[k]));
    for (size_t j = 0; j < o.faces.size(); j++) {
      PetscReal ue[30];
      Gather(*velocity, o.faces[j].k, x, ue);
      for (int i = 0; i < 30; i++) sum[2 * k] += b[k][30 * j + i] * ue[i];
    }
    if (o.local >= 0) sum[2 * k + 1] = PetscRealPart(x[o.local + P]);
  }
  PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, sum.data(), (PetscMPIInt)sum.size(), MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
  PetscCall(TimeHistoryGetPast(history, past));
  for (size_t k = 0; k < K; k++) {
    const Outlet &o = outlets[k];
    for (size_t j = 0; j < o.faces.size(); j++) { /* the traction -P n */
      PetscReal re[30];
      for (int i = 0; i < 30; i++) re[i] = sum[2 * k + 1] * b[k][30 * j + i];
      Scatter(*velocity, o.faces[j].k, re, f);
    }
    if (o.local < 0) continue;
    const PetscScalar *y = &x[o.local];
    f[o.local + Q] += y[Q] - sum[2 * k];
    f[o.local + P] += y[P] - o.Rp * y[Q] - y[PI];
    if (o.model == OUTLET_RESISTANCE) f[o.local + PI] += y[PI] - o.Pd;
    else if (o.model == OUTLET_PRESSURE) f[o.local + PI] += y[PI] - o.pressure.Value(time);
    else f[o.local + PI] += o.C * Rate(history, x, past, o.local + PI) + (y[PI] - o.Pd) / o.Rd - y[Q];
  }
  PetscCall(TimeHistoryRestorePast(history, past));
  PetscFunctionReturn(0);
}

PetscErrorCode OutletsBlock::Jacobian(const PetscScalar *x, Mat J)
{
  PetscFunctionBegin;
  for (const Outlet &o : outlets) {
    std::vector<PetscReal> b;
    const PetscInt         gQ = o.global + Q, gP = o.global + P;
    PetscCall(FaceWeights(o, x, b));
    for (size_t j = 0; j < o.faces.size(); j++) {
      const PetscInt k = o.faces[j].k;
      PetscScalar    minus[30];
      for (int i = 0; i < 30; i++) minus[i] = -b[30 * j + i];
      PetscCall(MatSetValues(J, 30, &velocity->rows[30 * k], 1, &gP, &b[30 * j], ADD_VALUES));
      PetscCall(MatSetValues(J, 1, &gQ, 30, &velocity->global[30 * k], minus, ADD_VALUES));
    }
    if (o.local < 0) continue;
    const PetscInt    rows[3] = {o.global + Q, o.global + P, o.global + PI};
    const PetscBool   rcr     = (PetscBool)(o.model == OUTLET_RCR);
    const PetscScalar capacitor = rcr ? o.C * RateCoefficient(history) + 1 / o.Rd : 1.0, inflow = rcr ? -1.0 : 0.0;
    const PetscScalar A[9]      = {1, 0, 0, -o.Rp, 1, -1, inflow, 0, capacitor};
    PetscCall(MatSetValues(J, 3, rows, 3, rows, A, ADD_VALUES));
  }
  PetscFunctionReturn(0);
}

void OutletsBlock::Couplings(Sparsity &s) const
{
  for (const Outlet &o : outlets) {
    const PetscInt gQ = o.global + Q, gP = o.global + P, rows[3] = {o.global + Q, o.global + P, o.global + PI};
    for (const CellFace &face : o.faces) {
      s.Couple(30, &velocity->rows[30 * face.k], 1, &gP);
      s.Couple(1, &gQ, 30, &velocity->global[30 * face.k]);
    }
    if (o.local >= 0) s.Couple(3, rows, 3, rows);
  }
}

/* No flow, the capacitor at Pi_0 (by default the distal pressure: at rest). */
PetscErrorCode OutletsBlock::InitialState(DM, Vec x, PetscBool *set)
{
  PetscFunctionBegin;
  *set = PETSC_FALSE;
  for (const Outlet &o : outlets) {
    const PetscInt    idx[2] = {o.global + P, o.global + PI};
    const PetscScalar v[2]   = {o.P0, o.P0};
    if (o.P0 != 0) *set = PETSC_TRUE;
    if (o.local >= 0) PetscCall(VecSetValues(x, 2, idx, v, INSERT_VALUES));
  }
  PetscCall(VecAssemblyBegin(x));
  PetscCall(VecAssemblyEnd(x));
  PetscFunctionReturn(0);
}

PetscErrorCode OutletsBlock::AfterStep(DM dm, PetscInt step, PetscReal t, Vec x)
{
  const PetscScalar *a;
  PetscInt           start;

  PetscFunctionBegin;
  PetscCall(VecGetOwnershipRange(x, &start, nullptr));
  PetscCall(VecGetArrayRead(x, &a));
  for (Outlet &o : outlets) {
    PetscReal y[3] = {0, 0, 0};
    if (o.local >= 0)
      for (int i = 0; i < 3; i++) y[i] = PetscRealPart(a[o.global - start + i]);
    PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, y, 3, MPIU_REAL, MPIU_SUM, PetscObjectComm((PetscObject)dm)));
    o.series.t.push_back(t);
    o.series.values.insert(o.series.values.end(), y, y + 3);
  }
  PetscCall(VecRestoreArrayRead(x, &a));
  for (const Outlet &o : outlets) { /* NAME_outlet_<group>.csv */
    const size_t n = o.series.t.size();
    const PetscReal *v = &o.series.values[3 * (n - 1)];
    PetscCall(CsvAppend(sc.output, "outlet_" + o.group, "t,Q,P,Pi", (PetscBool)(n == 1), (PetscBool)(step > 1), {o.series.t[n - 1], v[0], v[1], v[2]}));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode OutletsBlock::Results(DM, Vec, PetscReal, RunReport &report)
{
  PetscFunctionBegin;
  for (const Outlet &o : outlets) {
    if (o.series.t.empty()) continue;
    const PetscReal *v = &o.series.values[o.series.values.size() - 3];
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "outlet %s (%s): Q %.6e cm^3/s P %.6e dyn/cm^2\n", o.group.c_str(), o.model == OUTLET_RCR ? "RCR" : o.model == OUTLET_PRESSURE ? "pressure" : "resistance", (double)v[0], (double)v[1]));
    report.results.insert(report.results.end(), {{"outlet_" + o.group + "_flow", v[0]}, {"outlet_" + o.group + "_pressure", v[1]}});
    report.series.push_back({"outlet_" + o.group, &o.series});
  }
  PetscFunctionReturn(0);
}

} // namespace fsi
