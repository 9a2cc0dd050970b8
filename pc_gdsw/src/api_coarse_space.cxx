// SPDX-License-Identifier: BSD-2-Clause
/* The coarse space of PCGDSW and how its correction combines with the first level's: the type,
   RGDSW's partition of unity, the rotations, the kept basis, and the getters of Phi, A_0, the
   coarse solver and the interface counts. Each public function with its manual page calls the
   method of the same name composed on the PC, which holds its body just above it. */
#include "gdswimpl.h"

static PetscErrorCode PCGDSWSetCoarseSpaceType_GDSW(PC pc, PCGDSWCoarseSpaceType t)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCall(GDSWCheckEnum(pc, (PetscEnum)t, (PetscEnum)PC_GDSW_COARSE_NONE, PCGDSWCoarseSpaceTypes));
  if (t != gd->coarseType) pc->setupcalled = 0;
  gd->coarseType = t;
  PetscFunctionReturn(0);
}

/*@
   PCGDSWSetCoarseSpaceType - Sets the coarse space of `PCGDSW`

   Logically Collective on pc

   Input Parameters:
+  pc - the preconditioner context
-  type - `PC_GDSW_COARSE_GDSW` (the default: the null space on every face, edge and vertex), `PC_GDSW_COARSE_RGDSW` (reduced dimension: the null space on the coarse nodes, spread by a partition of unity) or `PC_GDSW_COARSE_NONE` (one-level Schwarz)

   Options Database Key:
.  -pc_gdsw_coarse_space <gdsw,rgdsw,none> - sets the type

   Note:
   A new value makes the next `PCSetUp()` rebuild the preconditioner.

   Level: intermediate

.seealso: `PCGDSW`, `PCGDSWCoarseSpaceType`, `PCGDSWGetCoarseSpaceType()`, `PCGDSWSetRGDSWWeightType()`, `PCGDSWSetRotations()`
@*/
PetscErrorCode PCGDSWSetCoarseSpaceType(PC pc, PCGDSWCoarseSpaceType type)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidLogicalCollectiveEnum(pc, type, 2);
  PetscTryMethod(pc, "PCGDSWSetCoarseSpaceType_C", (PC, PCGDSWCoarseSpaceType), (pc, type));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetCoarseSpaceType_GDSW(PC pc, PCGDSWCoarseSpaceType *t)
{
  PetscFunctionBegin;
  *t = ((PC_GDSW *)pc->data)->coarseType;
  PetscFunctionReturn(0);
}

/*@
   PCGDSWGetCoarseSpaceType - Gets the coarse space of `PCGDSW`

   Not Collective

   Input Parameter:
.  pc - the preconditioner context

   Output Parameter:
.  type - the coarse space

   Level: intermediate

.seealso: `PCGDSW`, `PCGDSWSetCoarseSpaceType()`
@*/
PetscErrorCode PCGDSWGetCoarseSpaceType(PC pc, PCGDSWCoarseSpaceType *type)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscAssertPointer(type, 2);
  PetscUseMethod(pc, "PCGDSWGetCoarseSpaceType_C", (PC, PCGDSWCoarseSpaceType *), (pc, type));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetRGDSWWeightType_GDSW(PC pc, PCGDSWRGDSWWeightType t)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCall(GDSWCheckEnum(pc, (PetscEnum)t, (PetscEnum)PC_GDSW_RGDSW_WEIGHTS_DISTANCE, PCGDSWRGDSWWeightTypes));
  if (t != gd->rgdswWeights) pc->setupcalled = 0;
  gd->rgdswWeights = t;
  PetscFunctionReturn(0);
}

/*@
   PCGDSWSetRGDSWWeightType - Sets the partition of unity of the RGDSW coarse space of `PCGDSW` on an interface component shared by several coarse nodes

   Logically Collective on pc

   Input Parameters:
+  pc - the preconditioner context
-  type - `PC_GDSW_RGDSW_WEIGHTS_DISTANCE` (the default; option 2.2 of Dohrmann and Widlund: shares proportional to 1 / distance to each coarse node's centroid) or `PC_GDSW_RGDSW_WEIGHTS_EQUAL` (option 1: equal shares)

   Options Database Key:
.  -pc_gdsw_rgdsw_weights <distance,equal> - sets the type

   Notes:
   The distances are measured between the coordinates from which the rigid-body modes are built, so the distance weights need `PCSetCoordinates()` and no near-null space on the operator (`MatSetNearNullSpace()`), with rotations on.
   Otherwise RGDSW uses equal shares, and `-ksp_view` says so.
   A new value makes the next `PCSetUp()` rebuild the preconditioner.

   Level: advanced

.seealso: `PCGDSW`, `PCGDSWRGDSWWeightType`, `PCGDSWGetRGDSWWeightType()`, `PCGDSWSetCoarseSpaceType()`, `PCSetCoordinates()`
@*/
PetscErrorCode PCGDSWSetRGDSWWeightType(PC pc, PCGDSWRGDSWWeightType type)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidLogicalCollectiveEnum(pc, type, 2);
  PetscTryMethod(pc, "PCGDSWSetRGDSWWeightType_C", (PC, PCGDSWRGDSWWeightType), (pc, type));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetRGDSWWeightType_GDSW(PC pc, PCGDSWRGDSWWeightType *t)
{
  PetscFunctionBegin;
  *t = ((PC_GDSW *)pc->data)->rgdswWeights;
  PetscFunctionReturn(0);
}

/*@
   PCGDSWGetRGDSWWeightType - Gets the requested partition of unity of the RGDSW coarse space of `PCGDSW`

   Not Collective

   Input Parameter:
.  pc - the preconditioner context

   Output Parameter:
.  type - the partition of unity requested (see `PCGDSWSetRGDSWWeightType()` for when equal shares replace the distance weights)

   Level: advanced

.seealso: `PCGDSW`, `PCGDSWSetRGDSWWeightType()`
@*/
PetscErrorCode PCGDSWGetRGDSWWeightType(PC pc, PCGDSWRGDSWWeightType *type)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscAssertPointer(type, 2);
  PetscUseMethod(pc, "PCGDSWGetRGDSWWeightType_C", (PC, PCGDSWRGDSWWeightType *), (pc, type));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetRotations_GDSW(PC pc, PetscBool flg)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  if (flg != gd->rotations) pc->setupcalled = 0;
  gd->rotations = flg;
  PetscFunctionReturn(0);
}

/*@
   PCGDSWSetRotations - Sets whether the coarse space of `PCGDSW` uses the rotations of the null space

   Logically Collective on pc

   Input Parameters:
+  pc - the preconditioner context
-  flg - `PETSC_TRUE` (the default) for the whole null space, `PETSC_FALSE` for translations only (GDSW-nr)

   Options Database Key:
.  -pc_gdsw_rotations <true,false> - sets the flag

   Note:
   A new value makes the next `PCSetUp()` rebuild the preconditioner.

   Level: advanced

.seealso: `PCGDSW`, `PCGDSWGetRotations()`, `PCGDSWSetCoarseSpaceType()`, `PCSetCoordinates()`, `MatSetNearNullSpace()`
@*/
PetscErrorCode PCGDSWSetRotations(PC pc, PetscBool flg)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidLogicalCollectiveBool(pc, flg, 2);
  PetscTryMethod(pc, "PCGDSWSetRotations_C", (PC, PetscBool), (pc, flg));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetRotations_GDSW(PC pc, PetscBool *flg)
{
  PetscFunctionBegin;
  *flg = ((PC_GDSW *)pc->data)->rotations;
  PetscFunctionReturn(0);
}

/*@
   PCGDSWGetRotations - Gets whether the coarse space of `PCGDSW` uses the rotations of the null space

   Not Collective

   Input Parameter:
.  pc - the preconditioner context

   Output Parameter:
.  flg - the flag

   Level: advanced

.seealso: `PCGDSW`, `PCGDSWSetRotations()`
@*/
PetscErrorCode PCGDSWGetRotations(PC pc, PetscBool *flg)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscAssertPointer(flg, 2);
  PetscUseMethod(pc, "PCGDSWGetRotations_C", (PC, PetscBool *), (pc, flg));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetCombinationType_GDSW(PC pc, PCCompositeType t)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCheck(t == PC_COMPOSITE_ADDITIVE || t == PC_COMPOSITE_MULTIPLICATIVE || t == PC_COMPOSITE_SYMMETRIC_MULTIPLICATIVE, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE,
             "PCGDSW: the combination %s is not one PCGDSW does: use PC_COMPOSITE_ADDITIVE, PC_COMPOSITE_MULTIPLICATIVE or PC_COMPOSITE_SYMMETRIC_MULTIPLICATIVE", t >= 0 && t <= PC_COMPOSITE_GKB ? PCCompositeTypes[t] : "(out of range)");
  if (t != gd->combination) pc->setupcalled = 0; /* the multiplicative and balanced ones have work vectors, the balanced one W */
  gd->combination = t;
  PetscFunctionReturn(0);
}

/*@
   PCGDSWSetCombinationType - Sets how `PCGDSW` combines its coarse correction Q_0 = Phi A_0^{-1} Phi^T and its local solves M_1 = sum_i R_i^T A_i^{-1} R_i, in the terms `PCCOMPOSITE` uses for its PCs

   Logically Collective on pc

   Input Parameters:
+  pc - the preconditioner context
-  type - `PC_COMPOSITE_SYMMETRIC_MULTIPLICATIVE` (the default: Q_0, M_1 on the updated residual, Q_0 again, i.e. Q_0 + (I - Q_0 A) M_1 (I - A Q_0); symmetric), `PC_COMPOSITE_ADDITIVE` (Q_0 + M_1; symmetric) or `PC_COMPOSITE_MULTIPLICATIVE` (Q_0, then M_1 on the updated residual; nonsymmetric)

   Options Database Key:
.  -pc_gdsw_combination <additive,multiplicative,symmetric_multiplicative> - sets the type

   Notes:
   The symmetric multiplicative combination is the balanced or hybrid Schwarz method ([Man93], [TW05] Sec. 2.5.2; BNN in [TNVE09]).
   It solves the coarse space exactly, M A Phi = Phi, so the local solves act only on what the coarse
   space cannot represent, and its condition number is at most the additive one's. It keeps
   W = A Phi from the set-up (nonzero on interface rows only after an exact extension, summed from
   the blocks that also give A_0) and then costs what the additive one does plus two products with W
   and a second coarse solve. For a nonsymmetric operator the products with (A^T Phi) go through A.
   The other `PCCompositeType` values are not combinations of two corrections and are refused.

   A new value makes the next `PCSetUp()` rebuild the preconditioner.

   Level: intermediate

.seealso: `PCGDSW`, `PCCompositeType`, `PCGDSWGetCombinationType()`, `PCGDSWSetFirstLevelType()`, `PCCompositeSetType()`
@*/
PetscErrorCode PCGDSWSetCombinationType(PC pc, PCCompositeType type)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidLogicalCollectiveEnum(pc, type, 2);
  PetscTryMethod(pc, "PCGDSWSetCombinationType_C", (PC, PCCompositeType), (pc, type));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetCombinationType_GDSW(PC pc, PCCompositeType *t)
{
  PetscFunctionBegin;
  *t = ((PC_GDSW *)pc->data)->combination;
  PetscFunctionReturn(0);
}

/*@
   PCGDSWGetCombinationType - Gets how `PCGDSW` combines its coarse and local corrections

   Not Collective

   Input Parameter:
.  pc - the preconditioner context

   Output Parameter:
.  type - the combination, a `PCCompositeType`

   Level: intermediate

.seealso: `PCGDSW`, `PCGDSWSetCombinationType()`
@*/
PetscErrorCode PCGDSWGetCombinationType(PC pc, PCCompositeType *type)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscAssertPointer(type, 2);
  PetscUseMethod(pc, "PCGDSWGetCombinationType_C", (PC, PCCompositeType *), (pc, type));
  PetscFunctionReturn(0);
}

/* Read at the next setup with new values: nothing to rebuild. */
static PetscErrorCode PCGDSWSetReuseCoarseBasis_GDSW(PC pc, PetscBool flg)
{
  PetscFunctionBegin;
  ((PC_GDSW *)pc->data)->reuseCoarseBasis = flg;
  PetscFunctionReturn(0);
}

/*@
   PCGDSWSetReuseCoarseBasis - Sets whether `PCGDSW` keeps its coarse basis Phi when the operator's values change with the same nonzero pattern

   Logically Collective on pc

   Input Parameters:
+  pc - the preconditioner context
-  flg - `PETSC_TRUE` to keep Phi and recompute only A_0 = Phi^T A Phi, `PETSC_FALSE` (the default) to re-extend Phi with the new values

   Options Database Key:
.  -pc_gdsw_reuse_coarse_basis <true,false> - sets the flag

   Note:
   A kept basis saves the interior factorisations and solves of the harmonic extension at the price of iterations when the operator changes much.
   A_0 is still assembled from the subdomains' own matrices, with one dense product Phi_I^T (A Phi)_I per subdomain for the interior rows of A Phi, which no longer vanish.

   Level: advanced

.seealso: `PCGDSW`, `PCGDSWGetReuseCoarseBasis()`, `PCSetReusePreconditioner()`
@*/
PetscErrorCode PCGDSWSetReuseCoarseBasis(PC pc, PetscBool flg)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidLogicalCollectiveBool(pc, flg, 2);
  PetscTryMethod(pc, "PCGDSWSetReuseCoarseBasis_C", (PC, PetscBool), (pc, flg));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetReuseCoarseBasis_GDSW(PC pc, PetscBool *flg)
{
  PetscFunctionBegin;
  *flg = ((PC_GDSW *)pc->data)->reuseCoarseBasis;
  PetscFunctionReturn(0);
}

/*@
   PCGDSWGetReuseCoarseBasis - Gets whether `PCGDSW` keeps its coarse basis when the operator's values change

   Not Collective

   Input Parameter:
.  pc - the preconditioner context

   Output Parameter:
.  flg - the flag

   Level: advanced

.seealso: `PCGDSW`, `PCGDSWSetReuseCoarseBasis()`
@*/
PetscErrorCode PCGDSWGetReuseCoarseBasis(PC pc, PetscBool *flg)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscAssertPointer(flg, 2);
  PetscUseMethod(pc, "PCGDSWGetReuseCoarseBasis_C", (PC, PetscBool *), (pc, flg));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetCoarseBasis_GDSW(PC pc, Mat *Phi)
{
  PetscFunctionBegin;
  PetscCall(GDSWCheckSetUp(pc));
  PC_GDSW *gd = (PC_GDSW *)pc->data;
  if (gd->Phi) PetscCall(GDSWAssemblePhiMatrix(pc));
  *Phi = gd->PhiAssembled;
  PetscFunctionReturn(0);
}

/*@
   PCGDSWGetCoarseBasis - Gets the coarse basis Phi of `PCGDSW` (global dofs x coarse dofs)

   Collective on pc the first time after each set-up (Phi is assembled then; the preconditioner applies it from its pieces)

   Input Parameter:
.  pc - the preconditioner context, set up

   Output Parameter:
.  Phi - the coarse basis, or NULL when there is no coarse level (type none, or no interface)

   Note:
   A borrowed reference, valid until the next `PCSetUp()`.

   Level: advanced

.seealso: `PCGDSW`, `PCGDSWGetCoarseOperator()`, `PCGDSWGetCoarseKSP()`, `PCGDSWGetInterfaceCounts()`
@*/
PetscErrorCode PCGDSWGetCoarseBasis(PC pc, Mat *Phi)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscAssertPointer(Phi, 2);
  PetscUseMethod(pc, "PCGDSWGetCoarseBasis_C", (PC, Mat *), (pc, Phi));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetCoarseOperator_GDSW(PC pc, Mat *A0)
{
  PetscFunctionBegin;
  PetscCall(GDSWCheckSetUp(pc));
  *A0 = ((PC_GDSW *)pc->data)->A0;
  PetscFunctionReturn(0);
}

/*@
   PCGDSWGetCoarseOperator - Gets the coarse operator A_0 = Phi^T A Phi of `PCGDSW`

   Not Collective, but the matrix is parallel

   Input Parameter:
.  pc - the preconditioner context, set up

   Output Parameter:
.  A0 - the coarse operator, or NULL when there is no coarse level

   Note:
   A borrowed reference, valid until the next `PCSetUp()`.

   Level: advanced

.seealso: `PCGDSW`, `PCGDSWGetCoarseBasis()`, `PCGDSWGetCoarseKSP()`
@*/
PetscErrorCode PCGDSWGetCoarseOperator(PC pc, Mat *A0)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscAssertPointer(A0, 2);
  PetscUseMethod(pc, "PCGDSWGetCoarseOperator_C", (PC, Mat *), (pc, A0));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetCoarseKSP_GDSW(PC pc, KSP *ksp)
{
  PetscFunctionBegin;
  PetscCall(GDSWCheckSetUp(pc));
  *ksp = ((PC_GDSW *)pc->data)->coarseKsp;
  PetscFunctionReturn(0);
}

/*@
   PCGDSWGetCoarseKSP - Gets the solver of the coarse problem of `PCGDSW`

   Not Collective, but the `KSP` is parallel

   Input Parameter:
.  pc - the preconditioner context, set up

   Output Parameter:
.  ksp - the coarse solver, with the options prefix -pc_gdsw_coarse_ (after the `PC`'s own), or NULL when there is no coarse level

   Note:
   A borrowed reference, valid until the next `PCSetUp()` that rebuilds the preconditioner.

   Level: advanced

.seealso: `PCGDSW`, `PCGDSWGetCoarseOperator()`, `PCGDSWGetCoarseBasis()`
@*/
PetscErrorCode PCGDSWGetCoarseKSP(PC pc, KSP *ksp)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscAssertPointer(ksp, 2);
  PetscUseMethod(pc, "PCGDSWGetCoarseKSP_C", (PC, KSP *), (pc, ksp));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetInterfaceCounts_GDSW(PC pc, PetscInt *faces, PetscInt *edges, PetscInt *vertices)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCall(GDSWCheckSetUp(pc));
  if (faces) *faces = gd->counts[0];
  if (edges) *edges = gd->counts[1];
  if (vertices) *vertices = gd->counts[2];
  PetscFunctionReturn(0);
}

/*@
   PCGDSWGetInterfaceCounts - Gets the numbers of interface components of `PCGDSW`, over all ranks

   Not Collective

   Input Parameter:
.  pc - the preconditioner context, set up

   Output Parameters:
+  faces - components shared by two subdomains, or NULL
.  edges - components of more than one node shared by three or more subdomains, or NULL
-  vertices - single nodes shared by three or more subdomains, or NULL

   Level: advanced

.seealso: `PCGDSW`, `PCGDSWGetCoarseBasis()`
@*/
PetscErrorCode PCGDSWGetInterfaceCounts(PC pc, PetscInt *faces, PetscInt *edges, PetscInt *vertices)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscUseMethod(pc, "PCGDSWGetInterfaceCounts_C", (PC, PetscInt *, PetscInt *, PetscInt *), (pc, faces, edges, vertices));
  PetscFunctionReturn(0);
}

/* The composed methods of the coarse space: added by PCCreate_GDSW(), removed by PCDestroy_GDSW(). */
PetscErrorCode GDSWComposeCoarseSpaceMethods(PC pc, PetscBool add)
{
  PetscObject o = (PetscObject)pc;

  PetscFunctionBegin;
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWSetCoarseSpaceType_C", add ? PCGDSWSetCoarseSpaceType_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetCoarseSpaceType_C", add ? PCGDSWGetCoarseSpaceType_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWSetRGDSWWeightType_C", add ? PCGDSWSetRGDSWWeightType_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetRGDSWWeightType_C", add ? PCGDSWGetRGDSWWeightType_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWSetRotations_C", add ? PCGDSWSetRotations_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetRotations_C", add ? PCGDSWGetRotations_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWSetCombinationType_C", add ? PCGDSWSetCombinationType_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetCombinationType_C", add ? PCGDSWGetCombinationType_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWSetReuseCoarseBasis_C", add ? PCGDSWSetReuseCoarseBasis_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetReuseCoarseBasis_C", add ? PCGDSWGetReuseCoarseBasis_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetCoarseBasis_C", add ? PCGDSWGetCoarseBasis_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetCoarseOperator_C", add ? PCGDSWGetCoarseOperator_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetCoarseKSP_C", add ? PCGDSWGetCoarseKSP_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetInterfaceCounts_C", add ? PCGDSWGetInterfaceCounts_GDSW : nullptr));
  PetscFunctionReturn(0);
}
