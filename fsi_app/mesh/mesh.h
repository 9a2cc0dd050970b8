/* Meshes: gmsh files read into one DMPlex whose labels are the file's physical groups, checked
   for the groups a scene needs, and distributed with a METIS partition of the cells. */
#pragma once

#include <petscdmplex.h>
#include <string>
#include <vector>

namespace fsi {

/* Read `file` (gmsh .msh, 2.2 or 4.1), check that every name in `required` is a physical group
   with at least one entity, and distribute the cells over the ranks of `comm` (METIS on the
   cell dual graph). Errors name the file, the group, and what the file has. */
PetscErrorCode LoadMesh(MPI_Comm comm, const std::string &file, const std::vector<std::string> &required, DM *dm);

/* Global number of points of depth `depth` (3: cells, 2: faces, 0: vertices) in label `name`. */
PetscErrorCode CountLabel(DM dm, const std::string &name, PetscInt depth, PetscInt *count);

} // namespace fsi
