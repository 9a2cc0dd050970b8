// SPDX-License-Identifier: BSD-2-Clause
/* When the preconditioner of a block's split is set up again: every Newton step, at the first
   Newton step of each time step (or of every k-th only), or once per run (rows that never
   change). The block owns its schedule; run/splits.cxx carries it out. */
#pragma once

#include "base/options.h"

namespace fsi {

enum SplitSetUp { SETUP_EVERY_NEWTON, SETUP_EVERY_STEP, SETUP_ONCE };
extern const char *const SplitSetUpNames[];

/* -<block>_pc_setup_interval k: with SETUP_EVERY_STEP, the split's preconditioner rebuilt at
   every k-th Newton solve of the run (a time step; one halved after a failed Newton counts
   again) and kept in between. Read with the block's options, checked once its policy is known. */
PetscErrorCode ReadSetUpInterval(const OptionReader &r, const char *block, PetscInt *k);
PetscErrorCode CheckSetUpInterval(const char *block, PetscInt k, SplitSetUp policy);

} // namespace fsi
