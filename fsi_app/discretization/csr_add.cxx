// SPDX-License-Identifier: BSD-2-Clause
#include "csr_add.h"

namespace fsi {

static const char *const Key = "fsi_csr_add";

static PetscErrorCode OpenPart(Mat A, PetscInt rows, const PetscInt **i, const PetscInt **j, PetscScalar **a)
{
  PetscInt  n;
  PetscBool done;

  PetscFunctionBegin;
  PetscCall(MatGetRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &n, i, j, &done));
  PetscCheck(done && n == rows, PETSC_COMM_SELF, PETSC_ERR_PLIB, "no CSR rows of the Jacobian's part");
  PetscCall(MatSeqAIJGetArray(A, a));
  PetscFunctionReturn(0);
}

PetscErrorCode AijParts(Mat P, Mat seq[2], int *n, const PetscInt **garray)
{
  PetscBool mpi, isSeq;

  PetscFunctionBegin;
  PetscCall(PetscObjectTypeCompare((PetscObject)P, MATMPIAIJ, &mpi));
  PetscCall(PetscObjectTypeCompare((PetscObject)P, MATSEQAIJ, &isSeq));
  seq[0] = seq[1] = nullptr, *n = mpi ? 2 : isSeq ? 1 : 0;
  if (garray) *garray = nullptr;
  if (mpi) PetscCall(MatMPIAIJGetSeqAIJ(P, &seq[0], &seq[1], garray));
  else if (isSeq) seq[0] = P;
  PetscFunctionReturn(0);
}

PetscErrorCode CsrAdd::Open(Mat P_)
{
  Mat             seq[2];
  const PetscInt *g;
  int             n;
  PetscBool       assembled;
  PetscInt        m;

  PetscFunctionBegin;
  PetscCall(AijParts(P_, seq, &n, &g));
  PetscCall(MatAssembled(P_, &assembled));
  if (!n || !assembled) PetscFunctionReturn(0);
  P = P_, diag.A = seq[0], off.A = seq[1], garray = g;
  PetscCall(MatGetOwnershipRange(P, &rStart, &rEnd));
  PetscCall(MatGetOwnershipRangeColumn(P, &cStart, &cEnd));
  m = rEnd - rStart;
  PetscCall(OpenPart(diag.A, m, &diag.i, &diag.j, &diag.a));
  if (off.A) PetscCall(OpenPart(off.A, m, &off.i, &off.j, &off.a));
  PetscContainer c;
  PetscCall(PetscContainerCreate(PETSC_COMM_SELF, &c));
  PetscCall(PetscContainerSetPointer(c, this));
  PetscCall(PetscObjectCompose((PetscObject)P, Key, (PetscObject)c));
  PetscCall(PetscContainerDestroy(&c));
  PetscFunctionReturn(0);
}

PetscErrorCode CsrAdd::Close()
{
  PetscInt  n;
  PetscBool done;

  PetscFunctionBegin;
  if (!P) PetscFunctionReturn(0);
  PetscCall(PetscObjectCompose((PetscObject)P, Key, nullptr));
  for (Part *p : {&diag, &off}) {
    if (!p->A) continue;
    PetscCall(MatSeqAIJRestoreArray(p->A, &p->a));
    PetscCall(MatRestoreRowIJ(p->A, 0, PETSC_FALSE, PETSC_FALSE, &n, &p->i, &p->j, &done));
    *p = Part();
  }
  P = nullptr, garray = nullptr;
  PetscFunctionReturn(0);
}

const CsrAdd *CsrAdd::Of(Mat P)
{
  PetscObject c = nullptr;
  void       *self;
  if (PetscObjectQuery((PetscObject)P, Key, &c) || !c || PetscContainerGetPointer((PetscContainer)c, &self)) return nullptr;
  return (const CsrAdd *)self;
}

/* The place of key c among key(lo), ..., key(hi - 1) (ascending), -1 if absent. Sorted element
   columns come in runs of consecutive dofs (a node's components), so c is most often at lo. */
template <class KeyOf>
static inline PetscInt Find(PetscInt lo, PetscInt hi, PetscInt c, KeyOf key)
{
  if (lo < hi && key(lo) == c) return lo;
  while (hi - lo > 8) {
    const PetscInt mid = lo + (hi - lo) / 2;
    if (key(mid) > c) hi = mid;
    else lo = mid;
  }
  for (; lo < hi && key(lo) <= c; lo++)
    if (key(lo) == c) return lo;
  return -1;
}

PetscErrorCode CsrAdd::Add(PetscInt nr, const PetscInt rows[], PetscInt nc, const PetscInt cols[], const PetscScalar K[]) const
{
  PetscInt hint[64]; /* each column's place in the previous row, from the row's start: a node's
                        rows (its components) have the same columns, so the next row's is checked first */

  PetscFunctionBegin;
  PetscCheck(nc <= 64, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "an element matrix of %" PetscInt_FMT " columns, more than 64", nc);
  for (PetscInt k = 0; k < nc; k++) hint[k] = -1;
  for (PetscInt r = 0; r < nr; r++) {
    const PetscInt row = rows[r];
    if (row < 0) continue;
    if (row < rStart || row >= rEnd) { /* another rank's row: the stash */
      PetscCall(MatSetValues(P, 1, &row, nc, cols, K + r * nc, ADD_VALUES));
      continue;
    }
    const PetscInt lr = row - rStart, d0 = diag.i[lr], dEnd = diag.i[lr + 1], o0 = off.A ? off.i[lr] : 0, oEnd = off.A ? off.i[lr + 1] : 0;
    PetscInt       d = d0, o = o0;
    for (PetscInt k = 0; k < nc; k++) {
      const PetscInt c = cols[k];
      if (c < 0) continue;
      if (c >= cStart && c < cEnd) {
        const PetscInt lc = c - cStart, h = d0 + hint[k];
        const PetscInt at = hint[k] >= 0 && h < dEnd && diag.j[h] == lc ? h : Find(d, dEnd, lc, [&](PetscInt p) { return diag.j[p]; });
        PetscCheck(at >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "entry (%" PetscInt_FMT ", %" PetscInt_FMT ") is not in the Jacobian's laid-out pattern", row, c);
        diag.a[at] += K[r * nc + k], d = at + 1, hint[k] = at - d0;
      } else {
        const PetscInt h  = o0 + hint[k];
        const PetscInt at = hint[k] >= 0 && h < oEnd && garray[off.j[h]] == c ? h : off.A ? Find(o, oEnd, c, [&](PetscInt p) { return garray[off.j[p]]; }) : -1;
        PetscCheck(at >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "entry (%" PetscInt_FMT ", %" PetscInt_FMT ") is not in the Jacobian's laid-out pattern", row, c);
        off.a[at] += K[r * nc + k], o = at + 1, hint[k] = at - o0;
      }
    }
  }
  PetscFunctionReturn(0);
}

} // namespace fsi
