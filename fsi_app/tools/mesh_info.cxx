// SPDX-License-Identifier: BSD-2-Clause
static const char help[] = "Reads a gmsh mesh as fsi_app does and prints, per physical group, its global number of\n"
                           "cells and faces, and of vertices and edges in their closure, after distribution.\n"
                           "  -mesh <file>          the .msh file\n"
                           "  -require <a,b,...>    groups that must exist (the message names a missing one)\n";

#include "mesh/mesh.h"

int main(int argc, char **argv)
{
  char      file[PETSC_MAX_PATH_LEN] = "", req[1024] = "";
  DM        dm;
  PetscInt  n;
  PetscBool flg;

  PetscCall(PetscInitialize(&argc, &argv, nullptr, help));
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-mesh", file, sizeof(file), &flg));
  PetscCheck(flg, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "give the mesh file with -mesh <file.msh>");
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-require", req, sizeof(req), nullptr));
  std::vector<fsi::GroupUse> required;
  for (std::string s = req; !s.empty();) {
    const size_t k = s.find(',');
    required.push_back({s.substr(0, k), "-require"});
    s = k == std::string::npos ? "" : s.substr(k + 1);
  }
  PetscCall(fsi::LoadMesh(PETSC_COMM_WORLD, file, 0, PETSC_FALSE, required, {}, &dm));
  PetscCall(DMGetNumLabels(dm, &n)); /* the groups: the closure labels made below come after them */
  for (PetscInt i = 0; i < n; i++) {
    const char *name;
    PetscInt    c, f, v, e;
    DMLabel     label, closure;
    PetscCall(DMGetLabelName(dm, i, &name));
    if (!strcmp(name, "depth") || !strcmp(name, "celltype") || !strncmp(name, "closure_", 8)) continue;
    PetscCall(fsi::CountLabel(dm, name, 3, &c));
    PetscCall(fsi::CountLabel(dm, name, 2, &f));
    const std::string cname = std::string("closure_") + name; /* the group's points and their closure */
    PetscCall(DMGetLabel(dm, name, &label));
    PetscCall(DMCreateLabel(dm, cname.c_str()));
    PetscCall(DMGetLabel(dm, cname.c_str(), &closure));
    PetscCall(fsi::ForEachLabelPoint(label, {}, [&](PetscInt p) { return DMLabelSetValue(closure, p, 1); }));
    PetscCall(DMPlexLabelComplete(dm, closure));
    PetscCall(fsi::CountLabel(dm, cname, 0, &v));
    PetscCall(fsi::CountLabel(dm, cname, 1, &e));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "group %s cells %" PetscInt_FMT " faces %" PetscInt_FMT " vertices %" PetscInt_FMT " edges %" PetscInt_FMT "\n", name, c, f, v, e));
  }
  PetscInt cStart, cEnd, local, total;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  local = cEnd - cStart;
  PetscCallMPI(MPIU_Allreduce(&local, &total, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCall(PetscSynchronizedPrintf(PETSC_COMM_WORLD, "rank cells %" PetscInt_FMT "\n", local));
  PetscCall(PetscSynchronizedFlush(PETSC_COMM_WORLD, PETSC_STDOUT));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "cells %" PetscInt_FMT "\n", total));
  PetscCall(DMDestroy(&dm));
  PetscCall(PetscFinalize());
  return 0;
}
