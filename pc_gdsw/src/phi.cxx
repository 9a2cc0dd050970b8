// SPDX-License-Identifier: BSD-2-Clause
/* The coarse basis Phi as an operator (MATSHELL): its interface rows assembled (PhiGamma, AIJ,
   a few nonzeros per row) and its interior rows as the subdomains' dense blocks Phi_I, which the
   harmonic extension computes and keeps anyway, applied by dense matrix-vector products. An
   assembled Phi held every interior entry a second time, with its column index: 12 instead of 8
   bytes per entry, read twice per coarse correction, and assembled again at every extension.
   Interior rows are disjoint between subdomains, so
     Phi x   = PhiGamma x   + sum_i R_I_i^T Phi_I_i x(cols_i),
     Phi^T r = PhiGamma^T r + sum_i R_cols_i^T Phi_I_i^T r(I_i).
   W = A Phi of a basis that is not harmonic for A (kept, or extended inexactly) has interior rows
   as dense as Phi's: the same operator with APhiGamma and the blocks (A Phi)_I of the coarse
   operator's set-up, through the same scatters. The assembled Phi is made only when asked for
   (PCGDSWGetCoarseBasis()). */
#include "gdswimpl.h"
#include <petscblaslapack.h>

using gdsw::Subdomain;

std::vector<PetscInt> GDSWPhiColumns(const Subdomain &s, const std::vector<PetscInt> &kept)
{
  std::vector<PetscInt> cols;
  for (const auto &g : s.groups)
    for (PetscInt j = 0; j < g.ncols; j++) cols.push_back(kept.empty() ? g.col0 + j : kept[g.col0 + j]);
  return cols;
}

PetscErrorCode GDSWGlobalRows(PC pc, const Subdomain &s, IS local, std::vector<PetscInt> &rows)
{
  PC_GDSW        *gd = (PC_GDSW *)pc->data;
  const PetscInt  bs = gd->bs;
  PetscInt        n;
  const PetscInt *idx;

  PetscFunctionBegin;
  PetscCall(ISGetLocalSize(local, &n));
  PetscCall(ISGetIndices(local, &idx));
  rows.resize(n);
  for (PetscInt r = 0; r < n; r++) rows[r] = s.nodes[idx[r] / bs] * bs + idx[r] % bs;
  PetscCall(ISRestoreIndices(local, &idx));
  PetscFunctionReturn(0);
}

PetscErrorCode GDSWKeptColumns(PC pc, std::vector<PetscInt> &kept)
{
  PC_GDSW        *gd = (PC_GDSW *)pc->data;
  IS              all;
  PetscInt        n;
  const PetscInt *idx;

  PetscFunctionBegin;
  kept.clear();
  if (!gd->keptCols) PetscFunctionReturn(0);
  PetscCall(ISAllGather(gd->keptCols, &all));
  PetscCall(ISGetLocalSize(all, &n));
  PetscCall(ISGetIndices(all, &idx));
  kept.assign(gd->nColsFull, -1);
  for (PetscInt k = 0; k < n; k++) kept[idx[k]] = k;
  PetscCall(ISRestoreIndices(all, &idx));
  PetscCall(ISDestroy(&all));
  PetscFunctionReturn(0);
}

static PetscInt NumColumns(const Subdomain &s)
{
  PetscInt n = 0;
  for (const auto &g : s.groups) n += g.ncols;
  return n;
}

/* Between the work vectors: interior = B_i cols, or cols = B_i^T interior, per subdomain, where B_i
   is Phi_I (dense, column-major) or, for W, (A Phi)_I (nI x ncols, row-major). */
static PetscErrorCode InteriorBlocks(PC pc, bool w, bool transpose)
{
  PC_GDSW          *gd = (PC_GDSW *)pc->data;
  PetscScalar      *cols, *in;
  const PetscScalar one = 1.0, zero = 0.0;
  const PetscBLASInt inc = 1;
  PetscLogDouble    flops = 0;

  PetscFunctionBegin;
  PetscCall(VecGetArray(gd->phiColsWork, &cols));
  PetscCall(VecGetArray(gd->phiIntWork, &in));
  for (const auto &s : *gd->sub) {
    if (!s.PhiI || (w && s.WI.empty())) continue;
    const PetscScalar *B;
    PetscInt           nI, ncols, lda;
    PetscBLASInt       m, n, ld;
    PetscCall(MatGetSize(s.PhiI, &nI, &ncols));
    PetscCall(MatDenseGetLDA(s.PhiI, &lda));
    if (w) B = s.WI.data(), lda = ncols, std::swap(nI, ncols); /* row-major: the column-major ncols x nI B_i^T */
    else PetscCall(MatDenseGetArrayRead(s.PhiI, &B));
    PetscCall(PetscBLASIntCast(nI, &m));
    PetscCall(PetscBLASIntCast(ncols, &n));
    PetscCall(PetscBLASIntCast(lda, &ld));
    PetscScalar *src = transpose ? in + s.intOffset : cols + s.colOffset, *dst = transpose ? cols + s.colOffset : in + s.intOffset;
    PetscCallBLAS("BLASgemv", BLASgemv_(transpose != w ? "T" : "N", &m, &n, &one, B, &ld, src, &inc, &zero, dst, &inc));
    if (!w) PetscCall(MatDenseRestoreArrayRead(s.PhiI, &B));
    flops += 2.0 * nI * ncols;
  }
  PetscCall(VecRestoreArray(gd->phiIntWork, &in));
  PetscCall(VecRestoreArray(gd->phiColsWork, &cols));
  PetscCall(PetscLogFlops(flops));
  PetscFunctionReturn(0);
}

/* z = y + P x, or y + P^T x (y may be null), P = Phi or W: the interface rows' product, then the
   interior blocks between a scatter in (the subdomains' columns, or their interior rows) and a
   scatter out adding to z (the other way round). */
static PetscErrorCode Apply(Mat P, Vec x, Vec y, Vec z, bool transpose)
{
  PC       pc;
  PC_GDSW *gd;

  PetscFunctionBegin;
  PetscCall(MatShellGetContext(P, &pc));
  gd = (PC_GDSW *)pc->data;
  const bool w     = P != gd->Phi;
  Mat        Gamma = w ? gd->APhiGamma : gd->PhiGamma;
  if (transpose) PetscCall(y ? MatMultTransposeAdd(Gamma, x, y, z) : MatMultTranspose(Gamma, x, z));
  else PetscCall(y ? MatMultAdd(Gamma, x, y, z) : MatMult(Gamma, x, z));
  VecScatter in = transpose ? gd->phiInterior : gd->phiCols, out = transpose ? gd->phiCols : gd->phiInterior;
  Vec        inWork = transpose ? gd->phiIntWork : gd->phiColsWork, outWork = transpose ? gd->phiColsWork : gd->phiIntWork;
  /* dropped columns, and subdomains without a block (or without columns: gemv then writes nothing), are never written */
  PetscCall(VecSet(gd->phiColsWork, 0.0));
  if (!transpose) PetscCall(VecSet(gd->phiIntWork, 0.0));
  PetscCall(VecScatterBegin(in, x, inWork, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(in, x, inWork, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(InteriorBlocks(pc, w, transpose));
  PetscCall(VecScatterBegin(out, outWork, z, ADD_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterEnd(out, outWork, z, ADD_VALUES, SCATTER_REVERSE));
  PetscFunctionReturn(0);
}

static PetscErrorCode PhiMult(Mat P, Vec x, Vec z)
{
  PetscFunctionBegin;
  PetscCall(Apply(P, x, nullptr, z, false));
  PetscFunctionReturn(0);
}

static PetscErrorCode PhiMultAdd(Mat P, Vec x, Vec y, Vec z)
{
  PetscFunctionBegin;
  PetscCall(Apply(P, x, y, z, false));
  PetscFunctionReturn(0);
}

static PetscErrorCode PhiMultTranspose(Mat P, Vec x, Vec z)
{
  PetscFunctionBegin;
  PetscCall(Apply(P, x, nullptr, z, true));
  PetscFunctionReturn(0);
}

static PetscErrorCode PhiMultTransposeAdd(Mat P, Vec x, Vec y, Vec z)
{
  PetscFunctionBegin;
  PetscCall(Apply(P, x, y, z, true));
  PetscFunctionReturn(0);
}

static PetscErrorCode CreateShell(PC pc, Mat *P)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;
  PetscInt m, n, M, N;

  PetscFunctionBegin;
  PetscCall(MatGetLocalSize(gd->PhiGamma, &m, &n));
  PetscCall(MatGetSize(gd->PhiGamma, &M, &N));
  PetscCall(MatCreateShell(PetscObjectComm((PetscObject)pc), m, n, M, N, pc, P));
  PetscCall(MatShellSetOperation(*P, MATOP_MULT, (void (*)(void))PhiMult));
  PetscCall(MatShellSetOperation(*P, MATOP_MULT_ADD, (void (*)(void))PhiMultAdd));
  PetscCall(MatShellSetOperation(*P, MATOP_MULT_TRANSPOSE, (void (*)(void))PhiMultTranspose));
  PetscCall(MatShellSetOperation(*P, MATOP_MULT_TRANSPOSE_ADD, (void (*)(void))PhiMultTransposeAdd));
  PetscFunctionReturn(0);
}

/* W = APhiGamma + the subdomains' blocks (A Phi)_I, after GDSWCreatePhiOperator() */
PetscErrorCode GDSWCreateAPhiOperator(PC pc)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCall(MatDestroy(&gd->APhi));
  PetscCall(CreateShell(pc, &gd->APhi));
  PetscFunctionReturn(0);
}

PetscErrorCode GDSWCreatePhiOperator(PC pc)
{
  PC_GDSW              *gd = (PC_GDSW *)pc->data;
  std::vector<PetscInt> kept, rows, from, to;
  PetscInt              nI = 0, nc = 0;
  Vec                   coarse, global;
  IS                    isRows, isFrom, isTo;

  PetscFunctionBegin;
  PetscCall(GDSWKeptColumns(pc, kept));
  for (auto &s : *gd->sub) {
    std::vector<PetscInt> r;
    const std::vector<PetscInt> cols = GDSWPhiColumns(s, kept);
    s.intOffset = nI, s.colOffset = nc;
    if (s.PhiI) {
      PetscCall(GDSWGlobalRows(pc, s, s.isI, r));
      rows.insert(rows.end(), r.begin(), r.end());
      nI += (PetscInt)r.size();
    }
    for (size_t j = 0; j < cols.size(); j++)
      if (cols[j] >= 0) from.push_back(cols[j]), to.push_back(nc + (PetscInt)j);
    nc += NumColumns(s);
  }
  PetscCall(MatCreateVecs(gd->PhiGamma, &coarse, &global));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, nI, &gd->phiIntWork));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, nc, &gd->phiColsWork));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, nI, rows.data(), PETSC_USE_POINTER, &isRows));
  PetscCall(VecScatterCreate(global, isRows, gd->phiIntWork, nullptr, &gd->phiInterior));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)from.size(), from.data(), PETSC_USE_POINTER, &isFrom));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, (PetscInt)to.size(), to.data(), PETSC_USE_POINTER, &isTo));
  PetscCall(VecScatterCreate(coarse, isFrom, gd->phiColsWork, isTo, &gd->phiCols));
  PetscCall(ISDestroy(&isRows));
  PetscCall(ISDestroy(&isFrom));
  PetscCall(ISDestroy(&isTo));
  PetscCall(VecDestroy(&coarse));
  PetscCall(VecDestroy(&global));
  PetscCall(CreateShell(pc, &gd->Phi));
  PetscFunctionReturn(0);
}
