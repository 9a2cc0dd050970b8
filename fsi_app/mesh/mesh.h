// SPDX-License-Identifier: BSD-2-Clause
/* Meshes: gmsh files read into one DMPlex whose labels are the file's physical groups, checked
   for the groups a scene needs, and distributed with a METIS partition of the cells. */
#pragma once

#include <petscdmplex.h>
#include <string>
#include <vector>

namespace fsi {

/* A physical group that an option names, and what the option needs of it: cells (dim 3) or
   faces (dim 2; 0: either). Options of the same nonempty role (the regions, the fluid's boundary
   conditions) must name different groups. An optional group may be absent from the file, or empty. */
struct GroupUse {
  std::string group, option;
  PetscInt    dim      = 0;
  std::string role     = "";
  bool        optional = false;
};

/* Read `file` (gmsh .msh 4.1 ASCII, checked first by GmshFileProblem), after checking in the
   file that every group of `uses` exists, is not empty and holds elements of the dimension its
   option needs, and that options of one role name different groups; and distribute the cells over the ranks of `comm` (METIS on the
   cell dual graph, balancing the cells of each of `regions` when there are several). Errors
   name the file, the line or the option and group, and what the file has. `order` is the
   cells' geometry (-mesh_order): 2 curved by the file's second-order nodes (which it must
   have), 1 straight whatever the file has, 0 as the file is. With `reorder` the points are
   numbered by reverse Cuthill-McKee of the cells before distribution (each rank's share keeps
   that order): a cell's unknowns then lie near each other in every vector and matrix. */
PetscErrorCode LoadMesh(MPI_Comm comm, const std::string &file, PetscInt order, PetscBool reorder, const std::vector<GroupUse> &uses, const std::vector<std::string> &regions, DM *dm);

/* The node of a curved edge of dm (the file's second-order node, LoadMesh with order != 1),
   found by its vertices' coordinates a and b; false for a straight edge. PETSc keeps the
   vertices only (its own second-order reader stores cellwise coordinates, which the vertex
   loops here cannot use), so the curved edges ride beside the DM. */
PetscBool MeshEdgeNode(DM dm, const PetscReal a[3], const PetscReal b[3], PetscReal x[3]);
PetscBool MeshIsCurved(DM dm);

/* Call f(point) for every point of `label` whose value is in `values` (every value if empty). */
template <class F>
PetscErrorCode ForEachLabelPoint(DMLabel label, const std::vector<PetscInt> &values, F f)
{
  std::vector<PetscInt> vals(values);
  PetscFunctionBegin;
  if (vals.empty()) {
    IS              is;
    PetscInt        nv;
    const PetscInt *v;
    PetscCall(DMLabelGetValueIS(label, &is));
    PetscCall(ISGetLocalSize(is, &nv));
    PetscCall(ISGetIndices(is, &v));
    vals.assign(v, v + nv);
    PetscCall(ISRestoreIndices(is, &v));
    PetscCall(ISDestroy(&is));
  }
  for (PetscInt value : vals) {
    IS              pts;
    PetscInt        np;
    const PetscInt *p;
    PetscCall(DMLabelGetStratumIS(label, value, &pts));
    if (!pts) continue;
    PetscCall(ISGetLocalSize(pts, &np));
    PetscCall(ISGetIndices(pts, &p));
    for (PetscInt i = 0; i < np; i++) PetscCall(f(p[i]));
    PetscCall(ISRestoreIndices(pts, &p));
    PetscCall(ISDestroy(&pts));
  }
  PetscFunctionReturn(0);
}

/* Label `name` (value 1) on the faces of the mesh's boundary: one cell on their side and not
   shared with another rank (PETSc 3.18's DMPlexMarkBoundaryFaces also marks the faces between
   ranks' parts). */
PetscErrorCode MarkBoundaryFaces(DM dm, const char *name);

/* Global number of points of depth `depth` (3: cells, 2: faces, 0: vertices) in label `name`. */
PetscErrorCode CountLabel(DM dm, const std::string &name, PetscInt depth, PetscInt *count);

/* Per point of dm's chart: 1 if this rank owns it, 0 if it is a ghost (a leaf of the point SF). */
PetscErrorCode OwnedPoints(DM dm, std::vector<char> &owned);

} // namespace fsi
