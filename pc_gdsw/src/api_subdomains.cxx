// SPDX-License-Identifier: BSD-2-Clause
/* The subdomains of PCGDSW: the application's, or how many, how large and how far they overlap
   when the PC makes them; and the node coordinates (PCSetCoordinates()). Each public function
   with its manual page calls the method of the same name composed on the PC, which holds its
   body just above it: a setter does nothing on a PC of another type, a getter says it cannot
   find the method. */
#include "gdswimpl.h"

/* what each integer option takes: the end of its messages here and in options.cxx */
const char GDSWSubdomainsTakes[]    = "give the number of subdomains per MPI rank, at least 1, or -1 (PETSC_DECIDE) for about -pc_gdsw_subdomain_size dofs each";
const char GDSWSubdomainSizeTakes[] = "give the target number of dofs per subdomain, at least 1";
const char GDSWOverlapTakes[]       = "give the number of layers, 0 or more";

PetscErrorCode GDSWDestroyUserSubdomains(PC_GDSW *gd)
{
  PetscFunctionBegin;
  for (PetscInt i = 0; i < gd->nUser; i++) {
    PetscCall(ISDestroy(&gd->userNon[i]));
    if (gd->userOvl) PetscCall(ISDestroy(&gd->userOvl[i]));
  }
  PetscCall(PetscFree(gd->userNon));
  PetscCall(PetscFree(gd->userOvl));
  gd->nUser = -1;
  PetscFunctionReturn(0);
}

/* Coordinates change the coarse space: the next PCSetUp() starts afresh. */
static PetscErrorCode PCSetCoordinates_GDSW(PC pc, PetscInt dim, PetscInt n, PetscReal *coords)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCheck(dim >= 1 && dim <= 3, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE, "PCGDSW: PCSetCoordinates() dimension %" PetscInt_FMT " must be 1, 2 or 3", dim);
  for (PetscInt k = 0; k < dim * n; k++)
    PetscCheck(!PetscIsInfOrNanReal(coords[k]), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "PCGDSW: PCSetCoordinates() coordinate %" PetscInt_FMT " of local node %" PetscInt_FMT " is not finite (NaN or Inf): the rigid-body modes need finite coordinates", k % dim, k / dim);
  PetscCall(PetscFree(gd->coords));
  PetscCall(PetscMalloc1(dim * n, &gd->coords));
  PetscCall(PetscArraycpy(gd->coords, coords, dim * n));
  gd->coordDim = dim, gd->nCoordNodes = n;
  pc->setupcalled = 0;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetSubdomains_GDSW(PC pc, PetscInt n, IS non[], IS ovl[])
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCheck(n >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "PCGDSWSetSubdomains: the number of subdomains %" PetscInt_FMT " must be >= 0", n);
  for (PetscInt i = 0; i < n; i++) PetscCall(PetscObjectReference((PetscObject)non[i]));
  if (ovl)
    for (PetscInt i = 0; i < n; i++) PetscCall(PetscObjectReference((PetscObject)ovl[i]));
  PetscCall(GDSWDestroyUserSubdomains(gd));
  PetscCall(PetscMalloc1(n, &gd->userNon));
  for (PetscInt i = 0; i < n; i++) gd->userNon[i] = non[i];
  if (ovl) {
    PetscCall(PetscMalloc1(n, &gd->userOvl));
    for (PetscInt i = 0; i < n; i++) gd->userOvl[i] = ovl[i];
  }
  gd->nUser       = n;
  pc->setupcalled = 0;
  PetscFunctionReturn(0);
}

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
  if (n > 0) PetscAssertPointer(nonoverlap, 3);
  for (PetscInt i = 0; i < n; i++) {
    PetscValidHeaderSpecific(nonoverlap[i], IS_CLASSID, 3);
    if (overlap) PetscValidHeaderSpecific(overlap[i], IS_CLASSID, 4);
  }
  PetscTryMethod(pc, "PCGDSWSetSubdomains_C", (PC, PetscInt, IS[], IS[]), (pc, n, nonoverlap, overlap));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWGetSubdomains_GDSW(PC pc, PetscInt *n, IS *non[], IS *ovl[])
{
  PC_GDSW       *gd   = (PC_GDSW *)pc->data;
  const PetscInt nsub = (PetscInt)gd->sub->size();

  PetscFunctionBegin;
  PetscCall(GDSWCheckSetUp(pc));
  if (!gd->nonArr && nsub) {
    PetscCall(PetscMalloc1(nsub, &gd->nonArr));
    PetscCall(PetscMalloc1(nsub, &gd->ovlArr));
    for (PetscInt i = 0; i < nsub; i++) gd->nonArr[i] = (*gd->sub)[i].nonoverlap, gd->ovlArr[i] = (*gd->sub)[i].overlap;
  }
  if (n) *n = nsub;
  if (non) *non = gd->nonArr;
  if (ovl) *ovl = gd->ovlArr;
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

static PetscErrorCode PCGDSWSetSubdomainsPerRank_GDSW(PC pc, PetscInt n)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCheck(n >= 1 || n == PETSC_DECIDE, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE, "PCGDSW: %s %" PetscInt_FMT " is out of range: %s", GDSWOptionName(pc, "-pc_gdsw_subdomains").c_str(), n, GDSWSubdomainsTakes);
  if (n != gd->nsubPerRank) pc->setupcalled = 0;
  gd->nsubPerRank = n;
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

static PetscErrorCode PCGDSWGetSubdomainsPerRank_GDSW(PC pc, PetscInt *n)
{
  PetscFunctionBegin;
  *n = ((PC_GDSW *)pc->data)->nsubPerRank;
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
  PetscAssertPointer(n, 2);
  PetscUseMethod(pc, "PCGDSWGetSubdomainsPerRank_C", (PC, PetscInt *), (pc, n));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetRepartition_GDSW(PC pc, PetscBool flg)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  if (flg != gd->repartition) pc->setupcalled = 0;
  gd->repartition = flg;
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

static PetscErrorCode PCGDSWGetRepartition_GDSW(PC pc, PetscBool *flg)
{
  PetscFunctionBegin;
  *flg = ((PC_GDSW *)pc->data)->repartition;
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
  PetscAssertPointer(flg, 2);
  PetscUseMethod(pc, "PCGDSWGetRepartition_C", (PC, PetscBool *), (pc, flg));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetSubdomainSize_GDSW(PC pc, PetscInt n)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCheck(n >= 1 || n == PETSC_DECIDE, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE, "PCGDSW: %s %" PetscInt_FMT " is out of range: %s", GDSWOptionName(pc, "-pc_gdsw_subdomain_size").c_str(), n, GDSWSubdomainSizeTakes);
  if (n != gd->subdomainSize) pc->setupcalled = 0;
  gd->subdomainSize = n;
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

static PetscErrorCode PCGDSWGetSubdomainSize_GDSW(PC pc, PetscInt *n)
{
  PetscFunctionBegin;
  *n = GDSWSubdomainSizeTarget((PC_GDSW *)pc->data);
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
  PetscAssertPointer(n, 2);
  PetscUseMethod(pc, "PCGDSWGetSubdomainSize_C", (PC, PetscInt *), (pc, n));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetOverlap_GDSW(PC pc, PetscInt k)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCheck(k >= 0, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE, "PCGDSW: %s %" PetscInt_FMT " is out of range: %s", GDSWOptionName(pc, "-pc_gdsw_overlap").c_str(), k, GDSWOverlapTakes);
  if (k != gd->overlap) pc->setupcalled = 0;
  gd->overlap = k;
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

static PetscErrorCode PCGDSWGetOverlap_GDSW(PC pc, PetscInt *k)
{
  PetscFunctionBegin;
  *k = ((PC_GDSW *)pc->data)->overlap;
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
  PetscAssertPointer(k, 2);
  PetscUseMethod(pc, "PCGDSWGetOverlap_C", (PC, PetscInt *), (pc, k));
  PetscFunctionReturn(0);
}

/* The composed methods of the subdomains and coordinates: added by PCCreate_GDSW(), removed by PCDestroy_GDSW(). */
PetscErrorCode GDSWComposeSubdomainMethods(PC pc, PetscBool add)
{
  PetscObject o = (PetscObject)pc;

  PetscFunctionBegin;
  PetscCall(PetscObjectComposeFunction(o, "PCSetCoordinates_C", add ? PCSetCoordinates_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWSetSubdomains_C", add ? PCGDSWSetSubdomains_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetSubdomains_C", add ? PCGDSWGetSubdomains_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWSetSubdomainsPerRank_C", add ? PCGDSWSetSubdomainsPerRank_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetSubdomainsPerRank_C", add ? PCGDSWGetSubdomainsPerRank_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWSetRepartition_C", add ? PCGDSWSetRepartition_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetRepartition_C", add ? PCGDSWGetRepartition_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWSetSubdomainSize_C", add ? PCGDSWSetSubdomainSize_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetSubdomainSize_C", add ? PCGDSWGetSubdomainSize_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWSetOverlap_C", add ? PCGDSWSetOverlap_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetOverlap_C", add ? PCGDSWGetOverlap_GDSW : nullptr));
  PetscFunctionReturn(0);
}
