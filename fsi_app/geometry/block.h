// SPDX-License-Identifier: BSD-2-Clause
/* The geometry block: the fluid's mesh displacement d_f (P2) on the fluid region, the harmonic
   extension of the interface displacement (geometry/harmonic.h), d_f . n = 0 on the planar ends
   (-geometry_slip). On the interface, d_f is either prescribed (PrescribedMotion: the block
   verified alone, or a fluid on a mesh moved by a given wall) or coupled to the structure: then
   its interface rows belong to the coupling block (d_f - d_s = 0) and it leaves them out. */
#pragma once

#include "geometry/harmonic.h"
#include "geometry/predictor.h"
#include "scene.h"
#include "solver/block.h"
#include "verification/mms.h"

namespace fsi {

class GeometryBlock : public Block {
public:
  /* coupled: the interface rows are the coupling's; movesFluid: a fluid block moves with it */
  GeometryBlock(const Scene &sc, PetscBool coupled, PetscBool movesFluid) : sc(sc), coupled(coupled), movesFluid(movesFluid) {}
  ~GeometryBlock() override { GeometryPredictorDestroy(predictor); }
  const char *Name() const override { return "geometry"; }
  void        Groups(std::vector<GroupUse> &groups) const override;
  std::string Region() const override { return sc.fluidRegion; }
  PetscBool   Coupled() const { return coupled; }

  PetscErrorCode AddFields(DM dm) override;
  PetscErrorCode AddConditions(DM dm, Conditions &list) override;
  PetscErrorCode SetUp(DM dm) override;

  PetscErrorCode Residual(const PetscScalar *x, PetscScalar *f) override { return GeometryResidual(&forms, x, f); }
  PetscErrorCode Jacobian(const PetscScalar *x, Mat P) override { return GeometryJacobian(&forms, x, P); }
  void           Couplings(Sparsity &s) const override { GeometryCouplings(forms, s); }
  /* the harmonic extension's operator lives on the reference mesh: its split's PC is built once */
  SplitSetUp     SetUpPolicy() const override { return SETUP_ONCE; }
  PetscErrorCode Predict(PetscReal t, Vec x) override;

  std::vector<PetscInt> SplitFields() const override { return {field}; }
  PetscBool             Linear() const override { return PETSC_TRUE; }
  PetscBool             HasEnergy() const override { return PETSC_TRUE; }

  void           Output(std::vector<OutputPart> &parts) const override;
  const char    *Headline(PetscInt *f) const override { return *f = field, "displacement"; }
  PetscErrorCode Results(DM dm, Vec x, PetscReal t, RunReport &report) override;

  PetscInt         field = -1; /* d_f */
  GeometryForms    forms;
  PrescribedMotion motion;     /* the interface displacement when it is prescribed */

private:
  const Scene      &sc;
  PetscBool         coupled, movesFluid;
  GeometryPredictor predictor; /* a fluid on a prescribed moving mesh: the step's mesh motion first */
};

} // namespace fsi
