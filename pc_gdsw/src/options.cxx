// SPDX-License-Identifier: BSD-2-Clause
/* The -pc_gdsw_* options: one table row per option, read in one pass. PETSc's parsers reject a
   malformed value on every rank, each printing a message that names neither the option nor (for
   numbers) what it takes; so each value is parsed here first, once for the PC, then handed to its
   public setter, which checks its range with a sentence naming the option. */
#include "gdswimpl.h"
#include <string>

/* the PCCompositeType values PCGDSW takes, in their order in PCCompositeTypes[] */
const char *const GDSWCombinationTypes[] = {"additive", "multiplicative", "symmetric_multiplicative", "PCCompositeType", "PC_COMPOSITE_", nullptr};

namespace {

union Value {
  PetscInt  i;
  PetscReal r;
  PetscBool b;
  PetscEnum e;
};

struct Option {
  const char        *name;  /* without the PC's prefix */
  const char        *help;  /* -help's text */
  const char        *man;   /* the setter, whose manual page -help names */
  PetscOptionType    kind;  /* OPTION_INT, OPTION_REAL, OPTION_BOOL or OPTION_ELIST */
  const char *const *list;  /* OPTION_ELIST: the values, then the type's name and prefix */
  const char        *takes; /* OPTION_INT, OPTION_REAL: the end of the message on a malformed value */
  PetscErrorCode (*get)(PC, Value *);
  PetscErrorCode (*set)(PC, Value);
};

/* -pc_gdsw_configuration comes first: it sets the defaults of -pc_gdsw_local_solver and
   -pc_gdsw_coarse_space, which then override it; -pc_gdsw_local_solver next: the size rule's
   default target, which -help shows for -pc_gdsw_subdomain_size, depends on it. */
const Option Options[] = {
  {"-pc_gdsw_configuration", "Local solvers and coarse space together: robust (exact, GDSW) or fast (adaptive, RGDSW: near an AMG's cost on benign elasticity, less robust); -pc_gdsw_local_solver and -pc_gdsw_coarse_space override it",
   "PCGDSWSetConfiguration", OPTION_ELIST, PCGDSWConfigurations, nullptr,
   [](PC pc, Value *v) { return PCGDSWGetConfiguration(pc, (PCGDSWConfiguration *)&v->e); }, [](PC pc, Value v) { return PCGDSWSetConfiguration(pc, (PCGDSWConfiguration)v.e); }},
  {"-pc_gdsw_local_solver", "First level's local solvers: exact factorisations, incomplete ones (ICC(0)/ILU(0)), or adaptive: incomplete where its condition estimate is at most -pc_gdsw_local_condition_max, exact elsewhere",
   "PCGDSWSetLocalSolverType", OPTION_ELIST, PCGDSWLocalSolverTypes, nullptr,
   [](PC pc, Value *v) { return PCGDSWGetLocalSolverType(pc, (PCGDSWLocalSolverType *)&v->e); }, [](PC pc, Value v) { return PCGDSWSetLocalSolverType(pc, (PCGDSWLocalSolverType)v.e); }},
  {"-pc_gdsw_local_condition_max", "Adaptive local solvers: the largest condition estimate of an incomplete factor's preconditioned subdomain matrix that keeps it",
   "PCGDSWSetLocalConditionMax", OPTION_REAL, nullptr, GDSWConditionMaxTakes,
   [](PC pc, Value *v) { return PCGDSWGetLocalConditionMax(pc, &v->r); }, [](PC pc, Value v) { return PCGDSWSetLocalConditionMax(pc, v.r); }},
  {"-pc_gdsw_local_precision", "Precision the first level's Cholesky factors are kept and applied in: double, or single where that solves to within 1e-3 of double (MATSOLVERCHOLMODSINGLE; for CG and FGMRES: GMRES then stalls, near a relative residual of 1e-5 on elasticity)",
   "PCGDSWSetLocalPrecision", OPTION_ELIST, PCGDSWLocalPrecisions, nullptr,
   [](PC pc, Value *v) { return PCGDSWGetLocalPrecision(pc, (PCGDSWLocalPrecision *)&v->e); }, [](PC pc, Value v) { return PCGDSWSetLocalPrecision(pc, (PCGDSWLocalPrecision)v.e); }},
  {"-pc_gdsw_subdomains", "Subdomains per MPI rank (METIS on the rank's node graph); -1 (PETSC_DECIDE): about -pc_gdsw_subdomain_size dofs each",
   "PCGDSWSetSubdomainsPerRank", OPTION_INT, nullptr, GDSWSubdomainsTakes,
   [](PC pc, Value *v) { return PCGDSWGetSubdomainsPerRank(pc, &v->i); }, [](PC pc, Value v) { return PCGDSWSetSubdomainsPerRank(pc, v.i); }},
  {"-pc_gdsw_repartition", "Subdomains from a parallel partition of the whole matrix graph (MatPartitioning, options -pc_gdsw_mat_partitioning_*) instead of METIS within each rank's rows",
   "PCGDSWSetRepartition", OPTION_BOOL, nullptr, nullptr,
   [](PC pc, Value *v) { return PCGDSWGetRepartition(pc, &v->b); }, [](PC pc, Value v) { return PCGDSWSetRepartition(pc, v.b); }},
  {"-pc_gdsw_subdomain_size", "Target dofs per subdomain when -pc_gdsw_subdomains is not given (the fastest on 3D elasticity here: 12000 with exact local solvers, 3000 with incomplete or adaptive ones)",
   "PCGDSWSetSubdomainSize", OPTION_INT, nullptr, GDSWSubdomainSizeTakes,
   [](PC pc, Value *v) { return PCGDSWGetSubdomainSize(pc, &v->i); }, [](PC pc, Value v) { return PCGDSWSetSubdomainSize(pc, v.i); }},
  {"-pc_gdsw_overlap", "Overlap in layers of the matrix graph (used when the caller gives no overlapping subdomains)",
   "PCGDSWSetOverlap", OPTION_INT, nullptr, GDSWOverlapTakes,
   [](PC pc, Value *v) { return PCGDSWGetOverlap(pc, &v->i); }, [](PC pc, Value v) { return PCGDSWSetOverlap(pc, v.i); }},
  {"-pc_gdsw_coarse_space", "Coarse space",
   "PCGDSWSetCoarseSpaceType", OPTION_ELIST, PCGDSWCoarseSpaceTypes, nullptr,
   [](PC pc, Value *v) { return PCGDSWGetCoarseSpaceType(pc, (PCGDSWCoarseSpaceType *)&v->e); }, [](PC pc, Value v) { return PCGDSWSetCoarseSpaceType(pc, (PCGDSWCoarseSpaceType)v.e); }},
  {"-pc_gdsw_rgdsw_weights", "RGDSW partition of unity: equal (option 1) or by inverse distance to the coarse nodes (option 2.2, needs coordinates)",
   "PCGDSWSetRGDSWWeightType", OPTION_ELIST, PCGDSWRGDSWWeightTypes, nullptr,
   [](PC pc, Value *v) { return PCGDSWGetRGDSWWeightType(pc, (PCGDSWRGDSWWeightType *)&v->e); }, [](PC pc, Value v) { return PCGDSWSetRGDSWWeightType(pc, (PCGDSWRGDSWWeightType)v.e); }},
  {"-pc_gdsw_rotations", "Use the rotations of the null space (false: GDSW-nr, translations only)",
   "PCGDSWSetRotations", OPTION_BOOL, nullptr, nullptr,
   [](PC pc, Value *v) { return PCGDSWGetRotations(pc, &v->b); }, [](PC pc, Value v) { return PCGDSWSetRotations(pc, v.b); }},
  {"-pc_gdsw_combination", "How the coarse and local corrections are combined",
   "PCGDSWSetCombinationType", OPTION_ELIST, GDSWCombinationTypes, nullptr,
   [](PC pc, Value *v) { return PCGDSWGetCombinationType(pc, (PCCompositeType *)&v->e); }, [](PC pc, Value v) { return PCGDSWSetCombinationType(pc, (PCCompositeType)v.e); }},
  {"-pc_gdsw_first_level_type", "Plain additive (symmetric) or restricted (RAS) prolongation of the local corrections",
   "PCGDSWSetFirstLevelType", OPTION_ELIST, PCGDSWFirstLevelTypes, nullptr,
   [](PC pc, Value *v) { return PCGDSWGetFirstLevelType(pc, (PCGDSWFirstLevelType *)&v->e); }, [](PC pc, Value v) { return PCGDSWSetFirstLevelType(pc, (PCGDSWFirstLevelType)v.e); }},
  {"-pc_gdsw_reuse_coarse_basis", "Keep Phi when the operator's values change; recompute only A_0 = Phi^T A Phi",
   "PCGDSWSetReuseCoarseBasis", OPTION_BOOL, nullptr, nullptr,
   [](PC pc, Value *v) { return PCGDSWGetReuseCoarseBasis(pc, &v->b); }, [](PC pc, Value v) { return PCGDSWSetReuseCoarseBasis(pc, v.b); }},
  {"-pc_gdsw_huge_pages", "During set-up, the blocks of 2 MiB or more it keeps (local factors, subdomain matrices) on transparent huge pages where the kernel gives them on request (mode madvise)",
   "PCGDSWSetHugePages", OPTION_BOOL, nullptr, nullptr,
   [](PC pc, Value *v) { return PCGDSWGetHugePages(pc, &v->b); }, [](PC pc, Value v) { return PCGDSWSetHugePages(pc, v.b); }},
};

/* Stops, once for the PC, on a value of o that its parser would reject or that is not finite. */
PetscErrorCode CheckParses(PC pc, const Option &o)
{
  char           value[256];
  PetscBool      set, ok = PETSC_TRUE;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscCall(PetscOptionsGetString(((PetscObject)pc)->options, ((PetscObject)pc)->prefix, o.name, value, sizeof(value), &set));
  if (!set) PetscFunctionReturn(0);
  std::string allowed;
  if (o.kind == OPTION_ELIST) {
    PetscEnum e;
    PetscCall(PetscEnumFind(o.list, value, &e, &ok));
    allowed = "one of:";
    for (PetscInt i = 0; o.list[i + 2]; i++) allowed += std::string(i ? ", " : " ") + o.list[i]; /* the list ends with its type name, prefix, NULL */
  } else if (o.kind != OPTION_BOOL || value[0]) { /* a logical option without a value is true */
    PetscInt  i;
    PetscReal r = 0;
    PetscBool b;
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
    ierr = o.kind == OPTION_INT ? PetscOptionsStringToInt(value, &i) : o.kind == OPTION_REAL ? PetscOptionsStringToReal(value, &r) : PetscOptionsStringToBool(value, &b);
    PetscCall(PetscPopErrorHandler());
    ok      = (PetscBool)(!ierr && !PetscIsInfOrNanReal(r));
    allowed = o.kind == OPTION_INT ? std::string("an integer: ") + o.takes : o.kind == OPTION_REAL ? std::string("a number: ") + o.takes : "true or false";
  }
  PetscCheck(ok, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_WRONG, "PCGDSW: %s %s is not %s", GDSWOptionName(pc, o.name).c_str(), value[0] ? value : "(no value)", allowed.c_str());
  PetscFunctionReturn(0);
}

/* The PetscOptions* macros name their context PetscOptionsObject. */
PetscErrorCode ReadOption(PC pc, PetscOptionItems *PetscOptionsObject, const Option &o)
{
  Value     now, v;
  PetscBool set;

  PetscFunctionBegin;
  PetscCall(CheckParses(pc, o));
  PetscCall(o.get(pc, &now));
  switch (o.kind) {
  case OPTION_INT:
    PetscCall(PetscOptionsInt(o.name, o.help, o.man, now.i, &v.i, &set));
    break;
  case OPTION_REAL:
    PetscCall(PetscOptionsReal(o.name, o.help, o.man, now.r, &v.r, &set));
    break;
  case OPTION_BOOL:
    PetscCall(PetscOptionsBool(o.name, o.help, o.man, now.b, &v.b, &set));
    break;
  default:
    PetscCall(PetscOptionsEnum(o.name, o.help, o.man, o.list, now.e, &v.e, &set));
  }
  if (set) PetscCall(o.set(pc, v));
  PetscFunctionReturn(0);
}

} // namespace

std::string GDSWOptionName(PC pc, const char name[])
{
  const char *prefix = ((PetscObject)pc)->prefix;
  return std::string("-") + (prefix ? prefix : "") + (name + 1);
}

/* An enum value from the API (the options are checked by name in CheckParses()). */
PetscErrorCode GDSWCheckEnum(PC pc, PetscEnum value, PetscEnum last, const char *const *list)
{
  PetscFunctionBegin;
  PetscCheck(value >= 0 && value <= last, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE, "PCGDSW: %d is not a valid %s", (int)value, list[last + 1]);
  PetscFunctionReturn(0);
}

PetscErrorCode GDSWSetFromOptions(PC pc, PetscOptionItems *PetscOptionsObject)
{
  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "GDSW two-level overlapping Schwarz options");
  for (const Option &o : Options) PetscCall(ReadOption(pc, PetscOptionsObject, o));
  PetscOptionsHeadEnd();
  PetscFunctionReturn(0);
}
