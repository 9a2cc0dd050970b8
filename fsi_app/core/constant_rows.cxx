// SPDX-License-Identifier: BSD-2-Clause
#include "constant_rows.h"
#include "discretization/csr_add.h"
#include <cstring>

namespace fsi {

static PetscErrorCode SeqParts(Mat P, Mat seq[2], int *n)
{
  PetscFunctionBegin;
  PetscCall(AijParts(P, seq, n, nullptr));
  PetscCheck(*n, PetscObjectComm((PetscObject)P), PETSC_ERR_SUP, "the Jacobian's constant rows are kept for AIJ matrices only");
  PetscFunctionReturn(0);
}

PetscErrorCode ConstantRows::Keep(Mat P)
{
  Mat seq[2];
  int n;

  PetscFunctionBegin;
  PetscCall(SeqParts(P, seq, &n));
  for (int p = 0; p < n; p++) {
    const PetscInt    *ia, *ja;
    const PetscScalar *a;
    PetscInt           m;
    PetscBool          done;
    Runs              &r = parts[p];
    r = Runs();
    PetscCall(MatGetRowIJ(seq[p], 0, PETSC_FALSE, PETSC_FALSE, &m, &ia, &ja, &done));
    PetscCheck(done, PETSC_COMM_SELF, PETSC_ERR_SUP, "no row structure of the Jacobian's local part");
    PetscCall(MatSeqAIJGetArrayRead(seq[p], &a));
    for (PetscInt i = 0; i < m; i++) {
      bool zero = true;
      for (PetscInt j = ia[i]; j < ia[i + 1] && zero; j++) zero = a[j] == 0.0;
      if (zero) continue;
      if (!r.start.empty() && r.start.back() + r.length.back() == ia[i]) r.length.back() += ia[i + 1] - ia[i]; /* rows in a row: one run */
      else r.start.push_back(ia[i]), r.length.push_back(ia[i + 1] - ia[i]);
      r.values.insert(r.values.end(), a + ia[i], a + ia[i + 1]);
    }
    PetscCall(MatSeqAIJRestoreArrayRead(seq[p], &a));
    PetscCall(MatRestoreRowIJ(seq[p], 0, PETSC_FALSE, PETSC_FALSE, &m, &ia, &ja, &done));
  }
  from = P;
  PetscCall(MatGetNonzeroState(P, &pattern));
  PetscFunctionReturn(0);
}

PetscErrorCode ConstantRows::KeptFor(Mat P, PetscBool *kept) const
{
  PetscObjectState now;

  PetscFunctionBegin;
  PetscCall(MatGetNonzeroState(P, &now));
  *kept = (PetscBool)(from == P && now == pattern);
  PetscFunctionReturn(0);
}

PetscErrorCode ConstantRows::Restore(Mat P) const
{
  Mat seq[2];
  int n;

  PetscFunctionBegin;
  PetscCall(MatZeroEntries(P));
  PetscCall(SeqParts(P, seq, &n));
  for (int p = 0; p < n; p++) {
    const Runs  &r = parts[p];
    PetscScalar *a;
    size_t       at = 0; /* in r.values */
    PetscCall(MatSeqAIJGetArray(seq[p], &a));
    for (size_t k = 0; k < r.start.size(); at += r.length[k], k++) std::memcpy(a + r.start[k], r.values.data() + at, r.length[k] * sizeof(PetscScalar));
    PetscCall(MatSeqAIJRestoreArray(seq[p], &a));
  }
  PetscFunctionReturn(0);
}

} // namespace fsi
