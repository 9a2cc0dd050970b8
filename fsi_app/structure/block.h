// SPDX-License-Identifier: BSD-2-Clause
/* The structure block: the wall's displacement d_s (P2) on its region, its material, loads and
   clamps, its rows R_s(d_s) (structure/assembly.h), GDSW's element subdomains and rigid-body
   modes, and its verification (Lame's cylinder, the manufactured solution). */
#pragma once

#include "scene.h"
#include "discretization/probes.h"
#include "solver/block.h"
#include "structure/assembly.h"

namespace fsi {

class StructureBlock : public Block {
public:
  explicit StructureBlock(const Scene &sc) : sc(sc) {}
  const char *Name() const override { return "structure"; }
  void        Groups(std::vector<GroupUse> &groups) const override;
  std::string Region() const override { return sc.region; }

  PetscErrorCode AddFields(DM dm) override;
  PetscErrorCode AddConditions(DM dm, Conditions &list) override;
  PetscErrorCode SetUp(DM dm) override;
  void           Attach(SNES snes, const TimeHistory *history) override { forms.snes = snes, forms.history = history; }

  PetscErrorCode Residual(const PetscScalar *x, PetscScalar *f) override { return StructureResidual(&forms, x, f); }
  PetscErrorCode Jacobian(const PetscScalar *x, Mat P) override { return StructureJacobian(&forms, x, P); }
  void           Couplings(Sparsity &s) const override { StructureCouplings(forms, s); }
  PetscErrorCode SetTime(PetscReal t) override;

  std::vector<PetscInt> SplitFields() const override { return {field}; }
  PetscBool             Linear() const override { return (PetscBool)(sc.material == LINEAR_ELASTIC && !sc.follower); }
  PetscBool             HasEnergy() const override { return PETSC_TRUE; }
  PetscErrorCode        ConfigurePC(DM dm, PC pc, MatNullSpace *nsp) override;
  SplitSetUp            SetUpPolicy() const override { return sc.pcSetUp >= 0 ? (SplitSetUp)sc.pcSetUp : Linear() ? SETUP_ONCE : SETUP_EVERY_STEP; }

  void           Output(std::vector<OutputPart> &parts) const override { parts.push_back({"wall", &forms.cells, {{"displacement", field}}}); }
  const char    *Headline(PetscInt *f) const override { return *f = field, "displacement"; }
  std::string    InvertedCause() const override;
  PetscErrorCode AfterStep(DM dm, PetscInt step, PetscReal t, Vec x) override;
  PetscErrorCode Results(DM dm, Vec x, PetscReal t, RunReport &report) override;

  PetscInt       field = -1; /* d_s */
  StructureForms forms;
  Probes         probes;

private:
  const Scene &sc;
};

/* The factor of every load (pressure, traction, body force) at time t (dynamics: the pulse and
   its ramp) or load fraction t (statics). */
PetscReal StructureLoadFactor(const Scene &sc, PetscReal t);

} // namespace fsi
