/* The geometry block: the harmonic extension of the interface displacement into the fluid
   region (the seed's eq. 5), -Lap d_f = 0 with d_f given on the interface and d_f . n = 0 on the
   other fluid boundaries (for the tube's planar ends: the z component), P2 like the
   structure. The ALE fluid will move its mesh with d_f; here the block stands alone
   (-physics geometry) with the interface displacement prescribed. */
#pragma once

#include "discretization/cells.h"
#include "scene.h"
#include <petscsnes.h>

namespace fsi {

struct GeometryBlock {
  FieldCells cells;
  P2Rule     rule; /* degree 2: the P2 stiffness exactly */
};

/* Field `geometry`; `sc` must outlive the block. */
PetscErrorCode SetUpGeometry(const Scene &sc, DM dm, GeometryBlock &gb, PetscInt *field);

/* The verification field: d = a (x^2 - y^2, -2 x y, 0), harmonic, and zero in z on planes z = c. */
PetscErrorCode HarmonicQuadratic(PetscInt dim, PetscReal t, const PetscReal x[], PetscInt nc, PetscScalar *u, void *ctx);
void           HarmonicQuadraticSolution(const PetscReal x[3], const void *ctx, PetscReal u[3], PetscReal G[9]);

} // namespace fsi
