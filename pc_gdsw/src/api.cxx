// SPDX-License-Identifier: BSD-2-Clause
/* The public PCGDSW functions with their manual pages. Each calls the method of the same name
   that PCCreate_GDSW() composes on the PC (gdsw.cxx), so it does nothing (setters) or says it
   cannot find the method (getters) on a PC of another type. */
#include <petsc/private/pcimpl.h> /* PetscTryMethod, PetscValid* */
#include <petscgdsw.h>

/*@
   PCGDSWSetSubdomains - Sets this rank's subdomains of `PCGDSW`: an element-based decomposition from an application that knows its mesh

   Collective on pc

   Input Parameters:
+  pc - the preconditioner context
.  n - the number of subdomains this rank holds (0 or more; the numbers may differ between ranks)
.  nonoverlap - for each subdomain the global dofs in the closure of its cells
-  overlap - for each subdomain the global dofs of its overlapping subdomain, a superset of nonoverlap[i], or NULL to add -pc_gdsw_overlap layers of the matrix graph

   Notes:
   Each index set must hold whole nodes (all dofs of each node it touches, for the block size of the operator), and together the nonoverlapping sets must cover every dof.
   Empty subdomains are dropped. The `PC` takes references to the index sets; the caller may destroy its own.
   The next `PCSetUp()` rebuilds the preconditioner.

   Level: intermediate

.seealso: `PCGDSW`, `PCGDSWGetSubdomains()`, `PCGDSWSetSubdomainsPerRank()`, `PCGDSWSetOverlap()`, `PCASMSetLocalSubdomains()`
@*/
PetscErrorCode PCGDSWSetSubdomains(PC pc, PetscInt n, IS nonoverlap[], IS overlap[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  if (n > 0) PetscValidPointer(nonoverlap, 3);
  for (PetscInt i = 0; i < n; i++) {
    PetscValidHeaderSpecific(nonoverlap[i], IS_CLASSID, 3);
    if (overlap) PetscValidHeaderSpecific(overlap[i], IS_CLASSID, 4);
  }
  PetscTryMethod(pc, "PCGDSWSetSubdomains_C", (PC, PetscInt, IS[], IS[]), (pc, n, nonoverlap, overlap));
  PetscFunctionReturn(0);
}

/*@C
   PCGDSWGetSubdomains - Gets this rank's subdomains of `PCGDSW` as the preconditioner uses them

   Not Collective

   Input Parameter:
.  pc - the preconditioner context, set up

   Output Parameters:
+  n - the number of subdomains this rank holds (empty ones dropped), or NULL
.  nonoverlap - for each the global dofs of the nonoverlapping subdomain, or NULL
-  overlap - for each the global dofs of the overlapping subdomain, or NULL

   Note:
   The arrays and index sets belong to the `PC` and stay valid until its next `PCSetUp()` that rebuilds it.

   Level: intermediate

.seealso: `PCGDSW`, `PCGDSWSetSubdomains()`, `PCGDSWSetOverlap()`, `PCASMGetLocalSubdomains()`
@*/
PetscErrorCode PCGDSWGetSubdomains(PC pc, PetscInt *n, IS *nonoverlap[], IS *overlap[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscUseMethod(pc, "PCGDSWGetSubdomains_C", (PC, PetscInt *, IS *[], IS *[]), (pc, n, nonoverlap, overlap));
  PetscFunctionReturn(0);
}

/*@
   PCGDSWSetSubdomainsPerRank - Sets the number of subdomains per MPI rank of `PCGDSW` when it splits each rank's node graph with METIS

   Logically Collective on pc

   Input Parameters:
+  pc - the preconditioner context
-  n - the number of subdomains per rank, at least 1, or `PETSC_DECIDE` (the default) for about `PCGDSWSetSubdomainSize()` dofs each

   Options Database Key:
.  -pc_gdsw_subdomains <n> - sets the number

   Notes:
   Not used when the application gives its subdomains with `PCGDSWSetSubdomains()`. For a `MATIS` operator each rank's local subdomain is split into n by METIS
   on its local matrix's node graph. With `PCGDSWSetRepartition()` the whole graph is split into n times the number of ranks.
   A new value makes the next `PCSetUp()` rebuild the preconditioner.

   Level: intermediate

.seealso: `PCGDSW`, `PCGDSWGetSubdomainsPerRank()`, `PCGDSWSetSubdomainSize()`, `PCGDSWSetSubdomains()`
@*/
PetscErrorCode PCGDSWSetSubdomainsPerRank(PC pc, PetscInt n)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidLogicalCollectiveInt(pc, n, 2);
  PetscTryMethod(pc, "PCGDSWSetSubdomainsPerRank_C", (PC, PetscInt), (pc, n));
  PetscFunctionReturn(0);
}

/*@
   PCGDSWGetSubdomainsPerRank - Gets the number of subdomains per MPI rank requested from `PCGDSW`

   Not Collective

   Input Parameter:
.  pc - the preconditioner context

   Output Parameter:
.  n - the number, or `PETSC_DECIDE` for the size rule

   Level: intermediate

.seealso: `PCGDSW`, `PCGDSWSetSubdomainsPerRank()`, `PCGDSWGetSubdomains()`
@*/
PetscErrorCode PCGDSWGetSubdomainsPerRank(PC pc, PetscInt *n)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidIntPointer(n, 2);
  PetscUseMethod(pc, "PCGDSWGetSubdomainsPerRank_C", (PC, PetscInt *), (pc, n));
  PetscFunctionReturn(0);
}

/*@
   PCGDSWSetRepartition - Sets whether `PCGDSW` makes its algebraic subdomains from a parallel partition of the whole matrix graph rather than from each rank's rows

   Logically Collective on pc

   Input Parameters:
+  pc - the preconditioner context
-  flg - `PETSC_TRUE` to repartition, `PETSC_FALSE` (the default) to split each rank's rows with METIS

   Options Database Keys:
+  -pc_gdsw_repartition <true,false> - sets the flag
-  -pc_gdsw_mat_partitioning_type <type> - the partitioner (`MatPartitioningType`; PETSc's default: ParMETIS, else PTScotch where installed)

   Notes:
   By default each subdomain lies within one rank's rows, so the subdomains are no better shaped than the application's distribution of the mesh.
   Where that distribution is not compact (a plate whose ranks each hold some layers of its thickness, as a simple partition of a box's
   cells in their order gives), the subdomains are thin and the iterations grow. With this flag the node graph of the whole operator is
   split into as many subdomains as the size rule or `PCGDSWSetSubdomainsPerRank()` asks for (times the number of ranks), subdomain i
   goes to rank floor(i size / N), and the rows stay where they are. The parts of a parallel partitioner need not be connected.
   Not used with `PCGDSWSetSubdomains()` or a `MATIS` operator. A new value makes the next `PCSetUp()` rebuild the preconditioner.

   Level: intermediate

.seealso: `PCGDSW`, `PCGDSWGetRepartition()`, `PCGDSWSetSubdomainsPerRank()`, `PCGDSWSetSubdomainSize()`, `MatPartitioningCreate()`
@*/
PetscErrorCode PCGDSWSetRepartition(PC pc, PetscBool flg)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidLogicalCollectiveBool(pc, flg, 2);
  PetscTryMethod(pc, "PCGDSWSetRepartition_C", (PC, PetscBool), (pc, flg));
  PetscFunctionReturn(0);
}

/*@
   PCGDSWGetRepartition - Gets whether `PCGDSW` makes its algebraic subdomains from a parallel partition of the whole matrix graph

   Not Collective

   Input Parameter:
.  pc - the preconditioner context

   Output Parameter:
.  flg - the flag

   Level: intermediate

.seealso: `PCGDSW`, `PCGDSWSetRepartition()`
@*/
PetscErrorCode PCGDSWGetRepartition(PC pc, PetscBool *flg)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidBoolPointer(flg, 2);
  PetscUseMethod(pc, "PCGDSWGetRepartition_C", (PC, PetscBool *), (pc, flg));
  PetscFunctionReturn(0);
}

/*@
   PCGDSWSetSubdomainSize - Sets the target number of dofs per subdomain with which `PCGDSW` chooses the number of subdomains per rank

   Logically Collective on pc

   Input Parameters:
+  pc - the preconditioner context
-  n - the target, at least 1, or `PETSC_DECIDE` (the default): 12000 with exact local solvers, 3000 with incomplete or adaptive ones (`PCGDSWSetLocalSolverType()`)

   Options Database Key:
.  -pc_gdsw_subdomain_size <n> - sets the target

   Notes:
   Each rank takes round(local dofs / n) subdomains, at least 1, when neither the application nor `PCGDSWSetSubdomainsPerRank()` fixes them.
   The default is the fastest of 1-32 subdomains per rank measured on 3D elasticity at 49 k and 96 k dofs per rank.
   A new value makes the next `PCSetUp()` rebuild the preconditioner.

   Level: advanced

.seealso: `PCGDSW`, `PCGDSWGetSubdomainSize()`, `PCGDSWSetSubdomainsPerRank()`
@*/
PetscErrorCode PCGDSWSetSubdomainSize(PC pc, PetscInt n)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidLogicalCollectiveInt(pc, n, 2);
  PetscTryMethod(pc, "PCGDSWSetSubdomainSize_C", (PC, PetscInt), (pc, n));
  PetscFunctionReturn(0);
}

/*@
   PCGDSWGetSubdomainSize - Gets the target number of dofs per subdomain of `PCGDSW`

   Not Collective

   Input Parameter:
.  pc - the preconditioner context

   Output Parameter:
.  n - the target

   Level: advanced

.seealso: `PCGDSW`, `PCGDSWSetSubdomainSize()`
@*/
PetscErrorCode PCGDSWGetSubdomainSize(PC pc, PetscInt *n)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidIntPointer(n, 2);
  PetscUseMethod(pc, "PCGDSWGetSubdomainSize_C", (PC, PetscInt *), (pc, n));
  PetscFunctionReturn(0);
}

/*@
   PCGDSWSetOverlap - Sets the number of layers of the matrix graph `PCGDSW` adds to each subdomain

   Logically Collective on pc

   Input Parameters:
+  pc - the preconditioner context
-  k - the number of layers, 0 or more (default 1)

   Options Database Key:
.  -pc_gdsw_overlap <k> - sets the overlap

   Notes:
   Not used when `PCGDSWSetSubdomains()` gave overlapping subdomains. For Q1 elements one layer of the graph is one layer of elements.
   A new value makes the next `PCSetUp()` rebuild the preconditioner.

   Level: intermediate

.seealso: `PCGDSW`, `PCGDSWGetOverlap()`, `PCGDSWSetSubdomains()`, `PCGDSWGetSubdomains()`, `MatIncreaseOverlap()`
@*/
PetscErrorCode PCGDSWSetOverlap(PC pc, PetscInt k)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidLogicalCollectiveInt(pc, k, 2);
  PetscTryMethod(pc, "PCGDSWSetOverlap_C", (PC, PetscInt), (pc, k));
  PetscFunctionReturn(0);
}

/*@
   PCGDSWGetOverlap - Gets the number of layers of the matrix graph `PCGDSW` adds to each subdomain

   Not Collective

   Input Parameter:
.  pc - the preconditioner context

   Output Parameter:
.  k - the number of layers

   Level: intermediate

.seealso: `PCGDSW`, `PCGDSWSetOverlap()`
@*/
PetscErrorCode PCGDSWGetOverlap(PC pc, PetscInt *k)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidIntPointer(k, 2);
  PetscUseMethod(pc, "PCGDSWGetOverlap_C", (PC, PetscInt *), (pc, k));
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
  PetscValidPointer(type, 2);
  PetscUseMethod(pc, "PCGDSWGetCoarseSpaceType_C", (PC, PCGDSWCoarseSpaceType *), (pc, type));
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
  PetscValidPointer(type, 2);
  PetscUseMethod(pc, "PCGDSWGetRGDSWWeightType_C", (PC, PCGDSWRGDSWWeightType *), (pc, type));
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
  PetscValidBoolPointer(flg, 2);
  PetscUseMethod(pc, "PCGDSWGetRotations_C", (PC, PetscBool *), (pc, flg));
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
  PetscValidPointer(type, 2);
  PetscUseMethod(pc, "PCGDSWGetCombinationType_C", (PC, PCCompositeType *), (pc, type));
  PetscFunctionReturn(0);
}

/*@
   PCGDSWSetFirstLevelType - Sets how `PCGDSW` prolongates its local corrections

   Logically Collective on pc

   Input Parameters:
+  pc - the preconditioner context
-  type - `PC_GDSW_FIRST_LEVEL_ADDITIVE` (the default, symmetric: R_i^T on the whole overlapping subdomain) or `PC_GDSW_FIRST_LEVEL_RESTRICTED` (RAS: each dof from the one subdomain of smallest number that holds it in its nonoverlapping part; nonsymmetric)

   Options Database Key:
.  -pc_gdsw_first_level_type <additive,restricted> - sets the type

   Note:
   A new value makes the next `PCSetUp()` rebuild the preconditioner.

   Level: intermediate

.seealso: `PCGDSW`, `PCGDSWFirstLevelType`, `PCGDSWGetFirstLevelType()`, `PCGDSWSetCombinationType()`, `PCASMSetType()`
@*/
PetscErrorCode PCGDSWSetFirstLevelType(PC pc, PCGDSWFirstLevelType type)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidLogicalCollectiveEnum(pc, type, 2);
  PetscTryMethod(pc, "PCGDSWSetFirstLevelType_C", (PC, PCGDSWFirstLevelType), (pc, type));
  PetscFunctionReturn(0);
}

/*@
   PCGDSWGetFirstLevelType - Gets how `PCGDSW` prolongates its local corrections

   Not Collective

   Input Parameter:
.  pc - the preconditioner context

   Output Parameter:
.  type - the first level's type

   Level: intermediate

.seealso: `PCGDSW`, `PCGDSWSetFirstLevelType()`
@*/
PetscErrorCode PCGDSWGetFirstLevelType(PC pc, PCGDSWFirstLevelType *type)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidPointer(type, 2);
  PetscUseMethod(pc, "PCGDSWGetFirstLevelType_C", (PC, PCGDSWFirstLevelType *), (pc, type));
  PetscFunctionReturn(0);
}

/*@
   PCGDSWSetLocalSolverType - Sets what solves the overlapping subdomain problems of `PCGDSW`'s first level

   Logically Collective on pc

   Input Parameters:
+  pc - the preconditioner context
-  type - `PC_GDSW_LOCAL_EXACT` (the default: Cholesky with CHOLMOD for symmetric operators, else LU with UMFPACK),
          `PC_GDSW_LOCAL_INCOMPLETE` (ICC(0) for symmetric operators, else ILU(0)), or
          `PC_GDSW_LOCAL_ADAPTIVE` (an incomplete factor where it is good enough, an exact one elsewhere)

   Options Database Key:
.  -pc_gdsw_local_solver <exact,incomplete,adaptive> - sets the type

   Notes:
   Incomplete factors cost O(n) for a subdomain of n dofs where exact ones cost O(n^2) in 3D, and
   lose quality with n, so without `PCGDSWSetSubdomainSize()` the size rule aims at 3000 dofs per
   subdomain for them (12000 for exact ones). On benign problems (homogeneous Q1 elasticity) they
   make the preconditioner several times cheaper; on nearly incompressible elasticity, coefficient
   jumps inside a subdomain or P2 shells they cost many more iterations or stall.

   The adaptive type factors each overlapping subdomain matrix incompletely, estimates the
   condition number of the preconditioned matrix from 12 conjugate gradient (symmetric) or GMRES
   iterations on a fixed random right-hand side, and factors the subdomains whose estimate exceeds
   `PCGDSWSetLocalConditionMax()` exactly. The choice is made at the first set-up of a pattern and
   kept when only the values change. -ksp_view counts the subdomains of each kind.

   Options of the prefix -pc_gdsw_sub_ (e.g. -pc_gdsw_sub_pc_type) override the type's solver;
   the interior solves of the harmonic extension (-pc_gdsw_extension_) stay exact.

   Level: intermediate

.seealso: `PCGDSW`, `PCGDSWLocalSolverType`, `PCGDSWGetLocalSolverType()`, `PCGDSWSetLocalConditionMax()`, `PCGDSWSetSubdomainSize()`
@*/
PetscErrorCode PCGDSWSetLocalSolverType(PC pc, PCGDSWLocalSolverType type)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidLogicalCollectiveEnum(pc, type, 2);
  PetscTryMethod(pc, "PCGDSWSetLocalSolverType_C", (PC, PCGDSWLocalSolverType), (pc, type));
  PetscFunctionReturn(0);
}

/*@
   PCGDSWGetLocalSolverType - Gets what solves the overlapping subdomain problems of `PCGDSW`'s first level

   Not Collective

   Input Parameter:
.  pc - the preconditioner context

   Output Parameter:
.  type - the type

   Level: intermediate

.seealso: `PCGDSW`, `PCGDSWSetLocalSolverType()`
@*/
PetscErrorCode PCGDSWGetLocalSolverType(PC pc, PCGDSWLocalSolverType *type)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidPointer(type, 2);
  PetscUseMethod(pc, "PCGDSWGetLocalSolverType_C", (PC, PCGDSWLocalSolverType *), (pc, type));
  PetscFunctionReturn(0);
}

/*@
   PCGDSWSetLocalConditionMax - Sets the largest condition number estimate at which an adaptive local solver of `PCGDSW` keeps its incomplete factor

   Logically Collective on pc

   Input Parameters:
+  pc - the preconditioner context
-  c - the bound, at least 1 (default 25)

   Options Database Key:
.  -pc_gdsw_local_condition_max <25> - sets the bound

   Note:
   Estimates measured with ICC(0) on subdomains of 3000 dofs (12 iterations): 4-14 on
   homogeneous Q1 elasticity, up to 66 where a 1e6 coefficient jump cuts a subdomain, 43-400 at
   nu = 0.49 and 70-1700 at nu = 0.4999. Used with `PC_GDSW_LOCAL_ADAPTIVE` only.

   Level: advanced

.seealso: `PCGDSW`, `PCGDSWSetLocalSolverType()`, `PCGDSWGetLocalConditionMax()`
@*/
PetscErrorCode PCGDSWSetLocalConditionMax(PC pc, PetscReal c)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidLogicalCollectiveReal(pc, c, 2);
  PetscTryMethod(pc, "PCGDSWSetLocalConditionMax_C", (PC, PetscReal), (pc, c));
  PetscFunctionReturn(0);
}

/*@
   PCGDSWGetLocalConditionMax - Gets the adaptive local solvers' bound of `PCGDSW`

   Not Collective

   Input Parameter:
.  pc - the preconditioner context

   Output Parameter:
.  c - the bound

   Level: advanced

.seealso: `PCGDSW`, `PCGDSWSetLocalConditionMax()`
@*/
PetscErrorCode PCGDSWGetLocalConditionMax(PC pc, PetscReal *c)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidRealPointer(c, 2);
  PetscUseMethod(pc, "PCGDSWGetLocalConditionMax_C", (PC, PetscReal *), (pc, c));
  PetscFunctionReturn(0);
}

/*@
   PCGDSWSetLocalPrecision - Sets the precision in which `PCGDSW` keeps and applies the Cholesky factors of its first level

   Logically Collective on pc

   Input Parameters:
+  pc - the preconditioner context
-  precision - `PC_GDSW_LOCAL_PRECISION_DOUBLE` (the default) or `PC_GDSW_LOCAL_PRECISION_SINGLE`

   Options Database Key:
.  -pc_gdsw_local_precision <single,double> - sets the precision

   Notes:
   The factors are computed by CHOLMOD in double precision either way. With single precision
   (`MATSOLVERCHOLMODSINGLE`, "cholmod_single") each factor is then rounded to single
   precision and its double values are freed: the factors take half the memory, and the
   triangular solves of every application, which read the whole factor for few flops and are
   limited by memory bandwidth, take about half the time. Each factorisation checks itself on a
   fixed pseudo-random right-hand side; where the single-precision solution deviates from the
   double one by more than 1e-3 (relative), that factor stays in double precision (-info names
   it). -ksp_view counts the factors kept in single precision.

   Use single precision with `KSPCG` or `KSPFGMRES`. A preconditioner applied in single
   precision is linear only up to its rounding, about 1e-7 of each application; `KSPGMRES`
   (either side) forms its solution from many applications whose rounding does not cancel with
   them, and its true residual stalls while its estimate goes on falling (Q1 elasticity: a true
   relative residual of 7e-6, against 5e-10 with double factors, for a tolerance of 1e-12). CG
   updates its residual with the operator, and FGMRES keeps each preconditioned vector, so both
   converge as with double factors (FGMRES: 1e-12 with either).

   Only symmetric operators are affected: LU factors (UMFPACK), incomplete factors and the
   interior solves of the harmonic extension stay in double precision. An explicit
   -pc_gdsw_sub_pc_factor_mat_solver_type overrides this setting.

   Level: intermediate

.seealso: `PCGDSW`, `PCGDSWLocalPrecision`, `PCGDSWGetLocalPrecision()`, `PCGDSWSetLocalSolverType()`
@*/
PetscErrorCode PCGDSWSetLocalPrecision(PC pc, PCGDSWLocalPrecision precision)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidLogicalCollectiveEnum(pc, precision, 2);
  PetscTryMethod(pc, "PCGDSWSetLocalPrecision_C", (PC, PCGDSWLocalPrecision), (pc, precision));
  PetscFunctionReturn(0);
}

/*@
   PCGDSWGetLocalPrecision - Gets the precision in which `PCGDSW` keeps and applies the Cholesky factors of its first level

   Not Collective

   Input Parameter:
.  pc - the preconditioner context

   Output Parameter:
.  precision - the precision

   Level: intermediate

.seealso: `PCGDSW`, `PCGDSWSetLocalPrecision()`
@*/
PetscErrorCode PCGDSWGetLocalPrecision(PC pc, PCGDSWLocalPrecision *precision)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidPointer(precision, 2);
  PetscUseMethod(pc, "PCGDSWGetLocalPrecision_C", (PC, PCGDSWLocalPrecision *), (pc, precision));
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
  PetscValidBoolPointer(flg, 2);
  PetscUseMethod(pc, "PCGDSWGetReuseCoarseBasis_C", (PC, PetscBool *), (pc, flg));
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
  PetscValidPointer(Phi, 2);
  PetscUseMethod(pc, "PCGDSWGetCoarseBasis_C", (PC, Mat *), (pc, Phi));
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
  PetscValidPointer(A0, 2);
  PetscUseMethod(pc, "PCGDSWGetCoarseOperator_C", (PC, Mat *), (pc, A0));
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
  PetscValidPointer(ksp, 2);
  PetscUseMethod(pc, "PCGDSWGetCoarseKSP_C", (PC, KSP *), (pc, ksp));
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

/*@
   PCGDSWSetHugePages - Sets whether `PCGDSW` asks for transparent huge pages for the local factors while it sets up

   Logically Collective on pc

   Input Parameters:
+  pc - the preconditioner context
-  flg - `PETSC_TRUE` (the default) to map the blocks of 2 MiB or more that the set-up keeps on huge pages, `PETSC_FALSE` to leave them to malloc()

   Options Database Key:
.  -pc_gdsw_huge_pages <true,false> - sets the flag

   Notes:
   A fresh set-up writes the subdomain matrices and the first level's factors (CHOLMOD, UMFPACK) to memory touched for
   the first time. Where the kernel gives transparent huge pages only on request (/sys/kernel/mm/transparent_hugepage/enabled
   is madvise, the default of Debian and Ubuntu) every 4 KiB page of them costs a page fault; with this flag their blocks
   of 2 MiB or more are mapped aligned to 2 MiB and advised MADV_HUGEPAGE, what the glibc tunable glibc.malloc.hugetlb=1
   does for a whole process. The flag changes nothing where the kernel's mode is always or never, or on other systems. It
   installs allocation functions in SuiteSparse_config once per process; they pass every other block to the functions
   installed before. -ksp_view reports the bytes mapped, -info the kernel's mode.

   Level: advanced

.seealso: `PCGDSW`, `PCGDSWGetHugePages()`
@*/
PetscErrorCode PCGDSWSetHugePages(PC pc, PetscBool flg)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidLogicalCollectiveBool(pc, flg, 2);
  PetscTryMethod(pc, "PCGDSWSetHugePages_C", (PC, PetscBool), (pc, flg));
  PetscFunctionReturn(0);
}

/*@
   PCGDSWGetHugePages - Gets whether `PCGDSW` asks for transparent huge pages for the local factors

   Not Collective

   Input Parameter:
.  pc - the preconditioner context

   Output Parameter:
.  flg - the flag

   Level: advanced

.seealso: `PCGDSW`, `PCGDSWSetHugePages()`
@*/
PetscErrorCode PCGDSWGetHugePages(PC pc, PetscBool *flg)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  PetscValidBoolPointer(flg, 2);
  PetscUseMethod(pc, "PCGDSWGetHugePages_C", (PC, PetscBool *), (pc, flg));
  PetscFunctionReturn(0);
}
