// SPDX-License-Identifier: BSD-2-Clause
/* Private data of PCGDSW. The setup is a pipeline of modules, each in its own file:
     decomposition.cxx  nonoverlapping subdomains Omega~_i and overlapping Omega_i^delta, their matrices
     interface.cxx      sharing sets, Dirichlet dofs, interface components, coarse numbering
     coarse_basis.cxx   Phi_Gamma per component, harmonic extension Phi_I, Phi's interface rows
     phi.cxx            Phi (and W = A Phi of a basis not harmonic for A) as an operator: interface rows assembled, interior rows as dense blocks
     coarse_operator.cxx A_0 = Phi^T A Phi
     coarse_solver.cxx  the solver of A_0
     first_level.cxx    local solvers on Omega_i^delta and their restriction/prolongation
   around them the PC object:
     gdsw.cxx           the operator's checks, setup order, the solve's check of its KSP, apply and
                        its transpose, view, creation, registration
     options.cxx        the -pc_gdsw_* options: one table row each, read and checked in one pass
     api_configuration.cxx, api_subdomains.cxx, api_coarse_space.cxx, api_first_level.cxx
                        the public functions with their manual pages, each beside the composed
                        method it calls
   and what the set-up asks of the machine and of PETSc, in platform/:
     platform/ordering.cxx      nested dissection of the node graph for the local factorisations
     platform/threads.cxx       one thread per rank while the set-up factors
     platform/huge_pages.cxx    the local factors on transparent huge pages
     platform/single_factor.cxx the first level's Cholesky factors kept in single precision
     platform/help_prefix.cxx   -help with the whole prefix of the inner solvers (PETSc 3.18 cuts long ones) */
#pragma once

#include <petscgdsw.h>
#include <petsc/private/pcimpl.h>
#include <petscsf.h>
#include <string>
#include <vector>

/* PETSc 3.20 replaced PetscValid{,Int,Bool,Real}Pointer() by PetscAssertPointer() and deprecated them */
#if PETSC_VERSION_LT(3, 20, 0)
  #define PetscAssertPointer(p, arg) PetscValidPointer(p, arg)
#endif

namespace gdsw {

enum ComponentKind { FACE = 0, EDGE = 1, VERTEX = 2 };

/* The two factored matrices of a subdomain: A(Omega_i^delta) of the first level and A_II of the
   harmonic extension. */
enum LocalMatrix { OVERLAPPING = 0, INTERIOR = 1 };

/* How a local matrix was factored, for -pc_view: CHOLESKY_SINGLE is a Cholesky factor kept in
   single precision (MATSOLVERCHOLMODSINGLE); LU_NOT_SPD is LU where Cholesky was asked for
   but the matrix is not symmetric positive definite; INCOMPLETE is ICC or ILU; OTHER is any other
   solver the options chose. */
enum Factorisation { UNFACTORED = 0, CHOLESKY, CHOLESKY_SINGLE, LU, LU_NOT_SPD, INCOMPLETE, OTHER };

/* A group of coarse basis functions, seen from one subdomain. For GDSW it is one interface
   component; for RGDSW one coarse node whose support is every component it is an ancestor of. */
struct CoarseGroup {
  PetscInt              rep;       /* global node id representing it (smallest node of its component) */
  std::vector<PetscInt> sharing;   /* sorted global ids of the subdomains sharing the component */
  ComponentKind         kind;
  PetscInt              ncols;     /* number of coarse functions */
  PetscInt              col0;      /* global index of the first one (-1 until numbered) */
  std::vector<PetscInt> support;   /* local node indices (into Subdomain::nodes) of its support */
  std::vector<PetscReal> weight;   /* partition-of-unity weight per support node (GDSW: 1) */
  std::vector<PetscReal> values;   /* Phi_Gamma on the support's non-Dirichlet dofs, column-major */
  PetscReal             center[3]; /* centroid of the component: origin of its rotations */
};

struct Subdomain {
  PetscInt gid = -1;                    /* global subdomain id */
  PetscInt leaf0 = 0;                   /* first leaf of its nodes in PC_GDSW::nodeSF */
  std::vector<PetscInt> nodes;          /* Omega~_i: sorted global node ids */
  IS  nonoverlap = nullptr;             /* Omega~_i as global dofs */
  IS  overlap = nullptr;                /* Omega_i^delta as global dofs */
  IS  ovlInU = nullptr;                 /* positions of Omega_i^delta's dofs within PC_GDSW::isU (several ranks) */
  /* interface view, filled by the interface module */
  std::vector<PetscInt> setOf;          /* per node: index into PC_GDSW::sets */
  std::vector<PetscInt> dirMask;        /* per node: bit c set if dof c is a Dirichlet dof */
  std::vector<PetscReal> nodeData;      /* per node: coordinates (dim) or null-space rows (nz*bs) */
  std::vector<CoarseGroup> groups;
  /* harmonic extension: A(Omega~_i, Omega~_i) is read in Aovl's rows, not copied */
  IS  nonInOvl = nullptr;               /* positions of Omega~_i's dofs within Omega_i^delta */
  std::vector<PetscInt> ovlToNon;       /* per dof of Omega_i^delta: its dof of Omega~_i, or -1 */
  Mat AII = nullptr, AIG = nullptr;
  IS  isI = nullptr, isG = nullptr;     /* local dofs of Omega~_i: interior / interface */
  Mat PhiG = nullptr, PhiI = nullptr;   /* dense: interface values, harmonic extension */
  std::vector<PetscScalar> WI;          /* (A Phi)_I, nI x ncols row-major, where Phi is not harmonic for A and W is used */
  /* first level */
  Mat Aovl = nullptr;                   /* A(Omega_i^delta, Omega_i^delta) */
  KSP ksp = nullptr;
  Factorisation factorisation[2] = {UNFACTORED, UNFACTORED}; /* per LocalMatrix */
  Vec x = nullptr, y = nullptr;         /* views into the work vectors (arrays placed in apply) */
  PetscInt wOffset = 0;                 /* start of its slice of the concatenated work vector */
  PetscInt intOffset = 0, colOffset = 0; /* start of its slices of Phi's interior and column work vectors */
  std::vector<PetscInt> rowRank;        /* per row of Aovl: its node's place in the nested dissection */
};

} // namespace gdsw

typedef struct {
  /* options */
  PCGDSWConfiguration   configuration;    /* -pc_gdsw_configuration: the last one set */
  PetscInt              nsubPerRank;      /* -pc_gdsw_subdomains, or PETSC_DECIDE: the size rule */
  PetscBool             repartition;      /* -pc_gdsw_repartition: algebraic subdomains from a parallel partition of the whole graph */
  PetscInt              subdomainSize;    /* -pc_gdsw_subdomain_size: target dofs per subdomain of the rule, or PETSC_DECIDE: by the local solver */
  PCGDSWLocalSolverType localSolver;      /* -pc_gdsw_local_solver */
  PetscReal             conditionMax;     /* -pc_gdsw_local_condition_max: the adaptive first level's bound */
  PCGDSWLocalPrecision  localPrecision;   /* -pc_gdsw_local_precision: of the first level's Cholesky factors */
  PetscInt              overlap;          /* -pc_gdsw_overlap */
  PCGDSWCoarseSpaceType coarseType;
  PCCompositeType       combination;    /* additive, multiplicative or symmetric multiplicative */
  PCGDSWFirstLevelType  firstLevel;
  PetscBool             rotations;
  PCGDSWRGDSWWeightType rgdswWeights;
  PetscBool             reuseCoarseBasis;
  PetscBool             hugePages;        /* -pc_gdsw_huge_pages: the set-up's large blocks on transparent huge pages */
  /* input */
  PetscInt  nUser;                        /* user subdomains (PCGDSWSetSubdomains), -1 if none */
  IS       *userNon, *userOvl;
  PetscInt  coordDim, nCoordNodes;        /* PCSetCoordinates */
  PetscReal *coords;
  /* derived */
  Mat       A;                            /* the operator as (MPI)AIJ */
  PetscInt  bs;                           /* dofs per node */
  PetscBool symmetric;                    /* chooses Cholesky for the default solvers */
  PetscInt  nz;                           /* null-space vectors per node */
  PetscBool haveCoords;                   /* nodeData holds coordinates (rigid modes built here) */
  PetscInt  dataWidth;                    /* reals per node in nodeData */
  std::vector<gdsw::Subdomain> *sub;
  std::vector<std::vector<PetscInt>> *sets; /* distinct sharing sets seen on this rank */
  PetscInt  nGlobalSubdomains;
  IS        isU;                          /* U: the union of the rank's overlapping subdomains (several ranks) */
  Mat      *AU;                           /* A(U, U), kept for the set-ups with the same pattern */
  IS       *nonArr, *ovlArr;              /* the subdomains' index sets as arrays, for PCGDSWGetSubdomains() */
  PetscInt  nsubRank0;                    /* subdomains on rank 0, for the view */
  PetscBool balanced;                     /* algebraic subdomains moved between ranks whose rows are unbalanced */
  char      partitioner[64];              /* the MatPartitioning type that repartitioned the graph */
  PetscSF   nodeSF;                       /* leaves: nodes of every local Omega~_i; roots: owned nodes */
  PetscInt  nDirichletRows;               /* global count */
  std::vector<PetscInt> *dirichletMask;   /* per owned node, its Dirichlet components as bits (the last fresh set-up's) */
  PetscInt  counts[3];                    /* faces, edges, vertices (global) */
  size_t    hugeBytes;                    /* given out on huge pages by the last set-up (this rank) */
  /* coarse level */
  Mat Phi, A0;                            /* Phi: the operator of phi.cxx */
  Mat PhiGamma;                           /* Phi's interface rows (AIJ, the kept columns) */
  Mat PhiAssembled;                       /* Phi as AIJ, made when asked for (PCGDSWGetCoarseBasis()) */
  VecScatter phiCols, phiInterior;        /* coarse vector -> the subdomains' columns; global -> their interior rows */
  Vec phiColsWork, phiIntWork;
  PetscInt nColsFull, nColsFullLocal;     /* Phi's columns before dropping zero ones (global, this rank's) */
  Mat APhiGamma;                          /* W's interface rows (AIJ) */
  Mat APhi;                               /* W = A Phi, for the balanced combination: APhiGamma, or the operator of phi.cxx with (A Phi)_I */
  PetscBool exactExtension;               /* every interior solve of the last extension was a direct factorisation */
  IS  keptCols;
  KSP coarseKsp;
  Vec r0, x0, c0;                         /* coarse work (c0: the balanced combination's first correction) */
  PetscInt coarseDim;
  PetscBool coarseActive;                 /* a coarse level exists (type not none, dimension > 0) */
  /* first level */
  Vec        work, workOut;               /* concatenated subdomain vectors */
  VecScatter restrictTo, prolongFrom;     /* global -> work, work(subset) -> global */
  Vec        tmp1, tmp2;                  /* global-size work for the multiplicative and balanced combinations */
} PC_GDSW;

/* the PC object (gdsw.cxx), its options (options.cxx) and the composed methods of its public
   functions (api_*.cxx) */
PETSC_INTERN PetscErrorCode GDSWSetFromOptions(PC, PetscOptionItems *);
PETSC_INTERN PetscErrorCode GDSWComposeSubdomainMethods(PC, PetscBool);
PETSC_INTERN PetscErrorCode GDSWComposeCoarseSpaceMethods(PC, PetscBool);
PETSC_INTERN PetscErrorCode GDSWComposeFirstLevelMethods(PC, PetscBool);
PETSC_INTERN PetscErrorCode GDSWComposeConfigurationMethods(PC, PetscBool);
PETSC_INTERN PetscErrorCode GDSWDestroyUserSubdomains(PC_GDSW *);
PETSC_INTERN PetscErrorCode GDSWCheckSetUp(PC);
PETSC_INTERN PetscErrorCode GDSWCheckEnum(PC, PetscEnum, PetscEnum, const char *const *);
PETSC_INTERN std::string    GDSWOptionName(PC, const char[]); /* "-" + the PC's prefix + name without its "-" */
PETSC_INTERN const char *const GDSWCombinationTypes[];
/* what each numeric option takes: the end of the messages of the setter and of options.cxx */
PETSC_INTERN const char GDSWSubdomainsTakes[], GDSWSubdomainSizeTakes[], GDSWOverlapTakes[], GDSWConditionMaxTakes[];

/* module entry points */
/* the local Cholesky factorisations' ordering: nested dissection of the node graph */
#define MATORDERINGGDSWNODES "gdsw_nodes"

PETSC_INTERN PetscErrorCode GDSWBuildDecomposition(PC);
PETSC_INTERN PetscErrorCode GDSWExtractSubdomainMatrices(PC, MatReuse);
PETSC_INTERN PetscErrorCode GDSWSubmatrix(Mat, IS, IS, PetscInt, MatReuse, Mat *);
PETSC_INTERN PetscErrorCode GDSWBuildInterface(PC);
PETSC_INTERN PetscErrorCode GDSWDirichletRowsChanged(PC, PetscBool *);
PETSC_INTERN PetscErrorCode GDSWBuildCoarseBasis(PC);
PETSC_INTERN PetscErrorCode GDSWUpdateCoarseBasis(PC);
PETSC_INTERN PetscErrorCode GDSWAssemblePhiMatrix(PC);
PETSC_INTERN PetscErrorCode GDSWCreatePhiOperator(PC);
PETSC_INTERN PetscErrorCode GDSWCreateAPhiOperator(PC);
/* Phi's numbering: a subdomain's columns (through kept, see GDSWKeptColumns(); -1 where dropped),
   the global rows of its local dofs, and kept[j], the place of column j among the kept ones */
PETSC_INTERN std::vector<PetscInt> GDSWPhiColumns(const gdsw::Subdomain &, const std::vector<PetscInt> &);
PETSC_INTERN PetscErrorCode GDSWGlobalRows(PC, const gdsw::Subdomain &, IS, std::vector<PetscInt> &);
PETSC_INTERN PetscErrorCode GDSWKeptColumns(PC, std::vector<PetscInt> &);
PETSC_INTERN PetscErrorCode GDSWAssembleCoarseOperator(PC, PetscBool);
PETSC_INTERN PetscErrorCode GDSWSetUpCoarseSolver(PC, PetscBool);
PETSC_INTERN PetscErrorCode GDSWSetUpFirstLevel(PC, MatReuse);
PETSC_INTERN PetscErrorCode GDSWApplyFirstLevel(PC, Vec, Vec, PetscBool);
PETSC_INTERN PetscErrorCode GDSWApplyCoarse(PC, Vec, Vec, PetscBool);
PETSC_INTERN PetscErrorCode GDSWApplyBalanced(PC, Vec, Vec, PetscBool);
PETSC_INTERN PetscErrorCode GDSWDefaultFactorSolver(KSP, MatSolverType, PetscBool);
PETSC_INTERN PetscErrorCode GDSWSetUpLocalSolver(PC, KSP, gdsw::Subdomain &, gdsw::LocalMatrix);
PETSC_INTERN PetscErrorCode GDSWViewLocalSolvers(PC, PetscViewer);
PETSC_INTERN PetscErrorCode GDSWComposeRowRanks(PC, gdsw::Subdomain &, gdsw::LocalMatrix, Mat);
PETSC_INTERN PetscErrorCode GDSWRegisterOrdering(void);
PETSC_INTERN PetscErrorCode GDSWCheckMetisSize(PetscCount);
/* MATSOLVERCHOLMODSINGLE hands PETSc's arrays to CHOLMOD's real double interface (int or long) */
#if defined(PETSC_USE_COMPLEX) || !defined(PETSC_USE_REAL_DOUBLE)
  #define GDSW_HAVE_SINGLE_FACTOR 0
#else
  #define GDSW_HAVE_SINGLE_FACTOR 1
#endif
PETSC_INTERN PetscErrorCode GDSWRegisterSingleFactor(void);
PETSC_INTERN PetscErrorCode GDSWFactorIsSingle(Mat, PetscBool *);
PETSC_INTERN PetscErrorCode GDSWSerialRegionsBegin(PetscInt *);
PETSC_INTERN PetscErrorCode GDSWSerialRegionsEnd(PetscInt);
PETSC_INTERN PetscErrorCode GDSWKSPSetFromOptions(KSP); /* KSPSetFromOptions(), -help with the whole prefix */
PETSC_INTERN PetscErrorCode GDSWHugePagesBegin(PC, PetscBool, PetscBool *, size_t *);
PETSC_INTERN PetscErrorCode GDSWHugePagesEnd(PetscBool, size_t, size_t *);
PETSC_INTERN void          *GDSWHugeMalloc(size_t);
PETSC_INTERN void           GDSWHugeFree(void *);
PETSC_INTERN PetscInt       GDSWSubdomainSizeTarget(const PC_GDSW *);

PETSC_INTERN PetscLogEvent GDSW_Decomposition, GDSW_Interface, GDSW_Basis, GDSW_Extension,
  GDSW_CoarseSetUp, GDSW_LocalFactor, GDSW_Apply, GDSW_ApplyLocal, GDSW_ApplyCoarse;
