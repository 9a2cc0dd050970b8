// SPDX-License-Identifier: BSD-2-Clause
/* The coupling block: the Lagrange multiplier lambda (P2, 3 components, on the interface
   nodes) and the coupling rows of the monolithic system (eq. 9 of Heinlein, Klawonn,
   Rheinbach 2016, the pressure-wave benchmark) for conforming meshes, where C1|G = I, C3|G = -I, C4|G = I are nodal selections:
     fluid momentum at an interface node      + lambda                  (C1^T lambda)
     structure at an interface node           - lambda                  (C3^T lambda)
     lambda row                               u - d_t d_s = 0           (C1 u + C2 d_s = C2 d_s^n)
     geometry at an interface node            d_f - d_s = 0             (C4 d_s + H d_f, H|G = I)
   d_t is the structure's own first difference (backward Euler or BDF2), so the interface
   velocity is exactly the discrete wall velocity; lambda is the nodal force the fluid exerts
   on the wall. Where u and d_s are both prescribed, lambda is too (its row would be empty).
   It reports the interface continuity of the state it ends with; the fluid reports its volume
   balance on the moving mesh. */
#pragma once

#include "core/block.h"
#include "core/scene.h"

namespace fsi {

class CouplingBlock : public Block {
public:
  explicit CouplingBlock(const Scene &sc) : sc(sc) {}
  const char    *Name() const override { return "coupling"; }
  PetscErrorCode Wire(const std::vector<Block *> &scene) override;
  PetscErrorCode ReadOptions(std::map<std::string, std::string> &) override { return 0; } /* none of its own */
  PetscErrorCode Check() const override;
  void           Groups(std::vector<GroupUse> &groups) const override { groups.push_back({geometry->Group("interface"), "-geometry_interface", 2}); }

  PetscErrorCode AddFields(DM dm) override;
  PetscErrorCode AddConditions(DM dm, Conditions &list) override;
  PetscErrorCode SetUp(DM dm) override;
  void           Attach(SNES, const TimeHistory *h) override { history = h; }

  PetscErrorCode Residual(const PetscScalar *x, PetscScalar *f) override;
  PetscErrorCode Jacobian(const PetscScalar *x, Mat P) override;
  void           Couplings(Sparsity &s) const override;

  /* lambda joins the fluid's split: the fluid block with its interface rows (FaCSI's fluid(u, p, lambda)) */
  const char           *SplitName() const override { return "fluid"; }
  std::vector<PetscInt> SplitFields() const override { return {field}; }
  void                  Unknowns(std::vector<std::pair<std::string, PetscInt>> &u) const override { u.push_back({"multiplier", field}); }
  PetscBool             RowsWithoutDiagonal() const override { return PETSC_TRUE; } /* lambda's rows hold only u - d_t d_s */

  PetscErrorCode Results(DM dm, Vec x, PetscReal t, RunReport &report) override;

private:
  /* An interface node this rank owns: local offsets and global indices (-1: constrained) of
     its lambda, u, d_s and d_f. */
  struct Node {
    PetscInt local[4], global[4][3];
  };
  enum { LAMBDA = 0, U = 1, DS = 2, DF = 3 };

  PetscErrorCode Continuity(DM dm, PetscReal *velocity, PetscReal *geometric);

  const Scene       &sc;
  const Block       *structure = nullptr, *fluid = nullptr, *geometry = nullptr;
  const TimeHistory *history   = nullptr;
  PetscInt           field     = -1; /* lambda */
  std::vector<Node>  nodes;
};

} // namespace fsi
