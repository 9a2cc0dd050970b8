static const char help[] = "Reads a gmsh mesh as fsi_app does and prints, per physical group, its global number of\n"
                           "cells, faces and vertices after distribution.\n"
                           "  -mesh <file>          the .msh file\n"
                           "  -require <a,b,...>    groups that must exist (the message names a missing one)\n";

#include "../mesh/mesh.h"

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
  std::vector<std::string> required;
  for (std::string s = req; !s.empty();) {
    const size_t k = s.find(',');
    required.push_back(s.substr(0, k));
    s = k == std::string::npos ? "" : s.substr(k + 1);
  }
  PetscCall(fsi::LoadMesh(PETSC_COMM_WORLD, file, required, {}, &dm));
  PetscCall(DMGetNumLabels(dm, &n));
  for (PetscInt i = 0; i < n; i++) {
    const char *name;
    PetscInt    c, f, v;
    PetscCall(DMGetLabelName(dm, i, &name));
    if (!strcmp(name, "depth") || !strcmp(name, "celltype")) continue;
    PetscCall(fsi::CountLabel(dm, name, 3, &c));
    PetscCall(fsi::CountLabel(dm, name, 2, &f));
    PetscCall(fsi::CountLabel(dm, name, 0, &v));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "group %s cells %" PetscInt_FMT " faces %" PetscInt_FMT " vertices %" PetscInt_FMT "\n", name, c, f, v));
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
