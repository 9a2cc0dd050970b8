// SPDX-License-Identifier: BSD-2-Clause
/* petscgdsw.h: the two-level overlapping Schwarz preconditioner PCGDSW for PETSc.
   Use it from any PETSc program with -pc_type gdsw after either
     -dll_append <prefix>/lib/libpetscgdsw.so   (no code change), or
     PCGDSWRegister()                           (when linking the library).
   The manual pages are in pc_gdsw/src/api_*.cxx and (PCGDSW) pc_gdsw/src/gdsw.cxx. */
#ifndef PETSCGDSW_H
#define PETSCGDSW_H

#include <petscksp.h>

#define PCGDSW "gdsw"

/* A Cholesky factorisation (MatSolverType) of sequential AIJ matrices: CHOLMOD's factor, kept and
   applied in single precision where that solves to within 1e-3 of the double one. */
#define MATSOLVERCHOLMODSINGLE "cholmod_single"

/* Which coarse space the second level uses. */
typedef enum {
  PC_GDSW_COARSE_GDSW,  /* null space on every interface component (faces, edges, vertices) */
  PC_GDSW_COARSE_RGDSW, /* reduced dimension: null space on coarse nodes, partition of unity */
  PC_GDSW_COARSE_NONE   /* one-level overlapping Schwarz (OS1) */
} PCGDSWCoarseSpaceType;
PETSC_EXTERN const char *const PCGDSWCoarseSpaceTypes[];

/* How local corrections are prolongated. */
typedef enum {
  PC_GDSW_FIRST_LEVEL_ADDITIVE,  /* R_i^T on the whole overlapping subdomain (symmetric) */
  PC_GDSW_FIRST_LEVEL_RESTRICTED /* restricted to a nonoverlapping partition (RAS) */
} PCGDSWFirstLevelType;
PETSC_EXTERN const char *const PCGDSWFirstLevelTypes[];

/* RGDSW's partition of unity on an interface component shared by several coarse nodes
   (Dohrmann & Widlund 2017). */
typedef enum {
  PC_GDSW_RGDSW_WEIGHTS_EQUAL,   /* option 1: 1 / (number of coarse nodes) */
  PC_GDSW_RGDSW_WEIGHTS_DISTANCE /* option 2.2: proportional to 1 / (distance to the coarse node); needs coordinates */
} PCGDSWRGDSWWeightType;
PETSC_EXTERN const char *const PCGDSWRGDSWWeightTypes[];

/* What solves the overlapping subdomain problems of the first level (unless -pc_gdsw_sub_pc_type
   says otherwise). */
typedef enum {
  PC_GDSW_LOCAL_EXACT,      /* Cholesky (CHOLMOD) for symmetric operators, LU (UMFPACK) otherwise */
  PC_GDSW_LOCAL_INCOMPLETE, /* ICC(0) for symmetric operators, ILU(0) otherwise */
  PC_GDSW_LOCAL_ADAPTIVE    /* incomplete where its condition estimate is small enough, exact elsewhere */
} PCGDSWLocalSolverType;
PETSC_EXTERN const char *const PCGDSWLocalSolverTypes[];

/* The precision the first level's Cholesky factors are kept and applied in. */
typedef enum {
  PC_GDSW_LOCAL_PRECISION_DOUBLE, /* CHOLMOD's factor as it is (the default) */
  PC_GDSW_LOCAL_PRECISION_SINGLE  /* MATSOLVERCHOLMODSINGLE: single precision where it solves to within 1e-3 of double; for CG, FGMRES */
} PCGDSWLocalPrecision;
PETSC_EXTERN const char *const PCGDSWLocalPrecisions[];

/* The local solvers and the coarse space together (PCGDSWSetConfiguration()). */
typedef enum {
  PC_GDSW_CONFIGURATION_ROBUST, /* exact local solvers, GDSW coarse space (the default) */
  PC_GDSW_CONFIGURATION_FAST    /* adaptive local solvers, RGDSW coarse space: near an AMG's cost on benign elasticity, less robust */
} PCGDSWConfiguration;
PETSC_EXTERN const char *const PCGDSWConfigurations[];

PETSC_EXTERN PetscErrorCode PCGDSWRegister(void);

/* the configuration */
PETSC_EXTERN PetscErrorCode PCGDSWSetConfiguration(PC, PCGDSWConfiguration);
PETSC_EXTERN PetscErrorCode PCGDSWGetConfiguration(PC, PCGDSWConfiguration *);

/* the decomposition */
PETSC_EXTERN PetscErrorCode PCGDSWSetSubdomains(PC, PetscInt, IS[], IS[]);
PETSC_EXTERN PetscErrorCode PCGDSWGetSubdomains(PC, PetscInt *, IS *[], IS *[]);
PETSC_EXTERN PetscErrorCode PCGDSWSetSubdomainsPerRank(PC, PetscInt);
PETSC_EXTERN PetscErrorCode PCGDSWGetSubdomainsPerRank(PC, PetscInt *);
PETSC_EXTERN PetscErrorCode PCGDSWSetRepartition(PC, PetscBool);
PETSC_EXTERN PetscErrorCode PCGDSWGetRepartition(PC, PetscBool *);
PETSC_EXTERN PetscErrorCode PCGDSWSetSubdomainSize(PC, PetscInt);
PETSC_EXTERN PetscErrorCode PCGDSWGetSubdomainSize(PC, PetscInt *);
PETSC_EXTERN PetscErrorCode PCGDSWSetOverlap(PC, PetscInt);
PETSC_EXTERN PetscErrorCode PCGDSWGetOverlap(PC, PetscInt *);

/* the first level's local solvers */
PETSC_EXTERN PetscErrorCode PCGDSWSetLocalSolverType(PC, PCGDSWLocalSolverType);
PETSC_EXTERN PetscErrorCode PCGDSWGetLocalSolverType(PC, PCGDSWLocalSolverType *);
PETSC_EXTERN PetscErrorCode PCGDSWSetLocalConditionMax(PC, PetscReal);
PETSC_EXTERN PetscErrorCode PCGDSWGetLocalConditionMax(PC, PetscReal *);
PETSC_EXTERN PetscErrorCode PCGDSWSetLocalPrecision(PC, PCGDSWLocalPrecision);
PETSC_EXTERN PetscErrorCode PCGDSWGetLocalPrecision(PC, PCGDSWLocalPrecision *);

/* the coarse space and how the levels are combined */
PETSC_EXTERN PetscErrorCode PCGDSWSetCoarseSpaceType(PC, PCGDSWCoarseSpaceType);
PETSC_EXTERN PetscErrorCode PCGDSWGetCoarseSpaceType(PC, PCGDSWCoarseSpaceType *);
PETSC_EXTERN PetscErrorCode PCGDSWSetRGDSWWeightType(PC, PCGDSWRGDSWWeightType);
PETSC_EXTERN PetscErrorCode PCGDSWGetRGDSWWeightType(PC, PCGDSWRGDSWWeightType *);
PETSC_EXTERN PetscErrorCode PCGDSWSetRotations(PC, PetscBool);
PETSC_EXTERN PetscErrorCode PCGDSWGetRotations(PC, PetscBool *);
/* how the coarse correction Q0 and the local solves M1 are combined, as PCCOMPOSITE combines its
   PCs: PC_COMPOSITE_ADDITIVE (Q0 + M1), PC_COMPOSITE_MULTIPLICATIVE (Q0, then M1 on the updated
   residual) or PC_COMPOSITE_SYMMETRIC_MULTIPLICATIVE (Q0, M1, Q0: symmetric; the default) */
PETSC_EXTERN PetscErrorCode PCGDSWSetCombinationType(PC, PCCompositeType);
PETSC_EXTERN PetscErrorCode PCGDSWGetCombinationType(PC, PCCompositeType *);
PETSC_EXTERN PetscErrorCode PCGDSWSetFirstLevelType(PC, PCGDSWFirstLevelType);
PETSC_EXTERN PetscErrorCode PCGDSWGetFirstLevelType(PC, PCGDSWFirstLevelType *);
PETSC_EXTERN PetscErrorCode PCGDSWSetReuseCoarseBasis(PC, PetscBool);
PETSC_EXTERN PetscErrorCode PCGDSWGetReuseCoarseBasis(PC, PetscBool *);
PETSC_EXTERN PetscErrorCode PCGDSWSetHugePages(PC, PetscBool);
PETSC_EXTERN PetscErrorCode PCGDSWGetHugePages(PC, PetscBool *);

/* after PCSetUp(): borrowed references */
PETSC_EXTERN PetscErrorCode PCGDSWGetCoarseBasis(PC, Mat *);
PETSC_EXTERN PetscErrorCode PCGDSWGetCoarseOperator(PC, Mat *);
PETSC_EXTERN PetscErrorCode PCGDSWGetCoarseKSP(PC, KSP *);
PETSC_EXTERN PetscErrorCode PCGDSWGetInterfaceCounts(PC, PetscInt *, PetscInt *, PetscInt *);

#endif
