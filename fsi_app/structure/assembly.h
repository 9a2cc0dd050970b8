/* The structure block's residual and Jacobian, assembled cell by cell with the P2 element of
   discretization/p2tet.h: R(d) = int rho (d - 2 d^n + d^(n-1))/dt^2 . v + int P(F) : grad v
   - int b . v + int_faces p n . v (fully implicit backward differences in time). */
#pragma once

#include "discretization/p2tet.h"
#include "structure/materials.h"
#include <petscsnes.h>

namespace fsi {

struct StructureBlock {
  MaterialLaw law;
  PetscReal   param[2];              /* the law's parameters (see materials.h) */
  SNES        snes = nullptr;        /* told when a cell is inverted (det F <= 0) */
  PetscBool   mms = PETSC_FALSE;     /* body force of the manufactured solution */
  DMLabel     region = nullptr;      /* cells of the wall (value 1), or all cells */
  P2Rule      rule;
  FaceRule    faceRule;
  PetscReal   pressure = 0;          /* dead pressure on the faces of `loaded` (pushes along -n) */
  PetscReal   inertia = 0;           /* rho / dt^2 (dynamics), 0 for statics */
  Vec         previous[2] = {nullptr, nullptr}; /* local d^n, d^(n-1): inertia (d - 2 d^n + d^(n-1)) */
  DMLabel     loaded = nullptr;
};

/* DMSNES local callbacks (the context is the StructureBlock). */
PetscErrorCode StructureResidual(DM dm, Vec X, Vec F, void *ctx);
PetscErrorCode StructureJacobian(DM dm, Vec X, Mat J, Mat P, void *ctx);

} // namespace fsi
