// SPDX-License-Identifier: BSD-2-Clause
/* Coarse basis Phi = [Phi_I; Phi_Gamma] (seed eq. 2): Phi_Gamma restricts the null space to
   each interface component (GDSW) or spreads it from each coarse node with a partition of
   unity (RGDSW: the coarse nodes and their weights are found here, from the components); Phi_I = -A_II^{-1} A_IGamma Phi_Gamma is its discrete harmonic extension,
   computed by independent interior solves in each subdomain. */
#include "gdswimpl.h"
#include <algorithm>
#include <cmath>

using gdsw::CoarseGroup;
using gdsw::Subdomain;

/* The nz null-space vectors at local node a of s, vector k at out[k*bs + c]. */
static void NullSpaceAt(const PC_GDSW *gd, const Subdomain &s, PetscInt a, const PetscReal center[], PetscReal out[])
{
  const PetscInt bs = gd->bs;
  std::fill(out, out + gd->nz * bs, 0.0);
  if (gd->haveCoords) {
    const PetscReal *x = &s.nodeData[a * bs];
    for (PetscInt c = 0; c < bs; c++) out[c * bs + c] = 1.0;
    const PetscReal dx = x[0] - center[0], dy = x[1] - center[1];
    if (bs == 2) {
      out[2 * bs + 0] = -dy, out[2 * bs + 1] = dx;
    } else {
      const PetscReal dz = x[2] - center[2];
      out[3 * bs + 0] = -dy, out[3 * bs + 1] = dx;  /* about z */
      out[4 * bs + 1] = -dz, out[4 * bs + 2] = dy;  /* about x */
      out[5 * bs + 0] = dz, out[5 * bs + 2] = -dx;  /* about y */
    }
  } else if (gd->dataWidth) {
    std::copy(&s.nodeData[a * gd->dataWidth], &s.nodeData[(a + 1) * gd->dataWidth], out);
  } else {
    for (PetscInt c = 0; c < bs; c++) out[c * bs + c] = 1.0;
  }
}

static bool Includes(const std::vector<PetscInt> &big, const std::vector<PetscInt> &small)
{
  return std::includes(big.begin(), big.end(), small.begin(), small.end());
}

/* Weight of coarse node v at interface node a (support node of a component whose coarse nodes
   are `ancestors`): equal shares, or shares by inverse distance to the coarse nodes' centroids. */
static PetscReal Weight(const PC_GDSW *gd, const Subdomain &s, PetscInt a, const CoarseGroup &v, const std::vector<const CoarseGroup *> &ancestors)
{
  if (ancestors.size() == 1) return 1.0;
  if (gd->rgdswWeights == PC_GDSW_RGDSW_WEIGHTS_EQUAL || !gd->haveCoords) return 1.0 / ancestors.size();
  auto inverseDistance = [&](const CoarseGroup &w) {
    PetscReal d2 = 0;
    for (PetscInt d = 0; d < gd->bs; d++) d2 += PetscSqr(s.nodeData[a * gd->bs + d] - w.center[d]);
    return 1.0 / std::max(std::sqrt(d2), PETSC_SMALL);
  };
  PetscReal sum = 0;
  for (const CoarseGroup *w : ancestors) sum += inverseDistance(*w);
  return inverseDistance(v) / sum;
}

/* Whether coarse node w takes in component c: c itself, or a component whose sharing set strictly
   contains c's. Pieces of an interface with the same sharing set (a face the matrix graph splits)
   stay separate coarse nodes: taking in each other's nodes would make their columns equal. */
static bool IsAncestor(const CoarseGroup &w, const CoarseGroup &c)
{
  return w.rep == c.rep || (w.sharing.size() > c.sharing.size() && Includes(w.sharing, c.sharing));
}

/* RGDSW: the coarse nodes are the components no other component's sharing set strictly
   contains; each interface node is shared among the coarse nodes that take in its component,
   with the weights above. */
static void ReduceToCoarseNodes(const PC_GDSW *gd, const Subdomain &s, std::vector<CoarseGroup> &comps)
{
  std::vector<CoarseGroup> nodes;
  for (const auto &c : comps) {
    bool maximal = true;
    for (const auto &d : comps)
      if (d.sharing.size() > c.sharing.size() && Includes(d.sharing, c.sharing)) maximal = false;
    if (maximal) nodes.push_back(c);
  }
  for (auto &v : nodes) v.support.clear(), v.weight.clear();
  for (const auto &c : comps) {
    std::vector<const CoarseGroup *> ancestors;
    for (const auto &w : nodes)
      if (IsAncestor(w, c)) ancestors.push_back(&w);
    for (auto &v : nodes) {
      if (!IsAncestor(v, c)) continue;
      for (PetscInt a : c.support) {
        v.support.push_back(a);
        v.weight.push_back(Weight(gd, s, a, v, ancestors));
      }
    }
  }
  comps.swap(nodes);
}

/* Number of non-Dirichlet dofs of a group's support (the rows of its values). */
static PetscInt SupportRows(const PC_GDSW *gd, const Subdomain &s, const CoarseGroup &g)
{
  PetscInt m = 0;
  for (PetscInt a : g.support)
    for (PetscInt c = 0; c < gd->bs; c++) m += !(s.dirMask[a] >> c & 1);
  return m;
}

/* Phi_Gamma of one group: the null space on its support (times the partition-of-unity weight);
   for GDSW orthonormalised by Gram-Schmidt, keeping the columns independent to 1e-9 of the
   largest (a straight edge loses one rotation, a vertex all three). */
static void GroupValues(const PC_GDSW *gd, const Subdomain &s, CoarseGroup &g)
{
  const PetscInt bs = gd->bs, nz = gd->nz, m = SupportRows(gd, s, g);
  std::vector<PetscReal> Z(m * nz), z(nz * bs);
  for (size_t t = 0, r = 0; t < g.support.size(); t++) {
    NullSpaceAt(gd, s, g.support[t], g.center, z.data());
    for (PetscInt c = 0; c < bs; c++) {
      if (s.dirMask[g.support[t]] >> c & 1) continue;
      for (PetscInt k = 0; k < nz; k++) Z[k * m + r] = g.weight[t] * z[k * bs + c];
      r++;
    }
  }
  if (gd->coarseType == PC_GDSW_COARSE_RGDSW) {
    g.values = Z, g.ncols = nz;
    return;
  }
  PetscReal maxNorm = 0;
  for (PetscInt k = 0; k < nz; k++) {
    PetscReal n2 = 0;
    for (PetscInt r = 0; r < m; r++) n2 += Z[k * m + r] * Z[k * m + r];
    maxNorm = std::max(maxNorm, std::sqrt(n2));
  }
  g.values.clear();
  g.ncols = 0;
  for (PetscInt k = 0; k < nz; k++) {
    PetscReal *v = &Z[k * m];
    for (int pass = 0; pass < 2; pass++)
      for (PetscInt j = 0; j < g.ncols; j++) {
        const PetscReal *q = &g.values[j * m];
        PetscReal        d = 0;
        for (PetscInt r = 0; r < m; r++) d += q[r] * v[r];
        for (PetscInt r = 0; r < m; r++) v[r] -= d * q[r];
      }
    PetscReal n2 = 0;
    for (PetscInt r = 0; r < m; r++) n2 += v[r] * v[r];
    if (std::sqrt(n2) <= 1e-9 * maxNorm) continue;
    for (PetscInt r = 0; r < m; r++) g.values.push_back(v[r] / std::sqrt(n2));
    g.ncols++;
  }
}

/* Global numbering: the subdomain of smallest id in a group's sharing set numbers it; the
   owner of its representative node relays the number to the other subdomains. */
static PetscErrorCode NumberGroups(PC pc, PetscInt *nlocal)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;
  PetscInt nmine = 0, first, nleaves, nroots;
  MPI_Comm comm;

  PetscFunctionBegin;
  PetscCall(PetscObjectGetComm((PetscObject)pc, &comm));
  for (auto &s : *gd->sub)
    for (auto &g : s.groups)
      if (g.sharing[0] == s.gid) nmine += g.ncols;
  PetscCallMPI(MPI_Scan(&nmine, &first, 1, MPIU_INT, MPI_SUM, comm));
  first -= nmine;
  PetscCall(PetscSFGetGraph(gd->nodeSF, &nroots, &nleaves, nullptr, nullptr));
  std::vector<PetscInt> leaf(nleaves, -1), root(nroots, -1);
  for (auto &s : *gd->sub)
    for (auto &g : s.groups)
      if (g.sharing[0] == s.gid) {
        const PetscInt a = (PetscInt)(std::lower_bound(s.nodes.begin(), s.nodes.end(), g.rep) - s.nodes.begin());
        leaf[s.leaf0 + a] = first;
        first += g.ncols;
      }
  PetscCall(PetscSFReduceBegin(gd->nodeSF, MPIU_INT, leaf.data(), root.data(), MPI_MAX));
  PetscCall(PetscSFReduceEnd(gd->nodeSF, MPIU_INT, leaf.data(), root.data(), MPI_MAX));
  PetscCall(PetscSFBcastBegin(gd->nodeSF, MPIU_INT, root.data(), leaf.data(), MPI_REPLACE));
  PetscCall(PetscSFBcastEnd(gd->nodeSF, MPIU_INT, root.data(), leaf.data(), MPI_REPLACE));
  for (auto &s : *gd->sub)
    for (auto &g : s.groups) {
      const PetscInt a = (PetscInt)(std::lower_bound(s.nodes.begin(), s.nodes.end(), g.rep) - s.nodes.begin());
      g.col0 = leaf[s.leaf0 + a];
      PetscCheck(g.col0 >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "PCGDSW: coarse group at node %" PetscInt_FMT " was not numbered", g.rep);
    }
  *nlocal = nmine; /* the layout of Phi's columns */
  PetscFunctionReturn(0);
}

/* Interior (I) and interface (Gamma) dofs of Omega~_i, their submatrices and Phi_Gamma. */
static PetscErrorCode SetUpExtension(PC pc, Subdomain &s)
{
  PC_GDSW       *gd = (PC_GDSW *)pc->data;
  const PetscInt bs = gd->bs, nn = (PetscInt)s.nodes.size();
  std::vector<PetscInt> I, G, gRow(nn * bs, -1);

  PetscFunctionBegin;
  for (PetscInt a = 0; a < nn; a++) {
    const bool onGamma = (*gd->sets)[s.setOf[a]].size() >= 2;
    for (PetscInt c = 0; c < bs; c++) {
      if (s.dirMask[a] >> c & 1) continue;
      if (onGamma) gRow[a * bs + c] = (PetscInt)G.size(), G.push_back(a * bs + c);
      else I.push_back(a * bs + c);
    }
  }
  PetscInt ncols = 0;
  for (auto &g : s.groups) ncols += g.ncols;
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)I.size(), I.data(), PETSC_COPY_VALUES, &s.isI));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)G.size(), G.data(), PETSC_COPY_VALUES, &s.isG));
  PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, (PetscInt)G.size(), ncols, nullptr, &s.PhiG));
  PetscScalar *phi;
  PetscCall(MatDenseGetArrayWrite(s.PhiG, &phi));
  std::fill(phi, phi + G.size() * ncols, 0.0);
  PetscInt j0 = 0;
  for (auto &g : s.groups) {
    const PetscInt m = (PetscInt)g.values.size() / std::max<PetscInt>(g.ncols, 1);
    for (PetscInt j = 0; j < g.ncols; j++) {
      PetscInt r = 0;
      for (PetscInt a : g.support)
        for (PetscInt c = 0; c < bs; c++)
          if (!(s.dirMask[a] >> c & 1)) phi[(j0 + j) * G.size() + gRow[a * bs + c]] = g.values[j * m + r++];
    }
    j0 += g.ncols;
  }
  PetscCall(MatDenseRestoreArrayWrite(s.PhiG, &phi));
  PetscFunctionReturn(0);
}

/* The positions in Omega_i^delta (rows of Aovl) of local dofs of Omega~_i. */
static PetscErrorCode InOverlap(const Subdomain &s, IS local, IS *pos)
{
  PetscInt        n;
  const PetscInt *idx, *p;
  PetscInt       *q;

  PetscFunctionBegin;
  PetscCall(ISGetLocalSize(local, &n));
  PetscCall(ISGetIndices(local, &idx));
  PetscCall(ISGetIndices(s.nonInOvl, &p));
  PetscCall(PetscMalloc1(n, &q));
  for (PetscInt k = 0; k < n; k++) q[k] = p[idx[k]];
  PetscCall(ISRestoreIndices(s.nonInOvl, &p));
  PetscCall(ISRestoreIndices(local, &idx));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, n, q, PETSC_OWN_POINTER, pos));
  PetscFunctionReturn(0);
}

/* Phi_I = -A_II^{-1} A_IGamma Phi_Gamma, with the current values of A. The interior solver
   lives only for this solve: its factor would otherwise sit next to the first level's through
   the whole run (the two are about the same size), and a new extension refactors anyway. */
static PetscErrorCode Extend(PC pc, Subdomain &s, MatReuse reuse)
{
  PC_GDSW  *gd = (PC_GDSW *)pc->data;
  PetscInt  nI, ncols;
  IS        rowsI, colsG;
  Mat       B;
  KSP       ksp;
  PC        ipc;
  PetscBool preonly, direct;

  PetscFunctionBegin;
  PetscCall(ISGetLocalSize(s.isI, &nI));
  PetscCall(MatGetSize(s.PhiG, nullptr, &ncols));
  if (!nI || !ncols) PetscFunctionReturn(0);
  PetscCall(InOverlap(s, s.isI, &rowsI));
  PetscCall(InOverlap(s, s.isG, &colsG));
  PetscCall(GDSWSubmatrix(s.Aovl, rowsI, rowsI, 1, reuse, &s.AII));
  PetscCall(GDSWSubmatrix(s.Aovl, rowsI, colsG, 1, reuse, &s.AIG));
  PetscCall(ISDestroy(&rowsI));
  PetscCall(ISDestroy(&colsG));
  PetscCall(MatMatMult(s.AIG, s.PhiG, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &B));
  PetscCall(MatScale(B, -1.0));
  if (reuse == MAT_INITIAL_MATRIX) PetscCall(MatDuplicate(B, MAT_DO_NOT_COPY_VALUES, &s.PhiI));
  PetscCall(KSPCreate(PETSC_COMM_SELF, &ksp));
  PetscCall(PetscObjectIncrementTabLevel((PetscObject)ksp, (PetscObject)pc, 1));
  PetscCall(KSPSetOptionsPrefix(ksp, ((PetscObject)pc)->prefix));
  PetscCall(KSPAppendOptionsPrefix(ksp, "pc_gdsw_extension_"));
  PetscCall(GDSWDefaultFactorSolver(ksp, nullptr, gd->symmetric));
  PetscCall(GDSWKSPSetFromOptions(ksp));
  PetscCall(KSPSetOperators(ksp, s.AII, s.AII));
  PetscCall(GDSWSetUpLocalSolver(pc, ksp, s, gdsw::INTERIOR));
  PetscCall(KSPMatSolve(ksp, B, s.PhiI));
  PetscCall(KSPGetPC(ksp, &ipc));
  PetscCall(PetscObjectTypeCompare((PetscObject)ksp, KSPPREONLY, &preonly));
  PetscCall(PetscObjectTypeCompareAny((PetscObject)ipc, &direct, PCLU, PCCHOLESKY, ""));
  gd->exactExtension = (PetscBool)(gd->exactExtension && preonly && direct);
  PetscCall(KSPDestroy(&ksp));
  PetscCall(MatDestroy(&B));
  PetscFunctionReturn(0);
}

/* A subdomain's columns of Phi, sorted, and where each sits in its dense blocks. */
static void SortedColumns(const Subdomain &s, std::vector<PetscInt> &cols, std::vector<PetscInt> &pos)
{
  cols.clear();
  for (auto &g : s.groups)
    for (PetscInt j = 0; j < g.ncols; j++) cols.push_back(g.col0 + j);
  pos.resize(cols.size());
  for (size_t j = 0; j < pos.size(); j++) pos[j] = (PetscInt)j;
  std::sort(pos.begin(), pos.end(), [&](PetscInt a, PetscInt b) { return cols[a] < cols[b]; });
  std::sort(cols.begin(), cols.end());
}

/* The lengths of the rows of Phi a subdomain sets, per leaf (node) of the node star forest:
   entries in the columns of the row owner's diagonal block, and the others. */
struct RowLengths {
  std::vector<PetscInt> diag, offdiag;
};

/* Phi's rows, each set by exactly one subdomain: with interior, its interior rows (dense over its
   columns), and the interface rows of the nodes whose sharing set it leads (over their nonzero columns; Phi_Gamma
   does not depend on A, so neither does this pattern). Rows may belong to other ranks (given
   subdomains need not follow the row layout). With len, only the row lengths are recorded; colRange
   holds every rank's first column of Phi (size + 1). */
static PetscErrorCode InsertPhi(PC pc, Mat P, bool interior, RowLengths *len, const std::vector<PetscInt> &colRange)
{
  PC_GDSW           *gd = (PC_GDSW *)pc->data;
  const PetscInt     bs = gd->bs;
  const PetscSFNode *owner = nullptr;

  PetscFunctionBegin;
  if (len) PetscCall(PetscSFGetGraph(gd->nodeSF, nullptr, nullptr, nullptr, &owner));
  /* a row's lengths, recorded at its node's leaf */
  auto record = [&](const Subdomain &s, PetscInt a, const PetscInt *cols, PetscInt n) {
    const PetscInt leaf = s.leaf0 + a, r = owner[leaf].rank;
    const PetscInt d = (PetscInt)(std::lower_bound(cols, cols + n, colRange[r + 1]) - std::lower_bound(cols, cols + n, colRange[r]));
    len->diag[leaf] = std::max(len->diag[leaf], d), len->offdiag[leaf] = std::max(len->offdiag[leaf], n - d);
  };
  for (auto &s : *gd->sub) {
    std::vector<PetscInt> cols, pos, nzCols;
    SortedColumns(s, cols, pos);
    const PetscInt ncols = (PetscInt)cols.size();
    if (!ncols) continue;
    PetscInt        nI, nG;
    const PetscInt *I, *G;
    PetscCall(ISGetLocalSize(s.isI, &nI));
    PetscCall(ISGetLocalSize(s.isG, &nG));
    PetscCall(ISGetIndices(s.isI, &I));
    PetscCall(ISGetIndices(s.isG, &G));
    std::vector<PetscScalar> row(ncols);
    const PetscScalar       *x = nullptr, *y;
    if (!interior) nI = 0;
    if (nI) PetscCall(MatDenseGetArrayRead(s.PhiI, &x));
    for (PetscInt r = 0; r < nI; r++) {
      const PetscInt grow = s.nodes[I[r] / bs] * bs + I[r] % bs;
      if (len) {
        record(s, I[r] / bs, cols.data(), ncols);
        continue;
      }
      for (PetscInt j = 0; j < ncols; j++) row[j] = x[pos[j] * nI + r];
      PetscCall(MatSetValues(P, 1, &grow, ncols, cols.data(), row.data(), INSERT_VALUES));
    }
    if (nI) PetscCall(MatDenseRestoreArrayRead(s.PhiI, &x));
    PetscCall(MatDenseGetArrayRead(s.PhiG, &y));
    for (PetscInt r = 0; r < nG; r++) {
      const PetscInt a = G[r] / bs;
      if ((*gd->sets)[s.setOf[a]][0] != s.gid) continue;
      nzCols.clear();
      for (PetscInt j = 0; j < ncols; j++)
        if (y[pos[j] * nG + r] != 0.0) row[nzCols.size()] = y[pos[j] * nG + r], nzCols.push_back(cols[j]);
      const PetscInt grow = s.nodes[a] * bs + G[r] % bs, nnz = (PetscInt)nzCols.size();
      if (len) record(s, a, nzCols.data(), nnz);
      else PetscCall(MatSetValues(P, 1, &grow, nnz, nzCols.data(), row.data(), INSERT_VALUES));
    }
    PetscCall(MatDenseRestoreArrayRead(s.PhiG, &y));
    PetscCall(ISRestoreIndices(s.isI, &I));
    PetscCall(ISRestoreIndices(s.isG, &G));
  }
  if (!len) {
    PetscCall(MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY));
  }
  PetscFunctionReturn(0);
}

/* Phi with all its columns (or only its interface rows): exact row lengths (per node: the longest
   of its dofs' rows), gathered at each node's owner along the node star forest, then the rows. */
static PetscErrorCode AssemblePhi(PC pc, bool interior, Mat *P)
{
  PC_GDSW       *gd = (PC_GDSW *)pc->data;
  const PetscInt bs = gd->bs;
  PetscMPIInt    size;
  PetscInt       nroots, nleaves, m, M;
  MPI_Comm       comm;

  PetscFunctionBegin;
  PetscCall(PetscObjectGetComm((PetscObject)pc, &comm));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(MatGetLocalSize(gd->A, &m, nullptr));
  PetscCall(MatGetSize(gd->A, &M, nullptr));
  PetscCall(MatCreate(comm, P));
  PetscCall(MatSetType(*P, MATAIJ));
  PetscCall(MatSetSizes(*P, m, gd->nColsFullLocal, M, gd->nColsFull));
  std::vector<PetscInt> colRange(size + 1, 0);
  PetscCallMPI(MPI_Allgather(&gd->nColsFullLocal, 1, MPIU_INT, colRange.data() + 1, 1, MPIU_INT, comm));
  for (PetscMPIInt r = 0; r < size; r++) colRange[r + 1] += colRange[r];
  PetscCall(PetscSFGetGraph(gd->nodeSF, &nroots, &nleaves, nullptr, nullptr));
  RowLengths leaf{std::vector<PetscInt>(nleaves, 0), std::vector<PetscInt>(nleaves, 0)};
  std::vector<PetscInt> dnode(nroots, 0), onode(nroots, 0), dnz(nroots * bs), onz(nroots * bs);
  PetscCall(InsertPhi(pc, *P, interior, &leaf, colRange));
  PetscCall(PetscSFReduceBegin(gd->nodeSF, MPIU_INT, leaf.diag.data(), dnode.data(), MPI_MAX));
  PetscCall(PetscSFReduceEnd(gd->nodeSF, MPIU_INT, leaf.diag.data(), dnode.data(), MPI_MAX));
  PetscCall(PetscSFReduceBegin(gd->nodeSF, MPIU_INT, leaf.offdiag.data(), onode.data(), MPI_MAX));
  PetscCall(PetscSFReduceEnd(gd->nodeSF, MPIU_INT, leaf.offdiag.data(), onode.data(), MPI_MAX));
  for (PetscInt a = 0; a < nroots; a++)
    for (PetscInt c = 0; c < bs; c++) dnz[a * bs + c] = dnode[a], onz[a * bs + c] = onode[a];
  PetscCall(MatXAIJSetPreallocation(*P, 1, dnz.data(), onz.data(), nullptr, nullptr));
  PetscCall(InsertPhi(pc, *P, interior, nullptr, colRange));
  PetscFunctionReturn(0);
}

/* The kept columns of a matrix with all of Phi's columns. */
static PetscErrorCode KeptSubmatrix(PC pc, Mat full, Mat *kept)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;
  PetscInt rstart, rend;
  IS       rows;

  PetscFunctionBegin;
  PetscCall(MatGetOwnershipRange(full, &rstart, &rend));
  PetscCall(ISCreateStride(PetscObjectComm((PetscObject)pc), rend - rstart, rstart, 1, &rows));
  PetscCall(MatCreateSubMatrix(full, rows, gd->keptCols, MAT_INITIAL_MATRIX, kept));
  PetscCall(ISDestroy(&rows));
  PetscFunctionReturn(0);
}

/* Columns that vanish everywhere (e.g. an RGDSW translation whose support is all Dirichlet)
   would make A_0 singular: drop them. A column vanishes exactly where its interface values do
   (Phi_I = -A_II^{-1} A_IGamma Phi_Gamma), so the interface rows decide, once per decomposition;
   PhiGamma keeps the others. */
static PetscErrorCode DropZeroColumns(PC pc, Mat full)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;
  PetscInt M, N, cstart, cend;

  PetscFunctionBegin;
  PetscCall(MatGetSize(full, &M, &N));
  PetscCall(MatGetOwnershipRangeColumn(full, &cstart, &cend));
  std::vector<PetscReal> norms(N);
  PetscCall(MatGetColumnNorms(full, NORM_INFINITY, norms.data()));
  std::vector<PetscInt> kept;
  for (PetscInt j = cstart; j < cend; j++)
    if (norms[j] > 0) kept.push_back(j);
  PetscInt nzero = (cend - cstart) - (PetscInt)kept.size(), gzero;
  PetscCallMPI(MPIU_Allreduce(&nzero, &gzero, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)pc)));
  if (!gzero) {
    PetscCall(PetscObjectReference((PetscObject)full));
    gd->PhiGamma = full;
    PetscFunctionReturn(0);
  }
  PetscCall(PetscInfo(pc, "dropping %" PetscInt_FMT " coarse functions that vanish on every non-Dirichlet dof\n", gzero));
  PetscCall(ISCreateGeneral(PetscObjectComm((PetscObject)pc), (PetscInt)kept.size(), kept.data(), PETSC_COPY_VALUES, &gd->keptCols));
  PetscCall(KeptSubmatrix(pc, full, &gd->PhiGamma));
  PetscFunctionReturn(0);
}

PetscErrorCode GDSWBuildCoarseBasis(PC pc)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;
  Mat      full;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(GDSW_Basis, pc, 0, 0, 0));
  for (auto &s : *gd->sub) {
    if (gd->coarseType == PC_GDSW_COARSE_RGDSW) ReduceToCoarseNodes(gd, s, s.groups);
    for (auto &g : s.groups) GroupValues(gd, s, g);
  }
  PetscCall(NumberGroups(pc, &gd->nColsFullLocal));
  PetscCallMPI(MPIU_Allreduce(&gd->nColsFullLocal, &gd->nColsFull, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)pc)));
  for (auto &s : *gd->sub) PetscCall(SetUpExtension(pc, s));
  PetscCall(AssemblePhi(pc, false, &full));
  PetscCall(DropZeroColumns(pc, full));
  PetscCall(MatDestroy(&full));
  PetscCall(MatGetSize(gd->PhiGamma, nullptr, &gd->coarseDim));
  PetscCall(PetscLogEventEnd(GDSW_Basis, pc, 0, 0, 0));

  PetscCall(PetscLogEventBegin(GDSW_Extension, pc, 0, 0, 0));
  gd->exactExtension = PETSC_TRUE;
  for (auto &s : *gd->sub) PetscCall(Extend(pc, s, MAT_INITIAL_MATRIX));
  PetscCall(GDSWCreatePhiOperator(pc));
  PetscCall(PetscLogEventEnd(GDSW_Extension, pc, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* New values of A with the same pattern: refactor the interiors and re-extend (Phi_Gamma does
   not depend on A). */
PetscErrorCode GDSWUpdateCoarseBasis(PC pc)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(GDSW_Extension, pc, 0, 0, 0));
  gd->exactExtension = PETSC_TRUE;
  for (auto &s : *gd->sub) PetscCall(Extend(pc, s, MAT_REUSE_MATRIX));
  PetscCall(MatDestroy(&gd->PhiAssembled));
  PetscCall(PetscLogEventEnd(GDSW_Extension, pc, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* Phi assembled, its kept columns: for PCGDSWGetCoarseBasis(), made on the first request after a
   set-up. */
PetscErrorCode GDSWAssemblePhiMatrix(PC pc)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;
  Mat      full;

  PetscFunctionBegin;
  if (gd->PhiAssembled) PetscFunctionReturn(0);
  PetscCall(AssemblePhi(pc, true, &full));
  if (gd->keptCols) {
    PetscCall(KeptSubmatrix(pc, full, &gd->PhiAssembled));
    PetscCall(MatDestroy(&full));
  } else gd->PhiAssembled = full;
  PetscFunctionReturn(0);
}
