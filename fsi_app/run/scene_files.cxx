// SPDX-License-Identifier: BSD-2-Clause
#include "scene_files.h"
#include "base/files.h"
#include <fstream>
#include <sys/stat.h>

namespace fsi {

/* No file the run writes is one it reads or another it writes (a checkpoint may be the one the
   run restarts from: it continues there). */
static PetscErrorCode CheckFilesDistinct(const Scene &sc)
{
  std::vector<std::pair<std::string, std::string>> inputs, outputs; /* (option, path) */

  PetscFunctionBegin;
  inputs.push_back({"-mesh", sc.mesh});
  if (sc.restart[0]) inputs.push_back({"-restart", sc.restart});
  if (sc.output[0]) {
    const std::string xdmf = sc.output;
    outputs.push_back({"-output", xdmf});
    if (xdmf.size() > 5) outputs.push_back({"-output (its data file)", xdmf.substr(0, xdmf.size() - 5) + ".h5"});
  }
  if (sc.checkpoint[0]) outputs.push_back({"-checkpoint", sc.checkpoint});
  if (sc.report[0]) outputs.push_back({"-report", sc.report});
  auto regular = [](const std::string &path) { /* a device (/dev/stdout) is not a file a run could lose */
    struct stat st;
    return stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode);
  };
  for (size_t i = 0; i < outputs.size(); i++) {
    const std::string out = CanonicalPath(outputs[i].second);
    if (!regular(outputs[i].second)) continue;
    for (const auto &in : inputs)
      PetscCheck(out != CanonicalPath(in.second) || (in.first == std::string("-restart") && outputs[i].first == std::string("-checkpoint")), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s %s is the file of %s: the run would write over what it reads; give another name", outputs[i].first.c_str(), outputs[i].second.c_str(), in.first.c_str());
    for (size_t j = 0; j < i; j++)
      PetscCheck(out != CanonicalPath(outputs[j].second), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s %s and %s %s are one file: one would be lost; give each its own name", outputs[j].first.c_str(), outputs[j].second.c_str(), outputs[i].first.c_str(), outputs[i].second.c_str());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CheckSceneFiles(const Scene &sc)
{
  PetscFunctionBegin;
  PetscCall(CheckOnRankZero(PETSC_COMM_WORLD, PETSC_ERR_FILE_OPEN, [&]() { /* read before the mesh is (the checkpoint's digest): a FIFO would block */
    struct stat st;
    return stat(sc.mesh, &st) != 0 || S_ISREG(st.st_mode) ? std::string() : std::string("-mesh ") + sc.mesh + ": not a regular file; give a gmsh .msh file";
  }));
  PetscCall(CheckFilesDistinct(sc));
  if (sc.output[0]) {
    const std::string xdmf = sc.output, base = xdmf.substr(0, xdmf.size() - 5), h5 = base + ".h5";
    PetscCheck(xdmf.size() > 5 && xdmf.substr(xdmf.size() - 5) == ".xdmf", PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-output %s: name the file <name>.xdmf (the data go to <name>.h5)", sc.output);
    PetscCall(CheckWritable(PETSC_COMM_WORLD, "-output", xdmf));
    PetscCall(CheckWritable(PETSC_COMM_WORLD, "-output", h5));
    if (sc.restart[0])
      PetscCall(CheckOnRankZero(PETSC_COMM_WORLD, PETSC_ERR_FILE_OPEN, [&]() {
        return std::ifstream(h5) ? std::string() : "-output " + xdmf + " with -restart: the series continues in " + h5 + ", which is not there; give the -output of the run that wrote the checkpoint";
      }));
  }
  if (sc.checkpoint[0]) PetscCall(CheckWritable(PETSC_COMM_WORLD, "-checkpoint", sc.checkpoint));
  if (sc.report[0]) PetscCall(CheckWritable(PETSC_COMM_WORLD, "-report", sc.report, false)); /* /dev/stdout will do */
  if (sc.restart[0] && CanonicalPath(sc.restart) != CanonicalPath(sc.checkpoint)) PetscCall(CheckNotClaimed(PETSC_COMM_WORLD, "-restart", sc.restart));
  PetscFunctionReturn(0);
}

PetscErrorCode ClaimSceneFiles(const Scene &sc)
{
  PetscFunctionBegin;
  if (sc.output[0]) PetscCall(ClaimFile(PETSC_COMM_WORLD, "-output", sc.output));             /* a second run on the same series would destroy it */
  if (sc.checkpoint[0]) PetscCall(ClaimFile(PETSC_COMM_WORLD, "-checkpoint", sc.checkpoint)); /* two runs writing one checkpoint would restart from each other's steps */
  PetscFunctionReturn(0);
}

PetscErrorCode ReleaseSceneFiles(const Scene &sc)
{
  PetscFunctionBegin;
  if (sc.output[0]) PetscCall(ReleaseFile(PETSC_COMM_WORLD, sc.output));
  if (sc.checkpoint[0]) PetscCall(ReleaseFile(PETSC_COMM_WORLD, sc.checkpoint));
  PetscFunctionReturn(0);
}

} // namespace fsi
