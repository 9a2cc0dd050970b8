// SPDX-License-Identifier: BSD-2-Clause
/* The scene's nonlinear solver: Newton with the KSP and PC of the options database, set up
   from what the blocks say of their rows, and the sentence that says why a run stopped. */
#pragma once

#include "core/scene.h"
#include "run/registry.h"

namespace fsi {

PetscErrorCode CreateSolver(const Scene &sc, DM dm, const Blocks &b, SNES *snes);

/* After a failed step: a MUMPS factor out of workspace gets twice its room
   (-<prefix>mat_mumps_icntl_14, said on stdout) and *repeat asks for the step at its size again,
   at most *raisesLeft times in a run; before that repeat or a halving (halving) each
   factorization that failed starts again from a new analysis (a failed MUMPS factor refuses
   every later numeric factorization of its pattern, so a halved step would fail the same way). */
PetscErrorCode RepairFactors(SNES snes, PetscInt step, PetscBool halving, PetscInt *raisesLeft, PetscBool *repeat);

/* Why the run stopped, as an error whose sentence names the cure; nothing if it did not. */
PetscErrorCode CheckFinished(const Scene &sc, const Blocks &b, SNES snes, const RunReport &report);

} // namespace fsi
