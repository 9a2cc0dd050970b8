// SPDX-License-Identifier: BSD-2-Clause
/* The files a scene reads and writes, checked before the run computes anything: the mesh is a
   regular file, every output can be written and is neither a file the run reads nor another
   output, the series and the checkpoint are claimed (a lock against a second run), and a
   restart's series and checkpoint are there and not being written by another run. */
#pragma once

#include "core/scene.h"

namespace fsi {

PetscErrorCode CheckSceneFiles(const Scene &sc);

} // namespace fsi
