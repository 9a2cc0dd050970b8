// SPDX-License-Identifier: BSD-2-Clause
/* The rows of the harmonic extension (the seed's eq. 5): -Lap d_f = 0 on the reference fluid
   region, component by component, P2 like the structure. The fluid's mesh moves with d_f
   (fluid/assembly.h). On the interface, d_f is given (prescribed motion) or its rows are the
   coupling's d_f = d_s (geometry/block.h). */
#pragma once

#include "discretization/cells.h"
#include "core/sparsity.h"
#include <petscsnes.h>

namespace fsi {

struct GeometryForms {
  FieldCells cells;
  P2Rule     rule; /* degree 2: the P2 stiffness exactly */
};

/* Its rows (the context is the GeometryForms): the cells' dropped rows are left out. */
PetscErrorCode GeometryResidual(const GeometryForms &gb, const PetscScalar *x, PetscScalar *f);
PetscErrorCode GeometryJacobian(const GeometryForms &gb, const PetscScalar *x, Mat P);
/* the entries GeometryJacobian inserts */
void GeometryCouplings(const GeometryForms &gb, Sparsity &s);

} // namespace fsi
