// SPDX-License-Identifier: BSD-2-Clause
/* Probes: a field's values over time at fixed reference points (the field's P1 or P2
   interpolant in the cell that holds the point): the pressure on the tube's axis, the wall's
   displacement at mid-length; and when a front first passes each of them (the wave speed of a
   pulse in an elastic tube). */
#pragma once

#include "discretization/cells.h"
#include <vector>

namespace fsi {

struct Probes {
  std::vector<PetscReal> X;      /* 3 per probe: the reference points */
  std::vector<PetscInt>  cell;   /* per probe: the index into the cells, -1 if another rank evaluates it */
  std::vector<PetscReal> lambda; /* 4 per probe: barycentric coordinates in that cell */
  PetscInt               nc = 1; /* components recorded */
  std::vector<PetscReal> t;      /* times recorded */
  std::vector<PetscReal> values; /* per time, nc per probe */
};

/* Find the cells of the points X (3 per point) among `cells`; a point in none is an error that
   names it and `option`. */
PetscErrorCode ProbesCreate(MPI_Comm comm, const FieldCells &cells, const std::vector<PetscReal> &X, const char *option, Probes &probes);

/* Record the field's values in the local state x (essential values inserted) at time t. */
PetscErrorCode ProbesRecord(MPI_Comm comm, const FieldCells &cells, const PetscScalar *x, PetscReal t, Probes &probes);

/* The same from the global vector x of dm (its essential values at time t inserted). */
PetscErrorCode ProbesRecordGlobal(DM dm, const FieldCells &cells, Vec x, PetscReal t, Probes &probes);

/* The time component 0 of each probe first rises through `level` (linear between the recorded
   times, from rest before the first), -1 if it never does. */
std::vector<PetscReal> ProbesArrival(const Probes &probes, PetscReal level);

} // namespace fsi
