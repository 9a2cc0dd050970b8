// SPDX-License-Identifier: BSD-2-Clause
/* A scene: every application option, read once, checked, with its default (-help lists them). */
#pragma once

#include "discretization/fields.h"
#include "solver/time_history.h"
#include "structure/materials.h"
#include "verification/mms.h"
#include <map>
#include <string>
#include <vector>

namespace fsi {

enum Physics { PHYSICS_STRUCTURE = 0, PHYSICS_FLUID = 1, PHYSICS_GEOMETRY = 2, PHYSICS_FSI = 3 };
extern const char *const PhysicsNames[];

struct Scene {
  Physics                  physics = PHYSICS_STRUCTURE; /* shorthand for a list of blocks */
  std::vector<std::string> blocks;                      /* the blocks a scene solves (blocks.h) */
  /* mesh */
  char     mesh[PETSC_MAX_PATH_LEN] = "meshes/cube_L0.msh";
  PetscInt refine                   = 0;
  /* structure */
  char      region[64] = "";  /* group of the structure's cells ("" all) */
  char      clamp[256] = "";  /* groups with d = 0 (group:xz fixes components) */
  PetscReal pressure   = 0;   /* on the faces of group `loaded` */
  char      loaded[64] = "interface";
  PetscBool follower   = PETSC_FALSE;
  PetscReal bodyForce[3] = {0, 0, 0};         /* per unit reference volume (dyn/cm^3) */
  PetscReal traction[3]  = {0, 0, 0};         /* dead traction per unit reference area (dyn/cm^2) */
  char      tractionGroup[64] = "";
  PetscReal pulseEnd   = 0;   /* the pressure acts for t <= pulseEnd (0: always) */
  PetscReal ramp       = 0;   /* the pressure rises as sin^2(pi t / 2 ramp) until t = ramp (0: at once) */
  Material  material   = LINEAR_ELASTIC;
  PetscReal E = 1.0, nu = 0.3;                            /* linear elastic */
  PetscReal mu = 7.72e4, kappa = 3.833e6;                 /* Neo-Hooke (dyn/cm^2) */
  PetscReal arterial[5] = {1.75e5, 4.998e6, 2.4, 3.00019e8, 5.1}; /* c1, eps1, eps2, alpha1, alpha2 */
  PetscReal fibreAngle  = 43.39;                          /* degrees from circumferential */
  PetscReal rho         = 1.2;
  PetscInt  degree = 2, subdomains = 1;
  PetscInt  pcSetUp = -1; /* its split's preconditioner rebuilt every Newton step, time step, once (SplitSetUp); -1: once if linear, else every time step */
  std::vector<PetscReal> structureProbes;             /* points (3 each) where the displacement is recorded */
  /* fluid */
  char      fluidRegion[64] = "fluid";
  char      noslip[256]     = "interface"; /* groups with u = 0 */
  PetscReal rhoFluid = 1.0, muFluid = 0.03; /* g/cm^3, poise */
  PetscReal inletPressure = 0;              /* normal stress -p n on the inlet group (dyn/cm^2) */
  PetscReal inflowVelocity[3] = {0, 0, 0};  /* or a prescribed velocity there (cm/s) */
  PetscBool inflow = PETSC_FALSE;
  char      inlet[64] = "inlet", outlet[64] = "outlet";
  PetscReal poiseuille[3] = {0, 0, 0};      /* verification: R, L, pressure drop */
  std::vector<PetscReal> fluidProbes;       /* points (3 each) where the pressure is recorded */
  /* geometry (harmonic extension) */
  char      interface[64]      = "interface";
  char      slip[256]          = "inlet:z,outlet:z"; /* d . n = 0: the normal component of planar ends */
  PetscReal geometryAmplitude  = 0.01;               /* of the prescribed interface displacement */
  PetscReal geometryRamp       = 0;                  /* it rises smoothly over this time (0: at once) */
  PetscBool movingMesh         = PETSC_FALSE;        /* -physics fluid: the mesh moves (ALE) with the geometry block */
  PetscBool shapeDerivatives   = PETSC_TRUE;         /* the fluid's Jacobian holds D_{d_f} R (exact Newton) */
  /* time, or load increments in statics */
  PetscReal  dt = 0, tFinal = 0.01;
  PetscInt   loadSteps = 1, maxCuts = 4;
  TimeScheme scheme    = BACKWARD_EULER;
  /* verification */
  PetscBool   mms          = PETSC_FALSE;
  PetscReal   mmsAmplitude = 1;
  FlowMMSKind mmsFlow      = FLOW_MMS_TRIGONOMETRIC;
  PetscReal   mmsRamp      = 0;
  PetscReal lameRadii[2] = {0, 0};
  /* files */
  char     output[PETSC_MAX_PATH_LEN] = "", checkpoint[PETSC_MAX_PATH_LEN] = "", restart[PETSC_MAX_PATH_LEN] = "", report[PETSC_MAX_PATH_LEN] = "";
  PetscInt outputEvery = 1, checkpointEvery = 10;
  /* the options that define the problem, with their values: a restart must have the same */
  std::map<std::string, std::string> problem;

  PetscBool Dynamic() const { return (PetscBool)(dt > 0); }
  PetscInt  Steps() const { return Dynamic() ? (PetscInt)PetscFloorReal(tFinal / dt + 0.5) : loadSteps; } /* ReadScene checked: a whole number */
};

PetscErrorCode ReadScene(Scene &sc);

/* sin^2(pi t / 2T) for t < T, then 1 (T = 0: 1 at once); its rate d/dt if asked. */
PetscReal SmoothRamp(PetscReal t, PetscReal T, PetscReal *rate = nullptr);

} // namespace fsi
