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
   It verifies the coupled problem: interface continuity and the fluid's volume balance. */
#pragma once

#include "fluid/block.h"
#include "geometry/block.h"
#include "scene.h"
#include "solver/block.h"
#include "structure/block.h"

namespace fsi {

class CouplingBlock : public Block {
public:
  explicit CouplingBlock(const Scene &sc) : sc(sc) {}
  const char    *Name() const override { return "coupling"; }
  PetscErrorCode Wire(const std::vector<Block *> &scene) override;
  PetscErrorCode ReadOptions(std::map<std::string, std::string> &) override { return 0; } /* none of its own */
  PetscErrorCode Check() const override;
  void           Groups(std::vector<GroupUse> &groups) const override { groups.push_back({geometry->opt.interface, "-geometry_interface", 2}); }

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

  PetscErrorCode AfterStep(DM dm, PetscInt step, PetscReal t, Vec x) override;
  PetscErrorCode Results(DM dm, Vec x, PetscReal t, RunReport &report) override;

  PetscInt field = -1; /* lambda */

private:
  /* An interface node this rank owns: local offsets and global indices (-1: constrained) of
     its lambda, u, d_s and d_f. */
  struct Node {
    PetscInt local[4], global[4][3];
  };
  enum { LAMBDA = 0, U = 1, DS = 2, DF = 3 };

  PetscErrorCode Continuity(DM dm, PetscReal *velocity, PetscReal *geometric);
  PetscErrorCode FluidVolume(DM dm, const PetscScalar *x, PetscReal *volume);
  PetscErrorCode InterfaceDisplacementSquared(DM dm, const PetscScalar *x, PetscReal *d2);

  const Scene          &sc;
  StructureBlock       *structure = nullptr;
  FluidBlock           *fluid     = nullptr;
  GeometryBlock        *geometry  = nullptr;
  const TimeHistory    *history   = nullptr;
  std::vector<Node>     nodes;
  std::vector<CellFace> wallFaces; /* the fluid's faces on the interface: the flux through the moving wall */
  /* per step: fluxes through inlet, outlet and interface, fluid volume (the volume balance) and
     int_Gamma |d|^2 dA (the interface displacement's norm in space and time) */
  struct Balance {
    PetscReal t, in, out, wall, volume, d2;
  };
  std::vector<Balance>   balance;
  std::vector<PetscReal> before;   /* volumes of the states before the first step recorded */
  PetscReal              d2Before = 0; /* int_Gamma |d|^2 dA of the state before it */
};

} // namespace fsi
