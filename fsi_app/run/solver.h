// SPDX-License-Identifier: BSD-2-Clause
/* The scene's nonlinear solver: Newton with the KSP and PC of the options database, set up
   from what the blocks say of their rows, and the sentence that says why a run stopped. */
#pragma once

#include "core/scene.h"
#include "run/registry.h"

namespace fsi {

PetscErrorCode CreateSolver(const Scene &sc, DM dm, const Blocks &b, SNES *snes);

/* Why the run stopped, as an error whose sentence names the cure; nothing if it did not. */
PetscErrorCode CheckFinished(const Scene &sc, const Blocks &b, SNES snes, const RunReport &report);

} // namespace fsi
