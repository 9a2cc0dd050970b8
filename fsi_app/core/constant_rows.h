// SPDX-License-Identifier: BSD-2-Clause
/* The Jacobian's values that never change: what the blocks with a constant Jacobian add (the
   harmonic extension, Block::ConstantJacobian), kept row by row after their first assembly and
   copied back into P at every later Jacobian instead of being assembled again. P's pattern is
   laid out once (core/sparsity.h), so a row's place in the CSR storage stays where it was. */
#pragma once

#include <petscmat.h>
#include <vector>

namespace fsi {

class ConstantRows {
public:
  /* P (AIJ, assembled) holds the constant blocks' values alone: keep its rows that are not all zero */
  PetscErrorCode Keep(Mat P);
  /* P's values become those kept, zero elsewhere */
  PetscErrorCode Restore(Mat P) const;
  /* values kept from this P, in its present pattern (another matrix, or a new pattern, is assembled afresh) */
  PetscErrorCode KeptFor(Mat P, PetscBool *kept) const;

private:
  struct Runs { /* of one sequential AIJ part: consecutive value ranges and their values */
    std::vector<PetscInt>    start, length;
    std::vector<PetscScalar> values;
  };
  Runs             parts[2]; /* an MPIAIJ's diagonal and off-diagonal parts; a SeqAIJ is parts[0] alone */
  Mat              from = nullptr; /* not referenced: only compared */
  PetscObjectState pattern = 0;
};

} // namespace fsi
