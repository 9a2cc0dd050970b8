// SPDX-License-Identifier: BSD-2-Clause
/* fsi_app: a scene of blocks (core/block.h) run as one Newton system (run/run.h). */
static const char help[] = "fsi_app: monolithic fluid-structure interaction on PETSc. A scene is a list of blocks:\n"
                           "the structure (linear elastic, Neo-Hooke and arterial walls; statics and dynamics), the\n"
                           "fluid (Navier-Stokes, P2-P1, ALE on a moving mesh), the geometry (harmonic mesh motion)\n"
                           "and the coupling (a Lagrange multiplier on the interface), solved as one Newton system.\n"
                           "Scenes are options files: -options_file scenes/X.opts; a path an options file names\n"
                           "(-options_file, -mesh, -restart) is relative to that file's folder (else to the working\n"
                           "directory). Each option below: <its value>, its units and range, its default if changed.\n";

#include "base/options_files.h"
#include "facsi/fluid_pc.h"
#include "run/run.h"
#include <cstdio>
#include <petscgdsw.h>

int main(int argc, char **argv)
{
  std::vector<std::string> args(argv + 1, argv + argc);
  std::vector<char *>      expanded{argv[0]};
  int                      rank;

  std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ); /* whole lines: a job log that merges stderr into stdout is not cut mid-line by an error */
  MPI_Init(&argc, &argv); /* before PETSc: its own reader of options files cannot be stopped on a cycle */
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const std::string error = fsi::ExpandOptionsFiles(args);
  if (!error.empty()) {
    if (!rank) std::fprintf(stderr, "fsi_app: %s\n", error.c_str());
    MPI_Finalize();
    return 1;
  }
  for (std::string &a : args) expanded.push_back(&a[0]);
  int    n = (int)expanded.size();
  char **v = expanded.data();
  PetscCall(PetscInitialize(&n, &v, nullptr, help));
  PetscCall(PCGDSWRegister());
  PetscCall(fsi::PCRegisterFaCSIFluid());
  PetscCall(fsi::RunScene());
  PetscCall(PetscFinalize());
  MPI_Finalize();
  return 0;
}
