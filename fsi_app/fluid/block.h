// SPDX-License-Identifier: BSD-2-Clause
/* The fluid block: velocity u (P2) and pressure p (P1) on the fluid region, Navier-Stokes in
   ALE form on the mesh moved by the geometry block's d_f (or on the fixed mesh), its no-slip
   groups, inflow velocity or traction, its outlets (traction-free, or the outlets block's 0D
   models) with backflow damped, and the exact data of the verification flows
   (Poiseuille, the manufactured flows of verification/mms.h); it reports the fluxes through
   the inlet and outlet, the wall shear stress, its time average and oscillatory index
   (fluid/wall_shear.h), the errors of the verification flows, and on a mesh moved by a
   coupled wall its volume balance (fluid/balance.h). */
#pragma once

#include "fluid/assembly.h"
#include "fluid/balance.h"
#include "fluid/inflow.h"
#include "fluid/wall_shear.h"
#include "base/waveform.h"
#include "discretization/probes.h"
#include "verification/mms.h"
#include "core/scene.h"
#include "core/block.h"

namespace fsi {

/* The inlet pressure over time: on at once, or one smooth hump p (1 - cos(2 pi t / T)) / 2 over
   [0, T] (T = -fluid_inlet_pressure_until; no jump, so the time schemes keep their order). */
enum PulseShape { PULSE_STEP = 0, PULSE_COSINE = 1 };
extern const char *const PulseShapeNames[];

/* The fluid's options (-fluid_*; ReadOptions lists them with their defaults). */
struct FluidOptions {
  char      region[64] = "fluid";
  char      noslip[256] = "interface";     /* groups with u = 0 */
  PetscReal rho = 1.0, mu = 0.03;          /* g/cm^3, poise */
  PetscReal inletPressure = 0;             /* normal stress -p n on the inlet group (dyn/cm^2) */
  PetscReal pulseEnd = 0;                  /* it acts while t <= pulseEnd (0: always) */
  PulseShape pulseShape = PULSE_STEP;
  char                   pressureWaveform[PETSC_MAX_PATH_LEN] = ""; /* or p(t) from samples of one period */
  std::vector<PetscReal> pressureFourier;                          /* or p(t) as a Fourier series T,a0,a1,b1,... */
  char                   flowWaveform[PETSC_MAX_PATH_LEN] = ""; /* or a flow rate Q(t) from samples of one period */
  std::vector<PetscReal> flowFourier;                          /* or Q(t) as a Fourier series */
  InflowProfileKind      profile  = INFLOW_PARABOLIC;          /* the flow rate's velocity profile */
  PetscReal              flowRamp = 0;                         /* Q rises over this time */
  PetscBool              womersley = PETSC_FALSE;              /* verification: errors against Womersley's flow */
  PetscReal inflowVelocity[3] = {0, 0, 0}; /* or a prescribed velocity there (cm/s) */
  PetscBool inflow = PETSC_FALSE;
  char      inlet[64] = "inlet", outlet[256] = "outlet"; /* outlets: groups, comma separated */
  PetscReal backflow = 0.2;                /* beta of the backflow term on the outlets */
  PetscBool shapeDerivatives = PETSC_TRUE; /* on a moving mesh the Jacobian holds D_{d_f} R (exact Newton) */
  PetscInt  pcSetUp          = SETUP_EVERY_NEWTON; /* its split's preconditioner rebuilt every Newton step or every time step (SplitSetUp) */
  PetscInt  pcSetUpInterval  = 1;                  /* every_step: rebuilt at every this many time steps */
  std::vector<PetscReal> probes;           /* points (3 each) where the pressure is recorded */
  PetscReal   shearFrom = 0;               /* the wall shear stress's time average and OSI from this time */
  PetscReal   poiseuille[3] = {0, 0, 0};   /* verification: R, L, pressure drop */
  FlowMMSKind mmsFlow = FLOW_MMS_TRIGONOMETRIC;
  PetscReal   mmsRamp = 0;
};

class FluidBlock : public Block {
public:
  explicit FluidBlock(const Scene &sc) : sc(sc) {}
  const char    *Name() const override { return "fluid"; }
  SplitSetUp     SetUpPolicy() const override { return (SplitSetUp)opt.pcSetUp; }
  PetscInt       SetUpInterval() const override { return opt.pcSetUpInterval; }
  PetscErrorCode Wire(const std::vector<Block *> &scene) override;
  PetscErrorCode ReadOptions(std::map<std::string, std::string> &problem) override;
  PetscErrorCode Check() const override;
  void           Groups(std::vector<GroupUse> &groups) const override;
  std::string       Group(const std::string &role) const override;
  PetscInt          Field(const std::string &name) const override { return name == "velocity" ? velocity : name == "pressure" ? pressure : -1; }
  const FieldCells *Cells(const std::string &name) const override { return name == "velocity" ? &forms.velocity : name == "pressure" ? &forms.pressure : nullptr; }

  PetscErrorCode AddFields(DM dm) override;
  PetscErrorCode AddConditions(DM dm, Conditions &list) override;
  PetscErrorCode SetUp(DM dm) override;
  void           Attach(SNES snes, const TimeHistory *history) override { forms.snes = snes, forms.history = history; }

  PetscErrorCode Residual(const PetscScalar *x, PetscScalar *f) override { return FluidResidual(forms, x, f); }
  PetscErrorCode Jacobian(const PetscScalar *x, Mat P) override { return FluidJacobian(forms, x, P); }
  void           Couplings(Sparsity &s) const override { FluidCouplings(forms, s); }
  PetscErrorCode SetTime(PetscReal t) override { return forms.time = t, 0; }
  PetscErrorCode InitialState(DM dm, Vec x, PetscBool *set) override;

  std::vector<PetscInt> SplitFields() const override { return {velocity, pressure}; }
  PetscInt              SplitPlace() const override { return 2; } /* after the wall and the mesh that moves it */

  void           Output(std::vector<OutputPart> &parts) const override;
  void           Unknowns(std::vector<std::pair<std::string, PetscInt>> &u) const override { u.insert(u.end(), {{"fluid", velocity}, {"pressure", pressure}}); }
  PetscBool      Summary(Headline *h) const override { return *h = {"velocity", velocity, "solution_norm", PETSC_TRUE}, PETSC_TRUE; }
  std::string    InvertedCause() const override;
  PetscErrorCode AfterStep(DM dm, PetscInt step, PetscReal t, Vec x) override;
  std::vector<PetscReal> *RunningSums() override { return Walls().empty() ? nullptr : &shear.sums; }
  PetscErrorCode Results(DM dm, Vec x, PetscReal t, RunReport &report) override;

private:
  const Scene          &sc;
  FluidOptions          opt;
  PetscInt              velocity = -1, pressure = -1;
  FluidForms            forms;
  FlowMMS               flow;                    /* the manufactured flow's data */
  std::vector<CellFace> inletFaces, outletFaces; /* the faces of the fluxes (empty: no such group), every outlet's */
  std::vector<std::vector<CellFace>> outletsFaces; /* each outlet's, when there are several */
  Probes                probes;
  const Block          *mesh    = nullptr;      /* the geometry block, whose d_f moves the mesh (nullptr: a fixed mesh) */
  PetscBool             coupled = PETSC_FALSE;  /* the mesh moves with a coupled wall */
  VolumeBalance         balance;                /* coupled: the volume balance */
  Waveform              inletPressure;          /* p(t) of -fluid_inlet_pressure_waveform or _fourier (period 0: neither) */
  InflowProfile         inflow;                 /* the flow rate Q(t) of -fluid_inflow_waveform or _fourier (period 0: neither) */
  Womersley             exact;                  /* -womersley: the exact flow */
  std::vector<PetscReal> womersleyErrors;       /* -womersley: per step t, the velocity's and the WSS's errors and the exact norms */
  WallShear             shear;                  /* on the no-slip faces and the interface */
  std::vector<std::pair<std::string, std::vector<CellFace>>> boundaries; /* each inlet, outlet and wall group: its flow and mean pressure per step */
  PetscInt              firstStep = -1;         /* of this run (a restart's is > 1) */

  std::string    Walls() const;                 /* the groups of the wall shear stress */
  PetscErrorCode RecordBoundaries(DM dm, PetscInt step, PetscReal t, Vec x);
};

} // namespace fsi
