/* Pressure probes: the fluid's pressure over time at fixed reference points (the P1 interpolant
   of the cell that holds the point), and when a pressure front first passes each of them — the
   wave speed of a pulse in an elastic tube. */
#pragma once

#include "discretization/cells.h"
#include <vector>

namespace fsi {

struct PressureProbes {
  std::vector<PetscReal> X;       /* 3 per probe: the reference points */
  std::vector<PetscInt>  cell;    /* per probe: the index into the pressure cells, -1 if not on this rank */
  std::vector<PetscInt>  owner;   /* per probe: the rank that evaluates it */
  std::vector<PetscReal> lambda;  /* 4 per probe: barycentric coordinates in that cell */
  std::vector<PetscReal> t;       /* times recorded */
  std::vector<PetscReal> p;       /* per time, one value per probe */
};

/* Find the cells of the points X (3 per point) among the P1 pressure cells; a point in no cell
   of the fluid is an error that names it and `option`. */
PetscErrorCode PressureProbesCreate(MPI_Comm comm, const FieldCells &pressure, const std::vector<PetscReal> &X, const char *option, PressureProbes &probes);

/* Record the pressures of the local state x (essential values inserted) at time t. */
PetscErrorCode PressureProbesRecord(MPI_Comm comm, const FieldCells &pressure, const PetscScalar *x, PetscReal t, PressureProbes &probes);

/* The time each probe's pressure first rises through `level` (linear between the recorded
   times), -1 if it never does. */
std::vector<PetscReal> PressureProbesArrival(const PressureProbes &probes, PetscReal level);

} // namespace fsi
