// SPDX-License-Identifier: BSD-2-Clause
/* Element matrices added straight into P's CSR storage while the blocks assemble a Jacobian.
   P's pattern is laid out once (core/sparsity.h) and never changes, so an entry's place is found
   by a search in its row of the diagonal or off-diagonal part; MatSetValues does the same search
   behind several layers per entry (about 30 ns, most of an element's insertion). Rows another
   rank owns still go through MatSetValues and its stash. AddElementMatrix
   (discretization/cells.h) uses the storage while it is open on P. */
#pragma once

#include <petscmat.h>

namespace fsi {

/* P's sequential AIJ parts: a SEQAIJ is its own part 0 (*n = 1); an MPIAIJ has its diagonal and
   off-diagonal parts (*n = 2) and, if asked, the off-diagonal part's global columns (ascending);
   any other type has none (*n = 0). */
PetscErrorCode AijParts(Mat P, Mat seq[2], int *n, const PetscInt **garray);

class CsrAdd {
public:
  /* P (SEQAIJ or MPIAIJ, assembled, its pattern final) opened for Add; any other type is left
     to MatSetValues (Open does nothing) */
  PetscErrorCode Open(Mat P);
  PetscErrorCode Close();
  ~CsrAdd() { (void)Close(); } /* an error inside the blocks' Jacobians leaves no storage open */
  /* P += K (nr x nc, row-major) at rows x cols, cols sorted ascending; negative indices dropped */
  PetscErrorCode Add(PetscInt nr, const PetscInt rows[], PetscInt nc, const PetscInt cols[], const PetscScalar K[]) const;
  /* the storage open on P, or nullptr */
  static const CsrAdd *Of(Mat P);

private:
  struct Part { /* a sequential AIJ part: its CSR and values */
    Mat             A = nullptr;
    const PetscInt *i = nullptr, *j = nullptr;
    PetscScalar    *a = nullptr;
  };
  Mat             P = nullptr;
  Part            diag, off;
  const PetscInt *garray = nullptr; /* the off-diagonal part's columns, global, ascending */
  PetscInt        rStart = 0, rEnd = 0, cStart = 0, cEnd = 0;
};

} // namespace fsi
