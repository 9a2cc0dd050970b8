// SPDX-License-Identifier: BSD-2-Clause
/* The files a scene reads and writes, checked before the run computes anything: the mesh is a
   regular file, every output can be written and is neither a file the run reads nor another
   output, and a restart's series and checkpoint are there and not being written by another
   run. */
#pragma once

#include "core/scene.h"

namespace fsi {

PetscErrorCode CheckSceneFiles(const Scene &sc);
/* The series and the checkpoint claimed (a lock against a second run) just before the first
   step, once the mesh and the blocks have passed their checks: a refused scene writes nothing,
   not even a lock; and released after the last. */
PetscErrorCode ClaimSceneFiles(const Scene &sc);
PetscErrorCode ReleaseSceneFiles(const Scene &sc);

} // namespace fsi
