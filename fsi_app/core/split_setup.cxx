// SPDX-License-Identifier: BSD-2-Clause
#include "split_setup.h"
#include <string>

namespace fsi {

const char *const SplitSetUpNames[] = {"every_newton", "every_step", "once"};

PetscErrorCode ReadSetUpInterval(const OptionReader &r, const char *block, PetscInt *k)
{
  const std::string name = std::string("-") + block + "_pc_setup_interval";
  const std::string text = std::string("with every_step: the ") + block + " split's preconditioner rebuilt at every k-th Newton solve of the run (a time step; one halved after a failed Newton counts again), kept in between";

  PetscFunctionBegin;
  PetscCall(r.Int(name.c_str(), text.c_str(), k, AtLeast(1), RUN));
  PetscFunctionReturn(0);
}

PetscErrorCode CheckSetUpInterval(const char *block, PetscInt k, SplitSetUp policy)
{
  PetscFunctionBegin;
  PetscCheck(k == 1 || policy == SETUP_EVERY_STEP, PETSC_COMM_WORLD, PETSC_ERR_ARG_INCOMP, "-%s_pc_setup_interval %" PetscInt_FMT ": only with a set-up every time step (-%s_pc_setup every_step); this run's is %s", block, k, block, SplitSetUpNames[policy]);
  PetscFunctionReturn(0);
}

} // namespace fsi
