// SPDX-License-Identifier: BSD-2-Clause
/* The coarse operator A_0 = Phi^T A Phi, assembled from dense blocks per subdomain and its own
   matrices: no parallel triple product. A row of A Phi at an interior dof of Omega~_i couples
   only dofs of Omega~_i, so
     A_0 = sum_i Phi_Gamma_i^T (A_GammaI Phi_I + A^_GammaGamma Phi_Gamma)_i + Phi_I_i^T (A_II Phi_I + A_IGamma Phi_Gamma)_i,
   each Gamma-Gamma coupling counted once (by the subdomain of smallest id containing both nodes).
   Where Phi was just extended with exact interior solves, the interior rows of A Phi vanish and
   their term is skipped; a kept basis with new values (-pc_gdsw_reuse_coarse_basis) or an inexact
   extension pays one dense product Phi_I^T (A Phi)_I per subdomain, where MatPtAP cost more than
   the extension it saved.
   The balanced combination also needs W = A Phi: the same blocks, summed on the interface rows,
   and where the interior rows do not vanish, their blocks kept for phi.cxx's operator. */
#include "gdswimpl.h"
#include <petscblaslapack.h>
#include <algorithm>

using gdsw::Subdomain;

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
   is assembled); with interior, plus Phi_I^T R, R = A_II Phi_I + A_IGamma Phi_Gamma (nI x ncols,
   row-major, returned likewise). */
static PetscErrorCode LocalBlock(PC pc, const Subdomain &s, PetscInt ncols, bool interior, std::vector<PetscScalar> &block, std::vector<PetscScalar> &C, std::vector<PetscScalar> &R)
{
  PC_GDSW          *gd = (PC_GDSW *)pc->data;
  const PetscInt    bs = gd->bs, novl = (PetscInt)s.ovlToNon.size();
  PetscInt          nI, nG, nrows;
  const PetscInt   *I, *G, *ia, *ja, *pos;
  const PetscScalar *phiI = nullptr, *phiG, *va;
  PetscBool         done;

  PetscFunctionBegin;
  PetscCall(ISGetLocalSize(s.isI, &nI));
  PetscCall(ISGetLocalSize(s.isG, &nG));
  PetscCall(ISGetIndices(s.isI, &I));
  PetscCall(ISGetIndices(s.isG, &G));
  /* the rows of Omega~_i's dofs in Aovl; where: dof of Omega_i^delta -> interior index, or
     -(Gamma index)-2, or -1 (a Dirichlet dof, or outside Omega~_i) */
  PetscCall(ISGetIndices(s.nonInOvl, &pos));
  std::vector<PetscInt> where(novl, -1);
  for (PetscInt r = 0; r < nI; r++) where[pos[I[r]]] = r;
  for (PetscInt r = 0; r < nG; r++) where[pos[G[r]]] = -r - 2;
  if (nI) PetscCall(MatDenseGetArrayRead(s.PhiI, &phiI));
  PetscCall(MatDenseGetArrayRead(s.PhiG, &phiG));
  PetscCall(MatGetRowIJ(s.Aovl, 0, PETSC_FALSE, PETSC_FALSE, &nrows, &ia, &ja, &done));
  PetscCall(MatSeqAIJGetArrayRead(s.Aovl, &va));
  /* the couplings of each Gamma row that enter C, as (value, row of Phi_I or Phi_Gamma) */
  std::vector<PetscInt>    ptr(nG + 1, 0), src; /* row of [Phi_I; Phi_Gamma] */
  std::vector<PetscScalar> val;
  for (PetscInt r = 0; r < nG; r++) {
    const PetscInt row = G[r];
    const auto    &Sr  = (*gd->sets)[s.setOf[row / bs]];
    for (PetscInt k = ia[pos[row]]; k < ia[pos[row] + 1]; k++) {
      const PetscInt w = where[ja[k]];
      if (w >= 0) val.push_back(va[k]), src.push_back(w);
      else if (w <= -2 && FirstCommon(Sr, (*gd->sets)[s.setOf[s.ovlToNon[ja[k]] / bs]]) == s.gid) val.push_back(va[k]), src.push_back(nI - w - 2);
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
  R.clear(); /* every coupling of an interior row lies in Omega~_i */
  if (interior && nI) {
    R.assign(nI * ncols, 0.0);
    PetscLogDouble flops = 0;
    for (PetscInt r = 0; r < nI; r++) {
      PetscScalar *rr = &R[r * ncols];
      for (PetscInt k = ia[pos[I[r]]]; k < ia[pos[I[r]] + 1]; k++) {
        const PetscInt w = where[ja[k]];
        if (w == -1) continue; /* a Dirichlet dof: Phi vanishes there */
        const PetscScalar *x = &X[(w >= 0 ? w : nI - w - 2) * ncols];
        const PetscScalar  a = va[k];
        for (PetscInt j = 0; j < ncols; j++) rr[j] += a * x[j];
        flops += 2.0 * ncols;
      }
    }
    PetscCall(PetscLogFlops(flops));
  }
  PetscCall(MatSeqAIJRestoreArrayRead(s.Aovl, &va));
  PetscCall(MatRestoreRowIJ(s.Aovl, 0, PETSC_FALSE, PETSC_FALSE, &nrows, &ia, &ja, &done));
  PetscCall(ISRestoreIndices(s.nonInOvl, &pos));
  block.assign(ncols * ncols, 0.0);
  PetscBLASInt m, n, kk;
  PetscCall(PetscBLASIntCast(ncols, &m));
  PetscCall(PetscBLASIntCast(ncols, &n));
  PetscCall(PetscBLASIntCast(nG, &kk));
  const PetscScalar one = 1.0, zero = 0.0;
  /* block = Phi_Gamma^T C; C row-major is C^T column-major (ncols x nG) */
  if (nG) PetscCallBLAS("BLASgemm", BLASgemm_("T", "T", &m, &n, &kk, &one, phiG, &kk, C.data(), &n, &zero, block.data(), &m));
  PetscCall(PetscLogFlops(2.0 * nG * ncols * ncols));
  if (!R.empty()) { /* block += Phi_I^T R */
    PetscCall(PetscBLASIntCast(nI, &kk));
    PetscCallBLAS("BLASgemm", BLASgemm_("T", "T", &m, &n, &kk, &one, phiI, &kk, R.data(), &n, &one, block.data(), &m));
    PetscCall(PetscLogFlops(2.0 * nI * ncols * ncols));
  }
  PetscCall(MatDenseRestoreArrayRead(s.PhiG, &phiG));
  if (nI) PetscCall(MatDenseRestoreArrayRead(s.PhiI, &phiI));
  PetscCall(ISRestoreIndices(s.isI, &I));
  PetscCall(ISRestoreIndices(s.isG, &G));
  PetscFunctionReturn(0);
}

/* Every subdomain's dense block, computed once for both the preallocation and the values; with
   C and R, also each subdomain's part of A Phi (otherwise each is dropped after its block); with
   interior, the interior rows' term too. */
static PetscErrorCode LocalBlocks(PC pc, bool interior, std::vector<std::vector<PetscScalar>> &blocks, std::vector<std::vector<PetscScalar>> *C, std::vector<std::vector<PetscScalar>> *R)
{
  PC_GDSW                 *gd = (PC_GDSW *)pc->data;
  std::vector<PetscScalar> scratchC, scratchR;

  PetscFunctionBegin;
  blocks.resize(gd->sub->size());
  if (C) C->resize(gd->sub->size()), R->resize(gd->sub->size());
  for (size_t i = 0; i < gd->sub->size(); i++) {
    const Subdomain &s = (*gd->sub)[i];
    PetscInt         ncols = 0;
    for (const auto &g : s.groups) ncols += g.ncols;
    if (ncols) PetscCall(LocalBlock(pc, s, ncols, interior, blocks[i], C ? (*C)[i] : scratchC, C ? (*R)[i] : scratchR));
  }
  PetscFunctionReturn(0);
}

/* W = A Phi = sum_i R_Gamma_i^T C_i (+ R_I_i^T R_i with interior). The interface rows are
   assembled (APhiGamma): a row's length is at most the sum of the column counts of the subdomains
   that share its node, split by the columns' owner, summed at the node's owner along the node star
   forest (assembly drops what is not used). The interior rows, disjoint between subdomains and
   dense over their columns, stay the subdomains' blocks R_i, applied as Phi's interior rows are
   (phi.cxx). */
static PetscErrorCode AssembleAPhi(PC pc, bool interior, const std::vector<PetscInt> &kept, const std::vector<std::vector<PetscScalar>> &C, std::vector<std::vector<PetscScalar>> &R)
{
  PC_GDSW           *gd = (PC_GDSW *)pc->data;
  const PetscInt     bs = gd->bs;
  const PetscInt    *colRange;
  const PetscSFNode *owner;
  PetscInt           nroots, nleaves, m, M, n, N;

  PetscFunctionBegin;
  if (!gd->APhiGamma) {
    PetscCall(MatGetOwnershipRangesColumn(gd->Phi, &colRange));
    PetscCall(PetscSFGetGraph(gd->nodeSF, &nroots, &nleaves, nullptr, &owner));
    std::vector<PetscInt> leafD(nleaves, 0), leafO(nleaves, 0), rootD(nroots, 0), rootO(nroots, 0);
    for (const auto &s : *gd->sub) {
      const std::vector<PetscInt> cols = GDSWPhiColumns(s, kept);
      for (size_t a = 0; a < s.nodes.size(); a++) {
        if ((*gd->sets)[s.setOf[a]].size() < 2) continue;
        const PetscInt leaf = s.leaf0 + (PetscInt)a, r = owner[leaf].rank;
        for (PetscInt c : cols)
          if (c >= 0) (c >= colRange[r] && c < colRange[r + 1] ? leafD : leafO)[leaf]++;
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
    PetscCall(MatCreate(PetscObjectComm((PetscObject)pc), &gd->APhiGamma));
    PetscCall(MatSetType(gd->APhiGamma, MATAIJ));
    PetscCall(MatSetSizes(gd->APhiGamma, m, n, M, N));
    PetscCall(MatXAIJSetPreallocation(gd->APhiGamma, 1, dnz.data(), onz.data(), nullptr, nullptr));
  } else PetscCall(MatZeroEntries(gd->APhiGamma));
  for (size_t i = 0; i < gd->sub->size(); i++) {
    Subdomain                  &s    = (*gd->sub)[i];
    const std::vector<PetscInt> cols = GDSWPhiColumns(s, kept);
    std::vector<PetscInt>       rows;
    s.WI = std::move(R[i]);
    if (cols.empty()) continue;
    PetscCall(GDSWGlobalRows(pc, s, s.isG, rows));
    PetscCall(MatSetValues(gd->APhiGamma, (PetscInt)rows.size(), rows.data(), (PetscInt)cols.size(), cols.data(), C[i].data(), ADD_VALUES));
  }
  PetscCall(MatAssemblyBegin(gd->APhiGamma, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(gd->APhiGamma, MAT_FINAL_ASSEMBLY));
  if (interior) PetscCall(GDSWCreateAPhiOperator(pc));
  else {
    PetscCall(MatDestroy(&gd->APhi));
    PetscCall(PetscObjectReference((PetscObject)gd->APhiGamma));
    gd->APhi = gd->APhiGamma;
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode AssembleLocal(PC pc, const std::vector<PetscInt> &kept, const std::vector<std::vector<PetscScalar>> &blocks, Mat A0)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  for (size_t i = 0; i < gd->sub->size(); i++) {
    const std::vector<PetscInt> cols = GDSWPhiColumns((*gd->sub)[i], kept);
    if (cols.empty()) continue;
    PetscCall(MatSetValues(A0, (PetscInt)cols.size(), cols.data(), (PetscInt)cols.size(), cols.data(), blocks[i].data(), ADD_VALUES));
  }
  PetscCall(MatAssemblyBegin(A0, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(A0, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

PetscErrorCode GDSWAssembleCoarseOperator(PC pc, PetscBool basisCurrent)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  /* the interior rows of A Phi vanish where Phi was just extended exactly (per rank: each adds its own blocks) */
  const bool      interior = !(basisCurrent && gd->exactExtension);
  const PetscBool balanced = (PetscBool)(gd->combination == PC_COMPOSITE_SYMMETRIC_MULTIPLICATIVE);
  std::vector<PetscInt>                 kept;
  std::vector<std::vector<PetscScalar>> blocks, C, R;
  PetscCall(GDSWKeptColumns(pc, kept));
  PetscCall(LocalBlocks(pc, interior, blocks, balanced ? &C : nullptr, balanced ? &R : nullptr));
  if (balanced) PetscCall(AssembleAPhi(pc, interior, kept, C, R));
  if (!gd->A0) {
    PetscInt n, N;
    Mat      pre;
    PetscCall(MatGetLocalSize(gd->Phi, nullptr, &n));
    PetscCall(MatGetSize(gd->Phi, nullptr, &N));
    PetscCall(MatCreate(PetscObjectComm((PetscObject)pc), &pre));
    PetscCall(MatSetType(pre, MATPREALLOCATOR));
    PetscCall(MatSetSizes(pre, n, n, N, N));
    PetscCall(MatSetUp(pre));
    PetscCall(AssembleLocal(pc, kept, blocks, pre));
    PetscCall(MatCreate(PetscObjectComm((PetscObject)pc), &gd->A0));
    PetscCall(MatSetType(gd->A0, MATAIJ));
    PetscCall(MatSetSizes(gd->A0, n, n, N, N));
    PetscCall(MatPreallocatorPreallocate(pre, PETSC_TRUE, gd->A0));
    PetscCall(MatDestroy(&pre));
    PetscCall(MatSetOption(gd->A0, MAT_ROW_ORIENTED, PETSC_FALSE)); /* the blocks are column-major */
  } else PetscCall(MatZeroEntries(gd->A0));
  PetscCall(AssembleLocal(pc, kept, blocks, gd->A0));
  PetscFunctionReturn(0);
}
