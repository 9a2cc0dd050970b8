// SPDX-License-Identifier: BSD-2-Clause
/* A pass over a gmsh file before PETSc reads it. PETSc 3.18's reader trusts the file: an element
   that names a node or a block that names an entity the file does not define is a segfault
   there, or a mesh with other cells on another number of ranks; a NaN coordinate is read as
   it is; a truncated file is "Insufficient data" without the file's name. */
#pragma once

#include <string>
#include <vector>

namespace fsi {

/* Why `file` cannot be the mesh, as a sentence that names the file and the line; "" if it can.
   It can if it is gmsh format 4.1 ASCII (what scripts/make-meshes writes; PETSc 3.18 mislabels
   the faces of 2.2 files), its node blocks give distinct tags and finite coordinates, its
   element blocks hold tetrahedra, triangles, lines (all of first or all of second order) or
   points that name nodes of $Nodes, every block names an entity of $Entities, it has a
   tetrahedron, and no section is cut off. *order (if asked) is then the elements' order, and
   *bent (if asked) the edges of second-order tetrahedra that are curved: 9 numbers each, the
   edge's two vertices (the smaller first, lexicographically) and its node; *groups (if asked)
   the physical groups of $PhysicalNames with their elements. */
struct GmshGroup {
  std::string name;
  int         dim;      /* 0 points, 1 lines, 2 faces, 3 cells */
  long long   elements; /* of the entities of that dimension carrying the group */
};
std::string GmshFileProblem(const std::string &file, int *order = nullptr, std::vector<double> *bent = nullptr, std::vector<GmshGroup> *groups = nullptr);

} // namespace fsi
