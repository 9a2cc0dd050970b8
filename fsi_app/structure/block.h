// SPDX-License-Identifier: BSD-2-Clause
/* The structure block: the wall's displacement d_s (P2) on its region, its material, loads and
   clamps, the tissue support, its rows R_s(d_s) (structure/assembly.h), GDSW's element subdomains and rigid-body
   modes, and its verification (Lame's cylinder, free or held by a spring; the manufactured solution). */
#pragma once

#include "core/scene.h"
#include "discretization/probes.h"
#include "core/block.h"
#include "structure/assembly.h"
#include "structure/materials.h"

namespace fsi {

/* The structure's options (-structure_*; ReadOptions lists them with their defaults). */
struct StructureOptions {
  char      region[64] = "";  /* group of the structure's cells ("" all) */
  char      clamp[256] = "";  /* groups with d = 0 (group:xz fixes components) */
  PetscReal pressure   = 0;   /* on the faces of group `loaded` */
  char      loaded[64] = "interface";
  PetscBool follower   = PETSC_FALSE;
  PetscReal bodyForce[3] = {0, 0, 0};         /* per unit reference volume (dyn/cm^3) */
  PetscReal traction[3]  = {0, 0, 0};         /* dead traction per unit reference area (dyn/cm^2) */
  char      tractionGroup[64] = "";
  PetscReal support[2] = {0, 0};          /* k_s, c_s of the tissue support */
  char      supportGroup[64] = "outer_wall";
  PetscBool supportNormal = PETSC_FALSE;  /* on d . n only */
  PetscReal pulseEnd   = 0;   /* the pressure acts for t <= pulseEnd (0: always) */
  PetscReal ramp       = 0;   /* the pressure rises as sin^2(pi t / 2 ramp) until t = ramp (0: at once) */
  Material  material   = LINEAR_ELASTIC;
  PetscReal E = 1.0, nu = 0.3;                            /* linear elastic */
  PetscReal mu = 7.72e4, kappa = 3.833e6;                 /* Neo-Hooke (dyn/cm^2) */
  PetscReal arterial[5] = {1.75e5, 4.998e6, 2.4, 3.00019e8, 5.1}; /* c1, eps1, eps2, alpha1, alpha2 */
  PetscReal fibreAngle  = 43.39;                          /* degrees from circumferential */
  char      centerline[PETSC_MAX_PATH_LEN] = "";          /* the fibres' frame from this centreline ("": about the z-axis) */
  PetscBool frameCheck = PETSC_FALSE;                     /* report the frame's deviation from the z-axis frame */
  PetscReal rho         = 1.2;
  PetscInt  subdomains = 1;
  PetscInt  pcSetUp = -1; /* its split's preconditioner rebuilt every Newton step, time step, once (SplitSetUp); -1: once if linear, else every time step */
  PetscInt  pcSetUpInterval = 1; /* every_step: rebuilt at every this many time steps */
  std::vector<PetscReal> probes;  /* points (3 each) where the displacement is recorded */
  PetscReal mmsAmplitude = 1;     /* -mms: the manufactured displacement's amplitude */
  PetscReal lameRadii[2] = {0, 0}; /* verification against Lame's cylinder */
};

class StructureBlock : public Block {
public:
  explicit StructureBlock(const Scene &sc) : sc(sc) {}
  const char    *Name() const override { return "structure"; }
  PetscErrorCode ReadOptions(std::map<std::string, std::string> &problem) override;
  void           Groups(std::vector<GroupUse> &groups) const override;
  std::string       Group(const std::string &role) const override { return role == "region" ? opt.region : ""; }
  PetscInt          Field(const std::string &name) const override { return name == "displacement" ? field : -1; }
  const FieldCells *Cells(const std::string &name) const override { return name == "displacement" ? &forms.cells : nullptr; }

  PetscErrorCode AddFields(DM dm) override;
  PetscErrorCode AddConditions(DM dm, Conditions &list) override;
  PetscErrorCode SetUp(DM dm) override;
  void           Attach(SNES snes, const TimeHistory *history) override { forms.snes = snes, forms.history = history; }

  PetscErrorCode Residual(const PetscScalar *x, PetscScalar *f) override { return StructureResidual(forms, x, f); }
  PetscErrorCode Jacobian(const PetscScalar *x, Mat P) override { return StructureJacobian(forms, x, P); }
  void           Couplings(Sparsity &s) const override { StructureCouplings(forms, s); }
  PetscErrorCode SetTime(PetscReal t) override;

  std::vector<PetscInt> SplitFields() const override { return {field}; }
  PetscInt              SplitPlace() const override { return 0; } /* FaCSI: the wall first, then the mesh, then the fluid */
  PetscBool             Linear() const override { return (PetscBool)(opt.material == LINEAR_ELASTIC && !opt.follower); }
  PetscBool             HasEnergy() const override { return PETSC_TRUE; }
  PetscErrorCode        ConfigurePC(DM dm, PC pc, MatNullSpace *nsp) override;
  SplitSetUp            SetUpPolicy() const override { return opt.pcSetUp >= 0 ? (SplitSetUp)opt.pcSetUp : Linear() ? SETUP_ONCE : SETUP_EVERY_STEP; }
  PetscInt              SetUpInterval() const override { return opt.pcSetUpInterval; }

  void           Output(std::vector<OutputPart> &parts) const override;
  void           Unknowns(std::vector<std::pair<std::string, PetscInt>> &u) const override { u.push_back({"structure", field}); }
  PetscBool      Summary(Headline *h) const override { return *h = {"displacement", field, "displacement_norm"}, PETSC_TRUE; }
  std::string    InvertedCause() const override;
  PetscErrorCode AfterStep(DM dm, PetscInt step, PetscReal t, Vec x) override;
  PetscErrorCode Results(DM dm, Vec x, PetscReal t, RunReport &report) override;

private:
  const Scene     &sc;
  StructureOptions opt;
  PetscInt         field = -1; /* d_s */
  StructureForms   forms;
  Probes           probes;

  /* The factor of every load (pressure, traction, body force) at time t (dynamics: the pulse
     and its ramp) or load fraction t (statics). */
  PetscReal LoadFactor(PetscReal t) const;
  bool      Supported() const { return opt.support[0] > 0 || opt.support[1] > 0; }
  PetscErrorCode SetUpFrame(DM dm);
  Centerline     centerline;               /* -structure_centerline */
  PetscReal      frameDeviation[2] = {0, 0}; /* -structure_frame_check_z_axis: largest |e_a - e_z|, |e_c - e_theta| */
  std::vector<PetscReal> fibres[2];          /* the arterial law's fibre families at the wall's nodes (3 per mesh point), for the output */
  void           NodeFibres();
};

} // namespace fsi
