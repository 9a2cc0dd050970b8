// SPDX-License-Identifier: BSD-2-Clause
/* The two configurations of PCGDSW, robust and fast: one switch for the local solvers and the
   coarse space together. Each public function with its manual page calls the method of the same
   name composed on the PC, which holds its body just above it. */
#include "gdswimpl.h"

const char *const PCGDSWConfigurations[] = {"robust", "fast", "PCGDSWConfiguration", "PC_GDSW_CONFIGURATION_", nullptr};

static PetscErrorCode PCGDSWSetConfiguration_GDSW(PC pc, PCGDSWConfiguration c)
{
  PC_GDSW  *gd   = (PC_GDSW *)pc->data;
  PetscBool fast = (PetscBool)(c == PC_GDSW_CONFIGURATION_FAST);

  PetscFunctionBegin;
  PetscCall(GDSWCheckEnum(pc, (PetscEnum)c, (PetscEnum)PC_GDSW_CONFIGURATION_FAST, PCGDSWConfigurations));
  gd->configuration = c;
  PetscCall(PCGDSWSetLocalSolverType(pc, fast ? PC_GDSW_LOCAL_ADAPTIVE : PC_GDSW_LOCAL_EXACT));
  PetscCall(PCGDSWSetCoarseSpaceType(pc, fast ? PC_GDSW_COARSE_RGDSW : PC_GDSW_COARSE_GDSW));
  PetscFunctionReturn(0);
}

/*@
   PCGDSWSetConfiguration - Sets `PCGDSW`'s local solvers and coarse space together: the robust
   configuration (the default) or the fast one

   Logically Collective on pc

   Input Parameters:
+  pc - the preconditioner context
-  configuration - `PC_GDSW_CONFIGURATION_ROBUST` (exact local solvers, GDSW coarse space) or
                   `PC_GDSW_CONFIGURATION_FAST` (adaptive local solvers, RGDSW coarse space)

   Options Database Key:
.  -pc_gdsw_configuration <robust,fast> - sets the configuration

   Notes:
   The configuration sets `PCGDSWSetLocalSolverType()` and `PCGDSWSetCoarseSpaceType()`; with the
   options database, -pc_gdsw_local_solver and -pc_gdsw_coarse_space, when given, override it.
   The size rule then aims at 3000 dofs per subdomain for the fast configuration's adaptive local
   solvers and at 12000 for the robust one's exact factors (`PCGDSWSetSubdomainSize()`).

   The robust configuration is the method that holds on thin plates, coefficient jumps, nearly
   incompressible elasticity and the P2 walls of fluid-structure interaction. The fast one costs
   0.9-1.9 times the best algebraic multigrid of PETSc on homogeneous 3D elasticity (the robust
   one 1.5-4.1 times) and gives up robustness. CG iterations to 1e-8 on 2 ranks, robust against
   fast: homogeneous Q1 elasticity 38 against 62, Young's modulus jumping by 1e6 40 against 95,
   nu = 0.4999 134 against 301, ksp ex56's soft inclusion on 8 ranks 32 against 70.
   Use the fast one where the operator is close to homogeneous compressible elasticity.

   Level: beginner

.seealso: `PCGDSW`, `PCGDSWConfiguration`, `PCGDSWGetConfiguration()`, `PCGDSWSetLocalSolverType()`, `PCGDSWSetCoarseSpaceType()`
@*/
PetscErrorCode PCGDSWSetConfiguration(PC pc, PCGDSWConfiguration configuration)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidLogicalCollectiveEnum(pc, configuration, 2);
  PetscTryMethod(pc, "PCGDSWSetConfiguration_C", (PC, PCGDSWConfiguration), (pc, configuration));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetConfiguration_GDSW(PC pc, PCGDSWConfiguration *c)
{
  PetscFunctionBegin;
  *c = ((PC_GDSW *)pc->data)->configuration;
  PetscFunctionReturn(0);
}

/*@
   PCGDSWGetConfiguration - Gets the configuration last set with `PCGDSWSetConfiguration()`

   Not Collective

   Input Parameter:
.  pc - the preconditioner context

   Output Parameter:
.  configuration - the configuration

   Note:
   The local solvers and the coarse space may have been changed since (`PCGDSWGetLocalSolverType()`,
   `PCGDSWGetCoarseSpaceType()`); -ksp_view shows what is used.

   Level: beginner

.seealso: `PCGDSW`, `PCGDSWSetConfiguration()`
@*/
PetscErrorCode PCGDSWGetConfiguration(PC pc, PCGDSWConfiguration *configuration)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscAssertPointer(configuration, 2);
  PetscUseMethod(pc, "PCGDSWGetConfiguration_C", (PC, PCGDSWConfiguration *), (pc, configuration));
  PetscFunctionReturn(0);
}

/* The composed methods of the configuration: added by PCCreate_GDSW(), removed by PCDestroy_GDSW(). */
PetscErrorCode GDSWComposeConfigurationMethods(PC pc, PetscBool add)
{
  PetscObject o = (PetscObject)pc;

  PetscFunctionBegin;
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWSetConfiguration_C", add ? PCGDSWSetConfiguration_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetConfiguration_C", add ? PCGDSWGetConfiguration_GDSW : nullptr));
  PetscFunctionReturn(0);
}
