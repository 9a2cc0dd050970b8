// SPDX-License-Identifier: BSD-2-Clause
#include "blocks.h"
#include <algorithm>

namespace fsi {

PetscErrorCode CreateBlocks(const Scene &sc, Blocks &b)
{
  auto      has      = [&](const char *name) { return (PetscBool)(std::find(sc.blocks.begin(), sc.blocks.end(), name) != sc.blocks.end()); };
  PetscBool coupled  = has("coupling");

  PetscFunctionBegin;
  for (const auto &n : sc.blocks)
    PetscCheck(n == "structure" || n == "fluid" || n == "geometry" || n == "coupling", PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-blocks: unknown block '%s' (structure, fluid, geometry, coupling)", n.c_str());
  PetscCheck(!coupled || (has("structure") && has("fluid") && has("geometry")), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-blocks: the coupling ties structure, fluid and geometry: name all four");
  PetscCheck(!coupled || sc.region[0], PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-structure_region: name the wall's group (the fluid's cells are not the wall's)");
  if (has("structure")) b.structure = std::make_unique<StructureBlock>(sc);
  if (has("geometry")) b.geometry = std::make_unique<GeometryBlock>(sc, coupled, has("fluid"));
  if (has("fluid")) b.fluid = std::make_unique<FluidBlock>(sc, b.geometry.get());
  if (coupled) b.coupling = std::make_unique<CouplingBlock>(sc, *b.structure, *b.fluid, *b.geometry);
  for (Block *blk : {(Block *)b.structure.get(), (Block *)b.fluid.get(), (Block *)b.geometry.get(), (Block *)b.coupling.get()})
    if (blk) b.list.push_back(blk);
  PetscCheck(!b.list.empty(), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-blocks: name at least one block");
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
  const std::vector<std::string> order = {"structure", "geometry", "fluid"}; /* the block lower triangle */
  auto rank = [&](const std::string &n) { return std::find(order.begin(), order.end(), n) - order.begin(); };
  std::stable_sort(splits.begin(), splits.end(), [&](const Split &a, const Split &b) { return rank(a.name) < rank(b.name); });
  return splits;
}

} // namespace fsi
