// SPDX-License-Identifier: BSD-2-Clause
/* The coarse operator A_0 = Phi^T A Phi.
   When Phi was just extended with exact interior solves, (A Phi) vanishes on interior rows,
   so A_0 = sum_i Phi_Gamma_i^T (A_GammaI Phi_I + A^_GammaGamma Phi_Gamma)_i: a dense block per
   subdomain from its own matrices, each Gamma-Gamma coupling counted once (by the subdomain of
   smallest id containing both nodes). No parallel triple product is needed. Otherwise (a kept
   basis with new values, or an inexact extension) A_0 comes from MatPtAP.
   The balanced combination also needs A Phi: the sum of the same blocks C_i = (A_GammaI Phi_I +
   A^_GammaGamma Phi_Gamma)_i on the interface rows, or MatMatMult where A_0 needs MatPtAP. */
#include "gdswimpl.h"
#include <petscblaslapack.h>
#include <algorithm>

using gdsw::Subdomain;

/* Columns of Phi a subdomain touches, in the order of its dense blocks. */
static std::vector<PetscInt> Columns(const Subdomain &s)
{
  std::vector<PetscInt> cols;
  for (const auto &g : s.groups)
    for (PetscInt j = 0; j < g.ncols; j++) cols.push_back(g.col0 + j);
  return cols;
}

/* Smallest subdomain id in both sorted sets. */
static PetscInt FirstCommon(const std::vector<PetscInt> &a, const std::vector<PetscInt> &b)
{
  for (size_t i = 0, j = 0; i < a.size() && j < b.size();) {
    if (a[i] == b[j]) return a[i];
    if (a[i] < b[j]) i++;
    else j++;
  }
  return -1;
}

/* block = Phi_Gamma^T C, ncols x ncols, column-major, with C = A_GammaI Phi_I + A^_GammaGamma Phi_Gamma
   (nG x ncols, row-major), the subdomain's part of A Phi (returned; kept by the caller only when W
   is assembled) */
static PetscErrorCode LocalBlock(PC pc, const Subdomain &s, PetscInt ncols, std::vector<PetscScalar> &block, std::vector<PetscScalar> &C)
{
  PC_GDSW          *gd = (PC_GDSW *)pc->data;
  const PetscInt    bs = gd->bs, nloc = (PetscInt)s.nodes.size() * bs;
  PetscInt          nI, nG, nrows;
  const PetscInt   *I, *G, *ia, *ja;
  const PetscScalar *phiI = nullptr, *phiG, *va;
  PetscBool         done;

  PetscFunctionBegin;
  PetscCall(ISGetLocalSize(s.isI, &nI));
  PetscCall(ISGetLocalSize(s.isG, &nG));
  PetscCall(ISGetIndices(s.isI, &I));
  PetscCall(ISGetIndices(s.isG, &G));
  std::vector<PetscInt> where(nloc, -1); /* local dof -> interior index, or -(Gamma index)-2 */
  for (PetscInt r = 0; r < nI; r++) where[I[r]] = r;
  for (PetscInt r = 0; r < nG; r++) where[G[r]] = -r - 2;
  if (nI) PetscCall(MatDenseGetArrayRead(s.PhiI, &phiI));
  PetscCall(MatDenseGetArrayRead(s.PhiG, &phiG));
  PetscCall(MatGetRowIJ(s.Anon, 0, PETSC_FALSE, PETSC_FALSE, &nrows, &ia, &ja, &done));
  PetscCall(MatSeqAIJGetArrayRead(s.Anon, &va));
  /* the couplings of each Gamma row that enter C, as (value, row of Phi_I or Phi_Gamma) */
  std::vector<PetscInt>    ptr(nG + 1, 0), src; /* row of [Phi_I; Phi_Gamma] */
  std::vector<PetscScalar> val;
  for (PetscInt r = 0; r < nG; r++) {
    const PetscInt row = G[r];
    const auto    &Sr  = (*gd->sets)[s.setOf[row / bs]];
    for (PetscInt k = ia[row]; k < ia[row + 1]; k++) {
      const PetscInt w = where[ja[k]];
      if (w >= 0) val.push_back(va[k]), src.push_back(w);
      else if (w <= -2 && FirstCommon(Sr, (*gd->sets)[s.setOf[ja[k] / bs]]) == s.gid) val.push_back(va[k]), src.push_back(nI - w - 2);
    }
    ptr[r + 1] = (PetscInt)val.size();
  }
  /* C = A_GammaI Phi_I + A^_GammaGamma Phi_Gamma, row-major nG x ncols: every coupling adds a
     contiguous row of Phi (copied row-major once), so the inner loop runs over the columns */
  std::vector<PetscScalar> X((nI + nG) * ncols);
  C.assign(nG * ncols, 0.0);
  for (PetscInt j = 0; j < ncols; j++) {
    for (PetscInt r = 0; r < nI; r++) X[r * ncols + j] = phiI[j * nI + r];
    for (PetscInt r = 0; r < nG; r++) X[(nI + r) * ncols + j] = phiG[j * nG + r];
  }
  for (PetscInt r = 0; r < nG; r++) {
    PetscScalar *c = &C[r * ncols];
    for (PetscInt k = ptr[r]; k < ptr[r + 1]; k++) {
      const PetscScalar *x = &X[src[k] * ncols];
      const PetscScalar  a = val[k];
      for (PetscInt j = 0; j < ncols; j++) c[j] += a * x[j];
    }
  }
  PetscCall(PetscLogFlops(2.0 * ptr[nG] * ncols));
  PetscCall(MatSeqAIJRestoreArrayRead(s.Anon, &va));
  PetscCall(MatRestoreRowIJ(s.Anon, 0, PETSC_FALSE, PETSC_FALSE, &nrows, &ia, &ja, &done));
  block.assign(ncols * ncols, 0.0);
  PetscBLASInt m, n, kk;
  PetscCall(PetscBLASIntCast(ncols, &m));
  PetscCall(PetscBLASIntCast(ncols, &n));
  PetscCall(PetscBLASIntCast(nG, &kk));
  const PetscScalar one = 1.0, zero = 0.0;
  /* block = Phi_Gamma^T C; C row-major is C^T column-major (ncols x nG) */
  if (nG) PetscCallBLAS("BLASgemm", BLASgemm_("T", "T", &m, &n, &kk, &one, phiG, &kk, C.data(), &n, &zero, block.data(), &m));
  PetscCall(PetscLogFlops(2.0 * nG * ncols * ncols));
  PetscCall(MatDenseRestoreArrayRead(s.PhiG, &phiG));
  if (nI) PetscCall(MatDenseRestoreArrayRead(s.PhiI, &phiI));
  PetscCall(ISRestoreIndices(s.isI, &I));
  PetscCall(ISRestoreIndices(s.isG, &G));
  PetscFunctionReturn(0);
}

/* Every subdomain's dense block, computed once for both the preallocation and the values; with
   C, also each subdomain's part of A Phi (otherwise each is dropped after its block). */
static PetscErrorCode LocalBlocks(PC pc, std::vector<std::vector<PetscScalar>> &blocks, std::vector<std::vector<PetscScalar>> *C)
{
  PC_GDSW                 *gd = (PC_GDSW *)pc->data;
  std::vector<PetscScalar> scratch;

  PetscFunctionBegin;
  blocks.resize(gd->sub->size());
  if (C) C->resize(gd->sub->size());
  for (size_t i = 0; i < gd->sub->size(); i++) {
    const Subdomain &s = (*gd->sub)[i];
    PetscInt         ncols = 0;
    for (const auto &g : s.groups) ncols += g.ncols;
    if (ncols) PetscCall(LocalBlock(pc, s, ncols, blocks[i], C ? (*C)[i] : scratch));
  }
  PetscFunctionReturn(0);
}

/* The global rows of a subdomain's interface dofs. */
static PetscErrorCode GammaRows(PC pc, const Subdomain &s, std::vector<PetscInt> &rows)
{
  PC_GDSW        *gd = (PC_GDSW *)pc->data;
  const PetscInt  bs = gd->bs;
  PetscInt        nG;
  const PetscInt *G;

  PetscFunctionBegin;
  PetscCall(ISGetLocalSize(s.isG, &nG));
  PetscCall(ISGetIndices(s.isG, &G));
  rows.resize(nG);
  for (PetscInt r = 0; r < nG; r++) rows[r] = s.nodes[G[r] / bs] * bs + G[r] % bs;
  PetscCall(ISRestoreIndices(s.isG, &G));
  PetscFunctionReturn(0);
}

/* A Phi = sum_i R_Gamma_i^T C_i. A row's length is at most the sum of the column counts of the
   subdomains that share its node, split by the columns' owner: summed at the node's owner along
   the node star forest (assembly drops what is not used). */
static PetscErrorCode AssembleAPhi(PC pc, const std::vector<std::vector<PetscScalar>> &C)
{
  PC_GDSW           *gd = (PC_GDSW *)pc->data;
  const PetscInt     bs = gd->bs;
  const PetscInt    *colRange;
  const PetscSFNode *owner;
  PetscInt           nroots, nleaves, m, M, n, N;

  PetscFunctionBegin;
  if (!gd->APhi) {
    PetscCall(MatGetOwnershipRangesColumn(gd->Phi, &colRange));
    PetscCall(PetscSFGetGraph(gd->nodeSF, &nroots, &nleaves, nullptr, &owner));
    std::vector<PetscInt> leafD(nleaves, 0), leafO(nleaves, 0), rootD(nroots, 0), rootO(nroots, 0);
    for (const auto &s : *gd->sub) {
      const std::vector<PetscInt> cols = Columns(s);
      for (size_t a = 0; a < s.nodes.size(); a++) {
        if ((*gd->sets)[s.setOf[a]].size() < 2) continue;
        const PetscInt leaf = s.leaf0 + (PetscInt)a, r = owner[leaf].rank;
        for (PetscInt c : cols) (c >= colRange[r] && c < colRange[r + 1] ? leafD : leafO)[leaf]++;
      }
    }
    PetscCall(PetscSFReduceBegin(gd->nodeSF, MPIU_INT, leafD.data(), rootD.data(), MPI_SUM));
    PetscCall(PetscSFReduceEnd(gd->nodeSF, MPIU_INT, leafD.data(), rootD.data(), MPI_SUM));
    PetscCall(PetscSFReduceBegin(gd->nodeSF, MPIU_INT, leafO.data(), rootO.data(), MPI_SUM));
    PetscCall(PetscSFReduceEnd(gd->nodeSF, MPIU_INT, leafO.data(), rootO.data(), MPI_SUM));
    PetscCall(MatGetLocalSize(gd->Phi, &m, &n));
    PetscCall(MatGetSize(gd->Phi, &M, &N));
    std::vector<PetscInt> dnz(nroots * bs), onz(nroots * bs);
    for (PetscInt a = 0; a < nroots; a++)
      for (PetscInt c = 0; c < bs; c++) dnz[a * bs + c] = std::min(rootD[a], n), onz[a * bs + c] = std::min(rootO[a], N - n);
    PetscCall(MatCreate(PetscObjectComm((PetscObject)pc), &gd->APhi));
    PetscCall(MatSetType(gd->APhi, MATAIJ));
    PetscCall(MatSetSizes(gd->APhi, m, n, M, N));
    PetscCall(MatXAIJSetPreallocation(gd->APhi, 1, dnz.data(), onz.data(), nullptr, nullptr));
  } else PetscCall(MatZeroEntries(gd->APhi));
  for (size_t i = 0; i < gd->sub->size(); i++) {
    const Subdomain            &s    = (*gd->sub)[i];
    const std::vector<PetscInt> cols = Columns(s);
    std::vector<PetscInt>       rows;
    if (cols.empty()) continue;
    PetscCall(GammaRows(pc, s, rows));
    PetscCall(MatSetValues(gd->APhi, (PetscInt)rows.size(), rows.data(), (PetscInt)cols.size(), cols.data(), C[i].data(), ADD_VALUES));
  }
  PetscCall(MatAssemblyBegin(gd->APhi, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(gd->APhi, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

static PetscErrorCode AssembleLocal(PC pc, const std::vector<std::vector<PetscScalar>> &blocks, Mat A0)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  for (size_t i = 0; i < gd->sub->size(); i++) {
    const std::vector<PetscInt> cols = Columns((*gd->sub)[i]);
    if (cols.empty()) continue;
    PetscCall(MatSetValues(A0, (PetscInt)cols.size(), cols.data(), (PetscInt)cols.size(), cols.data(), blocks[i].data(), ADD_VALUES));
  }
  PetscCall(MatAssemblyBegin(A0, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(A0, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

PetscErrorCode GDSWAssembleCoarseOperator(PC pc, PetscBool basisCurrent)
{
  PC_GDSW  *gd = (PC_GDSW *)pc->data;
  PetscBool local, localAll;

  PetscFunctionBegin;
  local = (PetscBool)(basisCurrent && !gd->keptCols && gd->exactExtension);
  PetscCallMPI(MPIU_Allreduce(&local, &localAll, 1, MPIU_BOOL, MPI_LAND, PetscObjectComm((PetscObject)pc)));
  const PetscBool balanced = (PetscBool)(gd->combination == PC_COMPOSITE_SYMMETRIC_MULTIPLICATIVE);
  if (gd->A0 && gd->a0ByPtAP != !localAll) { /* the other method made them */
    PetscCall(MatDestroy(&gd->A0));
    PetscCall(MatDestroy(&gd->APhi));
  }
  gd->a0ByPtAP = (PetscBool)!localAll;
  if (!localAll) {
    PetscCall(MatPtAP(gd->A, gd->Phi, gd->A0 ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, 2.0, &gd->A0));
    if (balanced) PetscCall(MatMatMult(gd->A, gd->Phi, gd->APhi ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, PETSC_DEFAULT, &gd->APhi));
    PetscFunctionReturn(0);
  }
  std::vector<std::vector<PetscScalar>> blocks, C;
  PetscCall(LocalBlocks(pc, blocks, balanced ? &C : nullptr));
  if (balanced) PetscCall(AssembleAPhi(pc, C));
  if (!gd->A0) {
    PetscInt n, N;
    Mat      pre;
    PetscCall(MatGetLocalSize(gd->Phi, nullptr, &n));
    PetscCall(MatGetSize(gd->Phi, nullptr, &N));
    PetscCall(MatCreate(PetscObjectComm((PetscObject)pc), &pre));
    PetscCall(MatSetType(pre, MATPREALLOCATOR));
    PetscCall(MatSetSizes(pre, n, n, N, N));
    PetscCall(MatSetUp(pre));
    PetscCall(AssembleLocal(pc, blocks, pre));
    PetscCall(MatCreate(PetscObjectComm((PetscObject)pc), &gd->A0));
    PetscCall(MatSetType(gd->A0, MATAIJ));
    PetscCall(MatSetSizes(gd->A0, n, n, N, N));
    PetscCall(MatPreallocatorPreallocate(pre, PETSC_TRUE, gd->A0));
    PetscCall(MatDestroy(&pre));
    PetscCall(MatSetOption(gd->A0, MAT_ROW_ORIENTED, PETSC_FALSE)); /* the blocks are column-major */
  } else PetscCall(MatZeroEntries(gd->A0));
  PetscCall(AssembleLocal(pc, blocks, gd->A0));
  PetscFunctionReturn(0);
}
