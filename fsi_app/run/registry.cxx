// SPDX-License-Identifier: BSD-2-Clause
#include "registry.h"
#include "coupling/block.h"
#include "fluid/block.h"
#include "geometry/block.h"
#include "outlets/block.h"
#include "structure/block.h"
#include "mesh/mesh.h"
#include <algorithm>
#include <functional>

namespace fsi {

/* Every block type a scene can name, in the order of their fields. */
struct BlockType {
  const char                                          *name;
  std::function<std::unique_ptr<Block>(const Scene &)> create;
};
static const BlockType Registry[] = {
  {"structure", [](const Scene &sc) { return std::unique_ptr<Block>(new StructureBlock(sc)); }},
  {"fluid",     [](const Scene &sc) { return std::unique_ptr<Block>(new FluidBlock(sc)); }    },
  {"geometry",  [](const Scene &sc) { return std::unique_ptr<Block>(new GeometryBlock(sc)); } },
  {"coupling",  [](const Scene &sc) { return std::unique_ptr<Block>(new CouplingBlock(sc)); } },
  {"outlets",   [](const Scene &sc) { return std::unique_ptr<Block>(new OutletsBlock(sc)); }  },
};

PetscErrorCode CreateBlocks(Scene &sc, Blocks &b)
{
  std::string known;

  PetscFunctionBegin;
  for (const BlockType &t : Registry) known += (known.empty() ? "" : ", ") + std::string(t.name);
  for (const auto &n : sc.blocks)
    PetscCheck(std::any_of(std::begin(Registry), std::end(Registry), [&](const BlockType &t) { return n == t.name; }), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-blocks: unknown block '%s' (%s)", n.c_str(), known.c_str());
  for (const BlockType &t : Registry)
    if (std::find(sc.blocks.begin(), sc.blocks.end(), t.name) != sc.blocks.end()) b.owned.push_back(t.create(sc));
  PetscCheck(!b.owned.empty(), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-blocks: name at least one block");
  for (auto &blk : b.owned) b.list.push_back(blk.get());
  for (Block *blk : b.list) PetscCall(blk->Wire(b.list));
  for (Block *blk : b.list) PetscCall(blk->ReadOptions(sc.problem));
  for (Block *blk : b.list) PetscCall(blk->Check());
  { /* the other block types read theirs too, into nothing: -help lists every block's options, and a
       scene file's options for a block left out (-blocks fluid on the coupled scene) are known */
    std::map<std::string, std::string> unused;
    for (const BlockType &t : Registry)
      if (std::find(sc.blocks.begin(), sc.blocks.end(), t.name) == sc.blocks.end()) PetscCall(t.create(sc)->ReadOptions(unused));
  }
  PetscFunctionReturn(0);
}

/* "boundary": the manufactured solutions' faces. */
PetscErrorCode CreateSceneMesh(const Scene &sc, const Blocks &b, DM *dm)
{
  std::vector<GroupUse>    groups, required;
  std::vector<std::string> regions;

  PetscFunctionBegin;
  for (const Block *blk : b.list) {
    blk->Groups(groups);
    if (!blk->Region().empty() && std::find(regions.begin(), regions.end(), blk->Region()) == regions.end()) regions.push_back(blk->Region());
  }
  for (const auto &g : groups) /* a region may be every cell (""); a set of faces is a group */
    PetscCheck(!g.group.empty() || g.dim == 3 || g.optional, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s: the value is empty; name a physical group of faces of %s", g.option.c_str(), sc.mesh);
  for (const auto &g : groups) /* "boundary" is made below; a group named by the same option twice is checked once */
    if (!g.group.empty() && g.group != "boundary" && std::none_of(required.begin(), required.end(), [&](const GroupUse &r) { return r.group == g.group && r.option == g.option; })) required.push_back(g);
  PetscCall(LoadMesh(PETSC_COMM_WORLD, sc.mesh, sc.meshOrder, sc.meshReorder, required, regions, dm));
  PetscCheck(!sc.refine || !MeshIsCurved(*dm), PETSC_COMM_WORLD, PETSC_ERR_SUP, "-refine %" PetscInt_FMT " on the curved cells of '%s': refinement would place the new nodes on the straight edges; make a finer second-order mesh (scripts/make-meshes NAME LEVEL 2) or read this one with -mesh_order 1", sc.refine, sc.mesh);
  if (sc.refine > 0) { /* each refinement makes 8 tetrahedra of one; a tetrahedral mesh has about 4.3 points (cells, faces, edges, vertices) per cell */
    PetscInt  cStart, cEnd;
    PetscReal cells, fine;
    PetscCall(DMPlexGetHeightStratum(*dm, 0, &cStart, &cEnd));
    PetscReal local = (PetscReal)(cEnd - cStart);
    PetscCallMPI(MPIU_Allreduce(&local, &cells, 1, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
    fine = cells * PetscPowReal(8.0, (PetscReal)sc.refine);
    PetscCheck(4.3 * fine <= (PetscReal)PETSC_MAX_INT, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE,
               "-refine %" PetscInt_FMT ": the mesh's %.0f cells would become %.3g (each refinement multiplies them by 8), more than PETSc's %d-bit indices can number (about %.3g cells); refine less, or start from a finer mesh file",
               sc.refine, (double)cells, (double)fine, (int)(8 * sizeof(PetscInt)), (double)PETSC_MAX_INT / 4.3);
  }
  for (PetscInt k = 0; k < sc.refine; k++) {
    DM fine;
    PetscCall(DMRefine(*dm, PETSC_COMM_WORLD, &fine));
    PetscCall(DMDestroy(dm));
    *dm = fine;
  }
  PetscCall(MarkBoundaryFaces(*dm, "boundary"));
  PetscFunctionReturn(0);
}

PetscErrorCode SetUpBlocks(DM dm, Blocks &b)
{
  PetscFunctionBegin;
  for (Block *blk : b.list) PetscCall(blk->AddFields(dm));
  for (Block *blk : b.list) PetscCall(blk->AddConditions(dm, b.conditions));
  PetscCall(CreateSection(dm, b.conditions));
  for (Block *blk : b.list) PetscCall(blk->SetUp(dm));
  b.system.blocks = b.list;
  PetscCall(SystemAttach(dm, b.system));
  PetscFunctionReturn(0);
}

std::vector<std::string> Blocks::Prefixes()
{
  std::vector<std::string> p;
  for (const BlockType &t : Registry) p.push_back(std::string(t.name) + "_");
  return p;
}

Splits Blocks::Splits() const
{
  fsi::Splits splits;
  for (Block *blk : list) {
    auto s = std::find_if(splits.begin(), splits.end(), [&](const Split &x) { return x.name == blk->SplitName(); });
    if (s == splits.end()) s = splits.insert(splits.end(), {blk->SplitName(), {}, nullptr});
    for (PetscInt f : blk->SplitFields()) s->fields.push_back(f);
    if (s->name == blk->Name()) s->owner = blk;
  }
  for (auto &s : splits) std::sort(s.fields.begin(), s.fields.end());
  auto place = [](const Split &s) { return s.owner ? s.owner->SplitPlace() : 0; };
  std::stable_sort(splits.begin(), splits.end(), [&](const Split &a, const Split &b) { return place(a) < place(b); });
  return splits;
}

} // namespace fsi
