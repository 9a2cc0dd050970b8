// SPDX-License-Identifier: BSD-2-Clause
/* The fluid block: velocity u (P2) and pressure p (P1) on the fluid region, Navier-Stokes in
   ALE form on the mesh moved by the geometry block's d_f (or on the fixed mesh), its no-slip
   groups, inflow velocity or traction, and the exact data of the verification flows
   (Poiseuille, the manufactured flows of verification/mms.h); it reports the fluxes through
   the inlet and outlet and the errors of the verification flows. */
#pragma once

#include "fluid/assembly.h"
#include "discretization/probes.h"
#include "geometry/block.h"
#include "scene.h"
#include "solver/block.h"

namespace fsi {

class FluidBlock : public Block {
public:
  /* `geometry`: the block whose d_f moves the mesh (nullptr: a fixed mesh) */
  FluidBlock(const Scene &sc, const GeometryBlock *geometry) : sc(sc), geometry(geometry) {}
  const char *Name() const override { return "fluid"; }
  void        Groups(std::vector<GroupUse> &groups) const override;
  std::string Region() const override { return sc.fluidRegion; }

  PetscErrorCode AddFields(DM dm) override;
  PetscErrorCode AddConditions(DM dm, Conditions &list) override;
  PetscErrorCode SetUp(DM dm) override;
  void           Attach(SNES snes, const TimeHistory *history) override { forms.snes = snes, forms.history = history; }

  PetscErrorCode Residual(const PetscScalar *x, PetscScalar *f) override { return FluidResidual(&forms, x, f); }
  PetscErrorCode Jacobian(const PetscScalar *x, Mat P) override { return FluidJacobian(&forms, x, P); }
  void           Couplings(Sparsity &s) const override { FluidCouplings(forms, s); }
  PetscErrorCode SetTime(PetscReal t) override { return forms.time = t, 0; }
  PetscErrorCode InitialState(DM dm, Vec x, PetscBool *set) override;

  std::vector<PetscInt> SplitFields() const override { return {velocity, pressure}; }

  void           Output(std::vector<OutputPart> &parts) const override;
  const char    *Headline(PetscInt *f) const override { return *f = velocity, "velocity"; }
  std::string    InvertedCause() const override;
  PetscErrorCode AfterStep(DM dm, PetscInt step, PetscReal t, Vec x) override;
  PetscErrorCode Results(DM dm, Vec x, PetscReal t, RunReport &report) override;

  PetscInt              velocity = -1, pressure = -1;
  FluidForms            forms;
  FlowMMS               flow;                                    /* the manufactured flow's data */
  std::vector<CellFace> inletFaces, outletFaces, interfaceFaces; /* the faces of the fluxes (empty: no such group) */
  Probes                probes;

private:
  const Scene         &sc;
  const GeometryBlock *geometry;
};

} // namespace fsi
