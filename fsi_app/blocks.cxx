// SPDX-License-Identifier: BSD-2-Clause
#include "blocks.h"
#include "coupling/block.h"
#include "fluid/block.h"
#include "geometry/block.h"
#include "structure/block.h"
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
};

PetscErrorCode CreateBlocks(Scene &sc, Blocks &b)
{
  std::string known;
  PetscBool   help;

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
  PetscCall(PetscOptionsHasHelp(nullptr, &help));
  if (help) { /* -help lists every block's options, the scene's or not */
    std::map<std::string, std::string> unused;
    for (const BlockType &t : Registry)
      if (std::find(sc.blocks.begin(), sc.blocks.end(), t.name) == sc.blocks.end()) PetscCall(t.create(sc)->ReadOptions(unused));
  }
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
  auto place = [](const Split &s) { return s.owner ? s.owner->SplitPlace() : 0; };
  std::stable_sort(splits.begin(), splits.end(), [&](const Split &a, const Split &b) { return place(a) < place(b); });
  return splits;
}

} // namespace fsi
