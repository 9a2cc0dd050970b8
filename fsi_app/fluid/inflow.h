// SPDX-License-Identifier: BSD-2-Clause
/* A flow rate Q(t) through the inlet (cm^3/s, positive into the fluid) imposed as the velocity
   u = Q(t) g(x) n on the inlet's nodes, n the inlet's unit normal into the fluid, with a profile
   g that is zero on the inlet's rim (the no-slip wall, or on a coupled wall the nodes that move
   with it):
     plug        g = 1 inside the rim;
     parabolic   g = phi, the solution of -Delta phi = 1 on the inlet surface with phi = 0 on its
                 rim (P2 on the inlet's own triangles): the Poiseuille parabola on a disc, and a
                 profile of the same kind on any other inlet shape;
     womersley   for a circular inlet, Womersley's solution for each harmonic of Q:
                 g_k(r) = 1 - J_0(Lambda_k r/R) / J_0(Lambda_k), Lambda_k = i^(3/2) R sqrt(k w rho/mu),
                 and the parabola for the mean (fluid/womersley.h).
   Each profile (each harmonic) is scaled so that the flux of its P2 interpolant through the
   inlet is exactly its part of Q(t): the discrete inflow is the given one, not the continuous
   profile's integral. */
#pragma once

#include "base/waveform.h"
#include "discretization/cells.h"
#include "fluid/womersley.h"
#include <complex>
#include <map>
#include <array>

namespace fsi {

enum InflowProfileKind { INFLOW_PLUG, INFLOW_PARABOLIC, INFLOW_WOMERSLEY };
extern const char *const InflowProfileNames[];

struct InflowProfile {
  InflowProfileKind kind = INFLOW_PARABOLIC;
  Waveform          flow;     /* Q(t), cm^3/s into the fluid */
  PetscReal         ramp = 0; /* Q rises as sin^2(pi t / 2T) over this T */
  PetscReal         rho = 1, mu = 0.03;
  /* set up */
  PetscReal                                 normal[3] = {0, 0, 0}, centre[3] = {0, 0, 0}, area = 0, radius = 0;
  /* per inlet node (by position): g scaled to a unit flux (plug, parabolic), or g_k (womersley) */
  std::map<std::array<PetscReal, 3>, std::vector<std::complex<PetscReal>>> values;
  Womersley womersley; /* womersley: c_k scaled to the discrete flux of g_k */

  /* u at node x (an inlet node; another point gets zero) at time t */
  void Velocity(const PetscReal x[3], PetscReal t, PetscScalar u[3]) const;
};

/* The inlet's triangles (gathered on every rank from the faces of `group` that bound the
   velocity cells), its normal, centre and area, and the profile's nodal values. */
PetscErrorCode InflowProfileSetUp(DM dm, const FieldCells &velocity, const char *group, InflowProfile &p);

} // namespace fsi
