// SPDX-License-Identifier: BSD-2-Clause
/* The first level of PCGDSW: its prolongation, its local solvers (their type, the adaptive
   bound, the precision of their factors) and where the set-up keeps their factors (huge pages).
   Each public function with its manual page calls the method of the same name composed on the
   PC, which holds its body just above it. */
#include "gdswimpl.h"

/* what -pc_gdsw_local_condition_max takes: the end of its messages here and in options.cxx */
const char GDSWConditionMaxTakes[] = "give the largest condition number estimate at which a subdomain keeps its incomplete factor, a finite number of at least 1";

static PetscErrorCode PCGDSWSetFirstLevelType_GDSW(PC pc, PCGDSWFirstLevelType t)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCall(GDSWCheckEnum(pc, (PetscEnum)t, (PetscEnum)PC_GDSW_FIRST_LEVEL_RESTRICTED, PCGDSWFirstLevelTypes));
  if (t != gd->firstLevel) pc->setupcalled = 0; /* the restricted prolongation has its own scatter */
  gd->firstLevel = t;
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

static PetscErrorCode PCGDSWGetFirstLevelType_GDSW(PC pc, PCGDSWFirstLevelType *t)
{
  PetscFunctionBegin;
  *t = ((PC_GDSW *)pc->data)->firstLevel;
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
  PetscAssertPointer(type, 2);
  PetscUseMethod(pc, "PCGDSWGetFirstLevelType_C", (PC, PCGDSWFirstLevelType *), (pc, type));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetLocalSolverType_GDSW(PC pc, PCGDSWLocalSolverType t)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCall(GDSWCheckEnum(pc, (PetscEnum)t, (PetscEnum)PC_GDSW_LOCAL_ADAPTIVE, PCGDSWLocalSolverTypes));
  if (t != gd->localSolver) pc->setupcalled = 0; /* new local solvers, and the size rule's target may change */
  gd->localSolver = t;
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

static PetscErrorCode PCGDSWGetLocalSolverType_GDSW(PC pc, PCGDSWLocalSolverType *t)
{
  PetscFunctionBegin;
  *t = ((PC_GDSW *)pc->data)->localSolver;
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
  PetscAssertPointer(type, 2);
  PetscUseMethod(pc, "PCGDSWGetLocalSolverType_C", (PC, PCGDSWLocalSolverType *), (pc, type));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetLocalConditionMax_GDSW(PC pc, PetscReal c)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCheck(c >= 1 && !PetscIsInfOrNanReal(c), PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE, "PCGDSW: %s %g is out of range: %s", GDSWOptionName(pc, "-pc_gdsw_local_condition_max").c_str(), (double)c, GDSWConditionMaxTakes);
  if (c != gd->conditionMax) pc->setupcalled = 0;
  gd->conditionMax = c;
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

static PetscErrorCode PCGDSWGetLocalConditionMax_GDSW(PC pc, PetscReal *c)
{
  PetscFunctionBegin;
  *c = ((PC_GDSW *)pc->data)->conditionMax;
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
  PetscAssertPointer(c, 2);
  PetscUseMethod(pc, "PCGDSWGetLocalConditionMax_C", (PC, PetscReal *), (pc, c));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetLocalPrecision_GDSW(PC pc, PCGDSWLocalPrecision p)
{
  PC_GDSW *gd = (PC_GDSW *)pc->data;

  PetscFunctionBegin;
  PetscCall(GDSWCheckEnum(pc, (PetscEnum)p, (PetscEnum)PC_GDSW_LOCAL_PRECISION_SINGLE, PCGDSWLocalPrecisions));
  if (p != gd->localPrecision) pc->setupcalled = 0; /* new local factors */
  gd->localPrecision = p;
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
   converge as with double factors (FGMRES: 1e-12 with either). So at each solve in which factors
   are kept in single precision, a `KSP` other than CG, FCG, FGMRES, GCR, Richardson or preonly
   with a relative tolerance below 1e-4 stops with an error that says so.

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

static PetscErrorCode PCGDSWGetLocalPrecision_GDSW(PC pc, PCGDSWLocalPrecision *p)
{
  PetscFunctionBegin;
  *p = ((PC_GDSW *)pc->data)->localPrecision;
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
  PetscAssertPointer(precision, 2);
  PetscUseMethod(pc, "PCGDSWGetLocalPrecision_C", (PC, PCGDSWLocalPrecision *), (pc, precision));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCGDSWSetHugePages_GDSW(PC pc, PetscBool flg)
{
  PetscFunctionBegin;
  ((PC_GDSW *)pc->data)->hugePages = flg;
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

static PetscErrorCode PCGDSWGetHugePages_GDSW(PC pc, PetscBool *flg)
{
  PetscFunctionBegin;
  *flg = ((PC_GDSW *)pc->data)->hugePages;
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
  PetscAssertPointer(flg, 2);
  PetscUseMethod(pc, "PCGDSWGetHugePages_C", (PC, PetscBool *), (pc, flg));
  PetscFunctionReturn(0);
}

/* The composed methods of the first level: added by PCCreate_GDSW(), removed by PCDestroy_GDSW(). */
PetscErrorCode GDSWComposeFirstLevelMethods(PC pc, PetscBool add)
{
  PetscObject o = (PetscObject)pc;

  PetscFunctionBegin;
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWSetFirstLevelType_C", add ? PCGDSWSetFirstLevelType_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetFirstLevelType_C", add ? PCGDSWGetFirstLevelType_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWSetLocalSolverType_C", add ? PCGDSWSetLocalSolverType_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetLocalSolverType_C", add ? PCGDSWGetLocalSolverType_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWSetLocalConditionMax_C", add ? PCGDSWSetLocalConditionMax_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetLocalConditionMax_C", add ? PCGDSWGetLocalConditionMax_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWSetLocalPrecision_C", add ? PCGDSWSetLocalPrecision_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetLocalPrecision_C", add ? PCGDSWGetLocalPrecision_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWSetHugePages_C", add ? PCGDSWSetHugePages_GDSW : nullptr));
  PetscCall(PetscObjectComposeFunction(o, "PCGDSWGetHugePages_C", add ? PCGDSWGetHugePages_GDSW : nullptr));
  PetscFunctionReturn(0);
}
