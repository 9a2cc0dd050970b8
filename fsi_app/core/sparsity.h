// SPDX-License-Identifier: BSD-2-Clause
/* The entries of the Jacobian, from the index lists the blocks insert per cell, without
   computing a single value: each block calls Couple() with exactly the rows and columns of its
   MatSetValues() calls (negative indices are skipped, as MatSetValues skips them). The rows of
   a cell that another rank owns are sent to it; each rank then merges the columns of its rows
   with a marker array and lays the matrix out with those entries, filled with zeros.
   This is PETSc's MATPREALLOCATOR without the element matrices and the hash of every inserted
   entry (about 10^9 for the coupled tube at the benchmark's size). */
#pragma once

#include <petscmat.h>
#include <unordered_map>
#include <vector>

namespace fsi {

class Sparsity {
public:
  /* for a matrix with these row and column layouts (set up) */
  Sparsity(PetscLayout rows, PetscLayout cols);
  /* the block of entries rows x cols */
  void Couple(PetscInt nr, const PetscInt rows[], PetscInt nc, const PetscInt cols[]);
  /* P's storage holds exactly the coupled entries (zeros); later insertions outside them are errors */
  PetscErrorCode LayOut(Mat P);

private:
  PetscInt    Compact(PetscInt col);
  PetscLayout rmap;
  PetscInt    cStart, cEnd;
  /* per stamp (one Couple call): nr, nc, the nr global rows, the nc columns in the compact
     numbering (owned columns first, then the others in order of appearance) */
  std::vector<PetscInt>                  stamps;
  std::vector<PetscInt>                  ghostCols; /* compact - (cEnd - cStart) -> global */
  std::unordered_map<PetscInt, PetscInt> ghostIndex;
};

} // namespace fsi
