// SPDX-License-Identifier: BSD-2-Clause
/* Checkpoints: the state a run needs to continue exactly as if never stopped (step, time, the
   solution and the past states of the time scheme, the running sums of the blocks' output)
   and the options that define its problem,
   in PETSc binary, written to a temporary file and renamed, so a crash while writing leaves
   the previous checkpoint intact. */
#pragma once

#include "core/time_history.h"
#include <deque>
#include <map>
#include <string>
#include <vector>

namespace fsi {

struct CheckpointHeader {
  PetscInt  step = 0; /* completed steps */
  PetscReal t    = 0;
};

/* The key of Scene::problem that holds the mesh file's digest (FileDigest), so that a restart
   tells a mesh file changed under the same name. */
inline const char *const MeshDigestKey = "mesh-file-digest";

/* A run's checkpoints: `file` always holds the newest; the newest `keep` are also kept as
   file.<step> (hard links of it, no copy), the older ones of this run removed. */
struct CheckpointSeries {
  std::string             file;
  PetscInt                keep = 1;
  std::deque<std::string> numbered; /* written by this run, oldest first */
};

/* `problem`: the options that define the problem and their values (Scene::problem); `sums`:
   this rank's running sums of the blocks' output (Block::RunningSums, one after another). */
PetscErrorCode CheckpointWrite(CheckpointSeries &s, DM dm, const CheckpointHeader &c, const std::map<std::string, std::string> &problem, Vec x, const TimeHistory &h, std::vector<PetscReal> &sums);

/* Errors name the file and what does not match this run: a file that is not a whole
   checkpoint (truncated: its size is not the one its header announces), a header or a state
   that does not match its checksum (damaged), the ranks, the unknowns, the time scheme, the step, the mesh
   file's contents, and the first option of `problem` whose value differs. */
PetscErrorCode CheckpointRead(const char *file, DM dm, const std::map<std::string, std::string> &problem, CheckpointHeader &c, Vec x, TimeHistory &h, std::vector<PetscReal> &sums);

} // namespace fsi
