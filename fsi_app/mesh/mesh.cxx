// SPDX-License-Identifier: BSD-2-Clause
#include "mesh.h"
#include "gmsh_file.h"
#include "base/files.h"
#include <petscsf.h>
#include <metis.h>
#include <algorithm>
#include <array>
#include <map>
#include <set>

namespace fsi {

PetscErrorCode CountLabel(DM dm, const std::string &name, PetscInt depth, PetscInt *count)
{
  DMLabel  label;
  PetscInt local = 0, pStart, pEnd;

  PetscFunctionBegin;
  *count = 0;
  PetscCall(DMGetLabel(dm, name.c_str(), &label));
  if (label) {
    std::vector<char> owned;
    PetscCall(DMPlexGetDepthStratum(dm, depth, &pStart, &pEnd));
    PetscCall(OwnedPoints(dm, owned));
    PetscCall(ForEachLabelPoint(label, {}, [&](PetscInt p) -> PetscErrorCode {
      local += p >= pStart && p < pEnd && owned[p];
      return 0;
    }));
  }
  PetscCallMPI(MPIU_Allreduce(&local, count, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

PetscErrorCode OwnedPoints(DM dm, std::vector<char> &owned)
{
  PetscSF         sf;
  PetscInt        pStart, pEnd, nleaves = 0;
  const PetscInt *leaves = nullptr;

  PetscFunctionBegin;
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  owned.assign(pEnd, 1);
  PetscCall(DMGetPointSF(dm, &sf));
  if (sf) PetscCall(PetscSFGetGraph(sf, nullptr, &nleaves, &leaves, nullptr));
  for (PetscInt l = 0; l < nleaves; l++) owned[leaves ? leaves[l] : l] = 0;
  PetscFunctionReturn(0);
}

/* The names of the file's groups holding elements of dimension dim (-1: every name), for error
   messages. */
static std::string GroupNames(const std::vector<GmshGroup> &groups, int dim)
{
  std::string           names;
  std::set<std::string> seen; /* a name may stand for groups of several dimensions */
  for (const auto &g : groups)
    if ((dim < 0 || (g.dim == dim && g.elements)) && seen.insert(g.name).second) names += (names.empty() ? "" : ", ") + g.name;
  return names.empty() ? "none" : names;
}

/* Why the file's groups cannot serve `uses` (one sentence naming the option, the group and the
   file; "" if they can): each group an option names is in the file, holds elements, and holds
   those of the dimension the option takes; options of one role name different groups. The
   file's own counts, not PETSc's labels: PETSc makes no label of an empty group, and a
   missing label cannot tell a missing group from an empty one or from one of lines. */
static std::string GroupProblem(const std::string &file, const std::vector<GmshGroup> &groups, const std::vector<GroupUse> &uses)
{
  static const char *const holds[] = {"points", "lines", "faces", "cells"};
  for (const auto &u : uses) {
    const std::string use = u.option + " " + u.group + ": ";
    long long         n[4] = {0, 0, 0, 0};
    bool              named = false;
    for (const auto &g : groups)
      if (g.name == u.group) named = true, n[g.dim] += g.elements;
    const long long all = n[0] + n[1] + n[2] + n[3], fit = u.dim ? n[u.dim] : n[2] + n[3];
    const char     *takes = u.dim ? holds[u.dim] : "faces or cells";
    if (u.optional && !all) continue;
    if (!named) return use + "mesh file '" + file + "' has no physical group '" + u.group + "', which this scene needs (the file has: " + GroupNames(groups, -1) + ")";
    if (!all) return use + "the physical group '" + u.group + "' of mesh file '" + file + "' is empty (named, but no element belongs to it), and the option takes a group of " + takes;
    if (!fit) {
      const int has = n[3] ? 3 : n[2] ? 2 : n[1] ? 1 : 0;
      return use + "the group holds " + holds[has] + ", and the option takes a group of " + takes + " (mesh file '" + file + "'; its groups of " + takes + ": " + GroupNames(groups, u.dim ? (int)u.dim : -1) + ")";
    }
    for (const auto &v : uses)
      if (!u.role.empty() && u.role == v.role && u.option != v.option && u.group == v.group) return u.option + " " + u.group + " and " + v.option + " " + v.group + " name the same group: the " + u.role + " must be different groups";
  }
  return "";
}

/* Cells to ranks: METIS k-way on the dual graph (cells sharing a face), computed where the
   serial mesh lives, handed to DMPlexDistribute through a shell partitioner. With two or more
   regions, one balance constraint per region (a vertex weight per region: 1 on its cells), so
   every rank gets its share of each region's cells, not only of all cells. */
static PetscErrorCode DistributeWithMetis(DM *dm, const std::vector<std::string> &regions)
{
  PetscMPIInt      size, rank;
  PetscInt         nv, *offsets, *adjacency;
  IS               globalNumbering;
  PetscPartitioner part;
  DM               dist = nullptr;
  MPI_Comm         comm = PetscObjectComm((PetscObject)*dm);

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (size == 1) PetscFunctionReturn(0);
  PetscCall(DMPlexCreatePartitionerGraph(*dm, 0, &nv, &offsets, &adjacency, &globalNumbering));
  std::vector<PetscInt> sizes(size, 0), points;
  if (nv) {
    std::vector<idx_t> xadj(offsets, offsets + nv + 1), adj(adjacency, adjacency + offsets[nv]), p(nv), weights;
    idx_t n = (idx_t)nv, ncon = regions.size() > 1 ? (idx_t)regions.size() : 1, np = size, cut, options[METIS_NOPTIONS];
    if (ncon > 1) {
      PetscInt cStart, cEnd;
      PetscCall(DMPlexGetHeightStratum(*dm, 0, &cStart, &cEnd));
      PetscCheck(cEnd - cStart == nv, PETSC_COMM_SELF, PETSC_ERR_PLIB, "the partitioner graph has %" PetscInt_FMT " vertices for %" PetscInt_FMT " cells", nv, cEnd - cStart);
      weights.assign(ncon * nv, 0);
      for (idx_t r = 0; r < ncon; r++) {
        DMLabel label;
        PetscCall(DMGetLabel(*dm, regions[r].c_str(), &label));
        for (PetscInt c = 0; c < nv && label; c++) {
          PetscInt v;
          PetscCall(DMLabelGetValue(label, cStart + c, &v));
          if (v >= 0) weights[ncon * c + r] = 1;
        }
      }
      for (PetscInt c = 0; c < nv; c++) /* a cell of no region counts for the first */
        if (std::all_of(&weights[ncon * c], &weights[ncon * c] + ncon, [](idx_t w) { return w == 0; })) weights[ncon * c] = 1;
    }
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_SEED] = 7;
    const int status = METIS_PartGraphKway(&n, &ncon, xadj.data(), adj.data(), weights.empty() ? nullptr : weights.data(), nullptr, nullptr, &np, nullptr, nullptr, options, &cut, p.data());
    PetscCheck(status == METIS_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "METIS could not partition the %" PetscInt_FMT " cells of the mesh into %d parts (status %d)", nv, size, status);
    std::vector<std::vector<PetscInt>> byRank(size);
    for (PetscInt c = 0; c < nv; c++) byRank[p[c]].push_back(c);
    for (PetscMPIInt r = 0; r < size; r++) sizes[r] = (PetscInt)byRank[r].size(), points.insert(points.end(), byRank[r].begin(), byRank[r].end());
  }
  PetscCall(PetscFree(offsets));
  PetscCall(PetscFree(adjacency));
  PetscCall(ISDestroy(&globalNumbering));
  PetscCall(DMPlexGetPartitioner(*dm, &part));
  PetscCall(PetscPartitionerSetType(part, PETSCPARTITIONERSHELL));
  PetscCall(PetscPartitionerShellSetPartition(part, size, sizes.data(), points.empty() ? nullptr : points.data()));
  PetscCall(DMPlexDistribute(*dm, 0, nullptr, &dist));
  if (dist) {
    PetscCall(DMDestroy(dm));
    *dm = dist;
  }
  PetscFunctionReturn(0);
}

/* The curved edges: (vertex a, vertex b) -> the edge's node, a < b lexicographically. */
using CurvedEdges = std::map<std::array<PetscReal, 6>, std::array<PetscReal, 3>>;
static const char CurvedEdgesKey[] = "fsi_curved_edges";

static PetscErrorCode DestroyCurvedEdges(void *ctx)
{
  delete (CurvedEdges *)ctx;
  return 0;
}

/* Every rank gets the curved edges rank 0 read (boundary edges on curved surfaces: few). */
static PetscErrorCode AttachCurvedEdges(MPI_Comm comm, std::vector<double> &bent, DM dm)
{
  PetscInt          n = (PetscInt)bent.size();
  PetscContainer    c;
  auto             *edges = new CurvedEdges;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Bcast(&n, 1, MPIU_INT, 0, comm));
  bent.resize(n);
  PetscCallMPI(MPI_Bcast(bent.data(), (PetscMPIInt)n, MPI_DOUBLE, 0, comm));
  for (PetscInt k = 0; k < n; k += 9) {
    std::array<PetscReal, 6> key;
    for (int i = 0; i < 6; i++) key[i] = bent[k + i];
    (*edges)[key] = {bent[k + 6], bent[k + 7], bent[k + 8]};
  }
  PetscCall(PetscContainerCreate(comm, &c));
  PetscCall(PetscContainerSetPointer(c, edges));
  PetscCall(PetscContainerSetUserDestroy(c, DestroyCurvedEdges));
  PetscCall(PetscObjectCompose((PetscObject)dm, CurvedEdgesKey, (PetscObject)c));
  PetscCall(PetscContainerDestroy(&c));
  PetscFunctionReturn(0);
}

PetscBool MeshIsCurved(DM dm)
{
  PetscObject c = nullptr;
  PetscObjectQuery((PetscObject)dm, CurvedEdgesKey, &c);
  return (PetscBool)(c != nullptr);
}

PetscBool MeshEdgeNode(DM dm, const PetscReal a[3], const PetscReal b[3], PetscReal x[3])
{
  PetscObject  c     = nullptr;
  CurvedEdges *edges = nullptr;
  PetscObjectQuery((PetscObject)dm, CurvedEdgesKey, &c);
  if (!c) return PETSC_FALSE;
  PetscContainerGetPointer((PetscContainer)c, (void **)&edges);
  const bool               swap = std::lexicographical_compare(b, b + 3, a, a + 3);
  std::array<PetscReal, 6> key;
  for (int i = 0; i < 3; i++) key[i] = swap ? b[i] : a[i], key[3 + i] = swap ? a[i] : b[i];
  const auto e = edges->find(key);
  if (e == edges->end()) return PETSC_FALSE;
  for (int i = 0; i < 3; i++) x[i] = e->second[i];
  return PETSC_TRUE;
}

/* The serial mesh renumbered by reverse Cuthill-McKee of its cells (vertices and edges in the
   order the cells first reach them). PETSc 3.18's DMPlexPermute keeps no point SF, so this runs
   before distribution, where the mesh has none. A gmsh file's own order may scatter a cell's
   vertices over the whole mesh (the tubes' files do), and the Jacobian's element insertion
   then misses the cache on them. */
static PetscErrorCode Reorder(DM *dm)
{
  IS perm;
  DM permuted;

  PetscFunctionBegin;
  PetscCall(DMPlexGetOrdering(*dm, MATORDERINGRCM, nullptr, &perm));
  PetscCall(DMPlexPermute(*dm, perm, &permuted));
  PetscCall(ISDestroy(&perm));
  PetscCall(DMDestroy(dm));
  *dm = permuted;
  PetscFunctionReturn(0);
}

PetscErrorCode LoadMesh(MPI_Comm comm, const std::string &file, PetscInt order, PetscBool reorder, const std::vector<GroupUse> &uses, const std::vector<std::string> &regions, DM *dm)
{
  PetscBool           set;
  int                 fileOrder = 1;
  std::vector<double> bent;

  PetscFunctionBegin;
  PetscCall(CheckOnRankZero(comm, PETSC_ERR_FILE_UNEXPECTED, [&]() { /* where PETSc reads it */
    std::vector<GmshGroup> groups;
    const std::string      why = GmshFileProblem(file, &fileOrder, order == 1 ? nullptr : &bent, &groups);
    return why.empty() ? GroupProblem(file, groups, uses) : why;
  }));
  PetscCallMPI(MPI_Bcast(&fileOrder, 1, MPI_INT, 0, comm));
  PetscCheck(order != 2 || fileOrder == 2, comm, PETSC_ERR_ARG_INCOMP, "-mesh_order 2: mesh file '%s' has first-order cells only; make it with gmsh -order 2 (scripts/make-meshes NAME LEVEL 2)", file.c_str());
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-dm_plex_gmsh_use_regions", &set));
  if (!set) PetscCall(PetscOptionsSetValue(nullptr, "-dm_plex_gmsh_use_regions", "true")); /* labels named by physical groups */
  PetscCall(PetscOptionsSetValue(nullptr, "-dm_plex_gmsh_highorder", "false")); /* the vertices; the curved edges below */
  PetscCall(DMPlexCreateGmshFromFile(comm, file.c_str(), PETSC_TRUE, dm));
  if (reorder) PetscCall(Reorder(dm));
  PetscCall(PetscObjectSetName((PetscObject)*dm, "mesh"));
  PetscCall(DistributeWithMetis(dm, regions));
  if (fileOrder == 2 && order != 1) PetscCall(AttachCurvedEdges(comm, bent, *dm));
  PetscFunctionReturn(0);
}

PetscErrorCode MarkBoundaryFaces(DM dm, const char *name)
{
  PetscSF         sf;
  PetscInt        fStart, fEnd, pStart, pEnd, nleaves;
  const PetscInt *leaves, *degree;
  DMLabel         label;

  PetscFunctionBegin;
  PetscCall(DMCreateLabel(dm, name));
  PetscCall(DMGetLabel(dm, name, &label));
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &fStart, &fEnd));
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(PetscSFGetGraph(sf, nullptr, &nleaves, &leaves, nullptr));
  std::vector<char> shared(pEnd - pStart, 0);
  for (PetscInt l = 0; l < nleaves; l++) shared[(leaves ? leaves[l] : l) - pStart] = 1;
  PetscCall(PetscSFComputeDegreeBegin(sf, &degree));
  PetscCall(PetscSFComputeDegreeEnd(sf, &degree));
  for (PetscInt p = pStart; p < pEnd && nleaves >= 0; p++)
    if (degree[p - pStart]) shared[p - pStart] = 1;
  for (PetscInt f = fStart; f < fEnd; f++) {
    PetscInt ns;
    PetscCall(DMPlexGetSupportSize(dm, f, &ns));
    if (ns == 1 && !shared[f - pStart]) PetscCall(DMLabelSetValue(label, f, 1));
  }
  PetscFunctionReturn(0);
}

} // namespace fsi
