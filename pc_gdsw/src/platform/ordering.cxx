// SPDX-License-Identifier: BSD-2-Clause
/* The fill-reducing ordering of the local Cholesky factorisations: METIS nested dissection of
   the node graph (MATORDERINGGDSWNODES, registered for any factorisation). CHOLMOD left to itself
   orders every local matrix over its dof graph, with AMD and, when AMD's fill is large, again
   with METIS, and keeps the better; the node graph has bs^2 times fewer edges and keeps a node's
   dofs together in the supernodes. Each subdomain is dissected once, on its overlapping matrix:
   the interior matrix of the harmonic extension, a principal submatrix, takes the restriction of
   that order (a separator of Omega_i^delta also separates its part of the interior). */
#include "../gdswimpl.h"
#include <metis.h>
#include <algorithm>
#include <limits>
#include <numeric>
#include <vector>

using gdsw::LocalMatrix;
using gdsw::Subdomain;

static const char RowRanksKey[] = "PCGDSW_row_ranks";

/* METIS numbers a graph's vertices and edges in idx_t, 32 bits in Debian's build whatever
   PetscInt is: a local node graph must have fewer adjacency entries than that holds */
PetscErrorCode GDSWCheckMetisSize(PetscCount entries)
{
  PetscFunctionBegin;
  PetscCheck(entries <= (PetscCount)std::numeric_limits<idx_t>::max(), PETSC_COMM_SELF, PETSC_ERR_SUP, "PCGDSW: a local node graph of %" PetscCount_FMT " adjacency entries is too large for METIS's %d-bit indices: give it more subdomains or ranks", entries, IDXTYPEWIDTH);
  PetscFunctionReturn(0);
}

/* METIS nested dissection of the graph of A (of its block rows if blocked) whose vertices are
   the runs of rows first[v] .. first[v + 1] - 1 (symmetric, without the diagonal, no edge twice); perm[j] is the vertex
   eliminated j-th. */
static PetscErrorCode NestedDissection(Mat A, PetscBool blocked, const std::vector<PetscInt> &first, std::vector<PetscInt> &perm)
{
  const PetscInt  nv = (PetscInt)first.size() - 1;
  PetscInt        n, m;
  const PetscInt *ia, *ja;
  PetscBool       done;

  PetscFunctionBegin;
  PetscCall(MatGetRowIJ(A, 0, PETSC_FALSE, blocked, &n, &ia, &ja, &done));
  PetscCheck(done, PETSC_COMM_SELF, PETSC_ERR_SUP, "PCGDSW: the ordering gdsw_nodes needs a sequential matrix");
  std::vector<PetscInt> vertex(n), mark(nv, -1), pairs;
  for (PetscInt v = 0; v < nv; v++)
    for (PetscInt r = first[v]; r < first[v + 1]; r++) vertex[r] = v;
  for (PetscInt a = 0; a < nv; a++)
    for (PetscInt r = first[a]; r < first[a + 1]; r++)
      for (PetscInt k = ia[r]; k < ia[r + 1]; k++) {
        const PetscInt b = vertex[ja[k]];
        if (b != a && mark[b] != a) mark[b] = a, pairs.push_back(a), pairs.push_back(b);
      }
  PetscCall(MatRestoreRowIJ(A, 0, PETSC_FALSE, blocked, &m, &ia, &ja, &done));
  PetscCall(GDSWCheckMetisSize((PetscCount)pairs.size()));
  std::vector<idx_t> xadj(nv + 1, 0), adj(pairs.size());
  for (size_t k = 0; k < pairs.size(); k += 2) xadj[pairs[k] + 1]++, xadj[pairs[k + 1] + 1]++;
  for (PetscInt a = 0; a < nv; a++) xadj[a + 1] += xadj[a];
  std::vector<idx_t> fill(xadj.begin(), xadj.end() - 1);
  for (size_t k = 0; k < pairs.size(); k += 2) adj[fill[pairs[k]]++] = (idx_t)pairs[k + 1], adj[fill[pairs[k + 1]]++] = (idx_t)pairs[k];
  std::fill(mark.begin(), mark.end(), -1);
  idx_t out = 0;
  for (PetscInt a = 0; a < nv; a++) { /* an edge of a structurally symmetric matrix came in twice */
    const idx_t begin = xadj[a], end = xadj[a + 1];
    xadj[a]           = out;
    for (idx_t k = begin; k < end; k++)
      if (mark[adj[k]] != a) mark[adj[k]] = a, adj[out++] = adj[k];
  }
  xadj[nv] = out;
  std::vector<idx_t> p(nv), ip(nv);
  if (nv > 0) {
    idx_t nvtx = (idx_t)nv, options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    const int status                = METIS_NodeND(&nvtx, xadj.data(), adj.data(), nullptr, options, p.data(), ip.data());
    PetscCheck(status == METIS_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "PCGDSW: METIS_NodeND failed (status %d) on a local matrix of %" PetscInt_FMT " nodes", status, nv);
  }
  perm.assign(p.begin(), p.end());
  PetscFunctionReturn(0);
}

/* Rows in order of their rank, those of equal rank (one node) in their own order. */
static PetscErrorCode RowsByRank(PetscInt n, const PetscInt *rank, IS *row)
{
  PetscInt *p;

  PetscFunctionBegin;
  PetscCall(PetscMalloc1(n, &p));
  std::iota(p, p + n, 0);
  std::stable_sort(p, p + n, [rank](PetscInt a, PetscInt b) { return rank[a] < rank[b]; });
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, n, p, PETSC_OWN_POINTER, row));
  PetscFunctionReturn(0);
}

/* gdsw's local matrices carry the rank of each row's node in their subdomain's dissection;
   any other matrix is dissected on the graph of its blocks (MatGetBlockSize()). */
static PetscErrorCode MatGetOrdering_GDSWNodes(Mat A, MatOrderingType type, IS *row, IS *col)
{
  IS       ranks;
  PetscInt n, bs;

  PetscFunctionBegin;
  PetscCall(MatGetLocalSize(A, &n, nullptr));
  PetscCall(PetscObjectQuery((PetscObject)A, RowRanksKey, (PetscObject *)&ranks));
  if (ranks) {
    const PetscInt *rank;
    PetscInt        m;
    PetscCall(ISGetLocalSize(ranks, &m));
    PetscCheck(m == n, PETSC_COMM_SELF, PETSC_ERR_PLIB, "PCGDSW: %" PetscInt_FMT " row ranks for a matrix of %" PetscInt_FMT " rows", m, n);
    PetscCall(ISGetIndices(ranks, &rank));
    PetscCall(RowsByRank(n, rank, row));
    PetscCall(ISRestoreIndices(ranks, &rank));
  } else {
    PetscBool blocked; /* PETSc orders a BAIJ matrix by its block rows, its graph's rows */
    PetscCall(PetscObjectTypeCompareAny((PetscObject)A, &blocked, MATSEQBAIJ, MATSEQSBAIJ, ""));
    PetscCall(MatGetBlockSize(A, &bs));
    if (blocked) n /= bs, bs = 1;
    else if (n % bs) bs = 1;
    std::vector<PetscInt> first(n / bs + 1), perm;
    for (PetscInt v = 0; v <= n / bs; v++) first[v] = v * bs;
    PetscCall(NestedDissection(A, blocked, first, perm));
    PetscInt *p, k = 0;
    PetscCall(PetscMalloc1(n, &p));
    for (PetscInt v : perm)
      for (PetscInt r = first[v]; r < first[v + 1]; r++) p[k++] = r;
    PetscCall(ISCreateGeneral(PETSC_COMM_SELF, n, p, PETSC_OWN_POINTER, row));
  }
  PetscCall(ISSetPermutation(*row));
  PetscCall(PetscObjectReference((PetscObject)*row));
  *col = *row;
  PetscFunctionReturn(0);
}

/* Compose on A, the overlapping or interior matrix of s, the rank of each row's node in the
   nested dissection of s's overlapping node graph (computed at the first call). A matrix keeps
   its ranks across set-ups with new values: its pattern, and so its ordering, is the same. */
PetscErrorCode GDSWComposeRowRanks(PC pc, Subdomain &s, LocalMatrix which, Mat A)
{
  PC_GDSW        *gd = (PC_GDSW *)pc->data;
  const PetscInt *idx, *pos;
  PetscInt        n, *rank;
  IS              ranks;

  PetscFunctionBegin;
  PetscCall(PetscObjectQuery((PetscObject)A, RowRanksKey, (PetscObject *)&ranks));
  if (ranks) PetscFunctionReturn(0);
  if (s.rowRank.empty()) {
    std::vector<PetscInt> first, perm;
    PetscCall(ISGetLocalSize(s.overlap, &n));
    PetscCall(ISGetIndices(s.overlap, &idx));
    for (PetscInt r = 0; r < n; r++)
      if (r == 0 || idx[r] / gd->bs != idx[r - 1] / gd->bs) first.push_back(r);
    first.push_back(n);
    PetscCall(ISRestoreIndices(s.overlap, &idx));
    PetscCall(NestedDissection(s.Aovl, PETSC_FALSE, first, perm));
    s.rowRank.resize(n);
    for (size_t j = 0; j < perm.size(); j++)
      for (PetscInt r = first[perm[j]]; r < first[perm[j] + 1]; r++) s.rowRank[r] = (PetscInt)j;
  }
  PetscCall(MatGetLocalSize(A, &n, nullptr));
  PetscCall(PetscMalloc1(n, &rank));
  if (which == gdsw::OVERLAPPING) std::copy(s.rowRank.begin(), s.rowRank.end(), rank);
  else { /* I's rows are dofs of Omega~_i, found in Omega_i^delta through nonInOvl */
    PetscCall(ISGetIndices(s.isI, &idx));
    PetscCall(ISGetIndices(s.nonInOvl, &pos));
    for (PetscInt k = 0; k < n; k++) rank[k] = s.rowRank[pos[idx[k]]];
    PetscCall(ISRestoreIndices(s.nonInOvl, &pos));
    PetscCall(ISRestoreIndices(s.isI, &idx));
  }
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, n, rank, PETSC_OWN_POINTER, &ranks));
  PetscCall(PetscObjectCompose((PetscObject)A, RowRanksKey, (PetscObject)ranks));
  PetscCall(ISDestroy(&ranks));
  PetscFunctionReturn(0);
}

PetscErrorCode GDSWRegisterOrdering(void)
{
  PetscFunctionBegin;
  PetscCall(MatOrderingRegister(MATORDERINGGDSWNODES, MatGetOrdering_GDSWNodes));
  PetscFunctionReturn(0);
}
