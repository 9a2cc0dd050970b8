// SPDX-License-Identifier: BSD-2-Clause
/* The geometry block: the fluid's mesh displacement d_f (P2) on the fluid region, the harmonic
   extension of the interface displacement (geometry/harmonic.h), d_f . n = 0 on the planar ends
   (-geometry_slip). On the interface, d_f is either prescribed (PrescribedMotion: the block
   verified alone, or a fluid on a mesh moved by a given wall) or coupled to the structure: then
   its interface rows belong to the coupling block (d_f - d_s = 0) and it leaves them out. */
#pragma once

#include "geometry/harmonic.h"
#include "geometry/predictor.h"
#include "core/scene.h"
#include "core/block.h"
#include "verification/mms.h"

namespace fsi {

/* The geometry's options (-geometry_*). It lives on the fluid's cells: -fluid_region, the fluid
   block's when the scene has one. */
struct GeometryOptions {
  char      region[64]    = "fluid";
  char      interface[64] = "interface";
  char      slip[256]     = "inlet:z,outlet:z"; /* d . n = 0: the normal component of planar ends */
  PetscReal amplitude     = 0.01;               /* of the prescribed interface displacement */
  PetscReal ramp          = 0;                  /* it rises smoothly over this time (0: at once) */
};

class GeometryBlock : public Block {
public:
  explicit GeometryBlock(const Scene &sc) : sc(sc) {}
  ~GeometryBlock() override { GeometryPredictorDestroy(predictor); }
  const char    *Name() const override { return "geometry"; }
  PetscErrorCode Wire(const std::vector<Block *> &scene) override;
  PetscErrorCode ReadOptions(std::map<std::string, std::string> &problem) override;
  void           Groups(std::vector<GroupUse> &groups) const override;
  std::string             Group(const std::string &role) const override;
  PetscInt                Field(const std::string &name) const override { return name == "geometry" ? field : -1; }
  const FieldCells       *Cells(const std::string &name) const override { return name == "geometry" ? &forms.cells : nullptr; }
  const PrescribedMotion *Motion() const override { return coupled ? nullptr : &motion; }

  PetscErrorCode AddFields(DM dm) override;
  PetscErrorCode AddConditions(DM dm, Conditions &list) override;
  PetscErrorCode SetUp(DM dm) override;

  PetscErrorCode Residual(const PetscScalar *x, PetscScalar *f) override { return GeometryResidual(forms, x, f); }
  PetscErrorCode Jacobian(const PetscScalar *x, Mat P) override { return GeometryJacobian(forms, x, P); }
  void           Couplings(Sparsity &s) const override { GeometryCouplings(forms, s); }
  /* the harmonic extension's operator lives on the reference mesh: its split's PC is built once */
  SplitSetUp     SetUpPolicy() const override { return SETUP_ONCE; }
  PetscErrorCode Predict(PetscReal t, Vec x) override;

  std::vector<PetscInt> SplitFields() const override { return {field}; }
  PetscInt              SplitPlace() const override { return 1; } /* the mesh follows the wall, the fluid the mesh */
  PetscBool             Linear() const override { return PETSC_TRUE; }
  PetscBool             ConstantJacobian() const override { return PETSC_TRUE; }
  PetscBool             HasEnergy() const override { return PETSC_TRUE; }

  void           Output(std::vector<OutputPart> &parts) const override;
  void           Unknowns(std::vector<std::pair<std::string, PetscInt>> &u) const override { u.push_back({"geometry", field}); }
  PetscBool      Summary(Headline *h) const override { return *h = {"displacement", field, "displacement_norm"}, PETSC_TRUE; }
  PetscErrorCode Results(DM dm, Vec x, PetscReal t, RunReport &report) override;

private:
  const Scene      &sc;
  GeometryOptions   opt;
  PetscInt          field = -1; /* d_f */
  GeometryForms     forms;
  PrescribedMotion  motion; /* the interface displacement when it is prescribed */
  PetscBool         coupled = PETSC_FALSE, movesFluid = PETSC_FALSE; /* movesFluid: a fluid block moves with it */
  const Block      *fluid   = nullptr;
  GeometryPredictor predictor; /* a fluid on a prescribed moving mesh: the step's mesh motion first */
};

} // namespace fsi
