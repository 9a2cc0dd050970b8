// SPDX-License-Identifier: BSD-2-Clause
/* The structure block's residual and Jacobian, assembled cell by cell with the P2 element of
   discretization/p2tet.h: R(d) = int rho d_tt . v + int P(F) : grad v - int b . v
   + int_faces p n . v + int_support (k_s d + c_s d_t) . v, with d_t, d_tt the fully implicit
   differences of core/time_history.h and n the normal of the reference face (dead pressure) or
   of the deformed one (follower). The support is the surrounding tissue (a spring and a damper
   per unit reference area, Moireau et al. 2012), on every component or on the reference normal's. */
#pragma once

#include "discretization/cells.h"
#include "core/sparsity.h"
#include "core/time_history.h"
#include "structure/materials.h"
#include "structure/wall_frame.h"
#include <petscsnes.h>

namespace fsi {

struct StructureForms {
  MaterialLaw        law;
  PetscReal          param[MATERIAL_MAX_PARAM]; /* the law's parameters (see materials.h) */
  PetscReal          fibreAngle = -1;            /* >= 0: arterial fibres at this angle (radians) */
  const Centerline  *centerline = nullptr;      /* the fibres' frame (structure/wall_frame.h); nullptr: about the z-axis */
  std::vector<PetscInt> segment;                 /* per cell: its nearest centreline segment */
  std::vector<PetscReal> fibres;                 /* the centreline frame's fibres, 6 per quadrature point of each cell's rule */
  std::vector<PetscInt>  fibresAt;               /* per cell: its first in `fibres` */
  SNES               snes = nullptr;             /* told when a cell is inverted (det F <= 0) */
  PetscReal          mms = 0;                    /* amplitude of the manufactured solution (its body force), 0: none */
  DMLabel            region = nullptr;           /* cells of the wall (value 1), or all cells */
  FieldCells            cells;                      /* the block's cells, prepared for assembly */
  P2Rule             rule;                       /* stress and body force */
  P2Rule             curvedRule;                 /* the same on curved cells (structure/block.cxx says its degree) */
  PetscReal          mass[100];                  /* P2 mass matrix of the reference cell (volume 1/6) */
  std::vector<PetscInt>  curvedAt;               /* per cell: its mass's place in curvedMass, -1 if straight */
  std::vector<PetscReal> curvedMass;             /* 100 per curved cell, by quadrature (StructureCurvedMasses) */
  FaceRule           faceRule;
  PetscReal          pressure = 0;               /* on the faces of `loaded` (pushes along -n) */
  PetscBool          follower = PETSC_FALSE;     /* the pressure follows the deformed face */
  std::vector<CellFace> loaded;                    /* faces of -structure_pressure_group */
  PetscReal          load = 1;                   /* factor of the body force and the traction (pressure: already in it) */
  PetscReal          bodyForce[3] = {0, 0, 0};   /* per unit reference volume */
  PetscReal          traction[3]  = {0, 0, 0};   /* dead, per unit reference area, on tractionFaces */
  std::vector<CellFace> tractionFaces;
  PetscReal          spring = 0, damper = 0;     /* k_s, c_s of the tissue support */
  PetscBool          supportNormal = PETSC_FALSE; /* the support acts on d . n only */
  std::vector<CellFace> supported;                 /* faces of -structure_support_group */
  PetscReal          rho      = 0;               /* density: inertia when history has past states */
  const TimeHistory *history  = nullptr;
  PetscInt           inverted = 0;               /* quadrature points with det F <= 0 in the last residual */
};

/* Its rows of the residual (added into the local f; the residual records inverted cells in
   the forms) and of the Jacobian, for the local state x. */
/* The mass matrices of the curved cells, once: the reference one times |det E| serves the rest. */
void           StructureCurvedMasses(StructureForms &sb);
PetscErrorCode StructureResidual(StructureForms &sb, const PetscScalar *x, PetscScalar *f);
PetscErrorCode StructureJacobian(const StructureForms &sb, const PetscScalar *x, Mat P);
/* the entries StructureJacobian inserts */
void StructureCouplings(const StructureForms &sb, Sparsity &s);

} // namespace fsi
