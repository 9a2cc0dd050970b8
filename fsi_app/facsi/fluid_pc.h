// SPDX-License-Identifier: BSD-2-Clause
/* PCFACSIFLUID: the fluid step of FaCSI (Deparis, Forti, Grandperrin, Quarteroni 2016) — the
   preconditioner of the fluid split (u, p, lambda) inside a multiplicative PCFIELDSPLIT over
   structure -> geometry -> fluid, which is the block lower triangle P_DN of the coupled
   Jacobian. On entry the split's residual already holds x_lambda - C2 y_s (the interface
   velocity of the structure's correction) and the fluid rows less the shape derivatives'
   action on y_g: PCFIELDSPLIT subtracts the lower blocks. This PC then
     1. condenses the interface: the velocity rows of Gamma become Dirichlet rows
        u_Gamma = x_lambda / c (c: the lambda row's velocity coefficient, 1 here),
     2. solves F^ (y_u, y_p) = (x_u with those rows replaced, x_p), F^ the fluid block with
        those rows of the identity, by the inner KSP (prefix -<prefix>dirichlet_: LU, or
        SIMPLE as a PCFIELDSPLIT Schur over velocity and pressure),
     3. recovers lambda from the interface momentum rows:
        y_lambda = (x_u - F y_u - B^T y_p)|_Gamma / g (g: the momentum row's lambda coefficient).
   With an exact inner solve this is the exact solve of the split, so the outer fieldsplit is
   P_DN^-1. The split's DM (KSPSetDM of the split's KSP) names its fields; the multiplier is
   the field called "multiplier" (-pc_facsi_fluid_multiplier_field), every other field is the
   fluid's. Each multiplier row must couple to exactly one velocity dof of its own rank (a nodal
   multiplier on conforming meshes). */
#pragma once

#include <petscksp.h>

#define PCFACSIFLUID "facsi_fluid"

namespace fsi {

PetscErrorCode PCRegisterFaCSIFluid();

/* The inner KSP of F^ (prefix -<prefix>dirichlet_), or null before the PC's first set-up. */
PetscErrorCode PCFaCSIFluidGetKSP(PC pc, KSP *ksp);

} // namespace fsi
