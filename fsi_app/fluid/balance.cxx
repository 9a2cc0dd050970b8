// SPDX-License-Identifier: BSD-2-Clause
#include "balance.h"
#include "discretization/ale_map.h"

namespace fsi {

PetscErrorCode VolumeBalance::SetUp(DM dm, const FluidForms &forms, const char *interface)
{
  DMLabel label;

  PetscFunctionBegin;
  PetscCall(DMGetLabel(dm, interface, &label));
  PetscCall(CellFacesCreate(dm, forms.velocity, label, wall));
  PetscFunctionReturn(0);
}

/* The moved fluid region's volume int J dX (exact: J is a polynomial of degree 3) for the
   local state x. */
PetscErrorCode VolumeBalance::Volume(DM dm, const FluidForms &forms, const PetscScalar *x, PetscReal *volume) const
{
  const FieldCells &cells = *forms.mesh;
  const P2Rule     &rule  = forms.rule;
  PetscReal         sum   = 0;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < cells.Size(); k++) {
    PetscReal de[30];
    Gather(cells, k, x, de);
    for (PetscInt q = 0; q < rule.nq; q++) {
      MovedPoint m;
      sum += rule.w[q] * cells.geom[k].detE * MovePoint(cells.geom[k], de, &rule.lambda[4 * q], &rule.N[10 * q], m);
    }
  }
  PetscCallMPI(MPIU_Allreduce(&sum, volume, 1, MPIU_REAL, MPIU_SUM, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

PetscErrorCode VolumeBalance::Record(DM dm, const FluidForms &forms, const std::vector<CellFace> &inlet, const std::vector<CellFace> &outlet, PetscReal t, Vec x)
{
  const TimeHistory &h = *forms.history;
  Step               s;

  PetscFunctionBegin;
  if (steps.empty()) /* the states before the first step recorded (the start, or a checkpoint's state) */
    for (size_t j = 1; j < h.past.size(); j++) {
      const PetscScalar *y;
      PetscReal          v;
      PetscCall(VecGetArrayRead(h.past[j], &y));
      PetscCall(Volume(dm, forms, y, &v));
      if (j == 1) PetscCall(FluidFaceNormSquared(dm, forms, *forms.mesh, wall, y, &d2Before));
      PetscCall(VecRestoreArrayRead(h.past[j], &y));
      before.push_back(v);
    }
  s.t = t;
  PetscCall(FluidFlux(dm, forms, inlet, x, &s.in));
  PetscCall(FluidFlux(dm, forms, outlet, x, &s.out));
  PetscCall(FluidFlux(dm, forms, wall, x, &s.wall));
  {
    const PetscScalar *y; /* past[0] is x with its essential values */
    PetscCall(VecGetArrayRead(h.past[0], &y));
    PetscCall(Volume(dm, forms, y, &s.volume));
    PetscCall(FluidFaceNormSquared(dm, forms, *forms.mesh, wall, y, &s.d2));
    PetscCall(VecRestoreArrayRead(h.past[0], &y));
  }
  s.in = -s.in; /* into the fluid */
  steps.push_back(s);
  PetscFunctionReturn(0);
}

PetscErrorCode VolumeBalance::Report(DM dm, const FluidForms &forms, RunReport &report) const
{
  const TimeHistory &h    = *forms.history;
  PetscReal          mass = 0, rate = 0, inMax = 0, wallMax = 0;

  PetscFunctionBegin;
  for (size_t k = 0; k < steps.size(); k++) {
    const Step &s  = steps[k];
    PetscReal   dV = h.first[0] * s.volume;
    for (PetscInt j = 1; j < 3 && h.first[j] != 0; j++) dV += h.first[j] * ((PetscInt)k - j >= 0 ? steps[k - j].volume : before[j - k - 1]);
    dV /= h.dt;
    mass    = PetscMax(mass, PetscAbsReal(s.in - s.out - s.wall));
    rate    = PetscMax(rate, PetscAbsReal(s.wall - dV));
    inMax   = PetscMax(inMax, PetscAbsReal(s.in));
    wallMax = PetscMax(wallMax, PetscAbsReal(s.wall));
    PetscCall(PetscInfo(nullptr, "t %g inflow %g outflow %g interface %g dV/dt %g volume %g\n", (double)s.t, (double)s.in, (double)s.out, (double)s.wall, (double)dV, (double)s.volume));
  }
  if (steps.empty()) PetscFunctionReturn(0);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "volume balance over %zu steps: max |inflow - outflow - interface flux| %.3e (max inflow %.3e); max |interface flux - dV/dt| %.3e (max interface flux %.3e)\n", steps.size(), (double)mass, (double)inMax, (double)rate, (double)wallMax));
  report.results.insert(report.results.end(), {{"volume_balance", mass}, {"max_inflow", inMax}, {"volume_rate_mismatch", rate}, {"max_interface_flux", wallMax}});
  /* by the trapezoidal rule (second order: it does not cap BDF2's) */
  PetscReal integral = 0, previous = d2Before;
  for (const Step &s : steps) integral += h.dt * (previous + s.d2) / 2, previous = s.d2;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "interface displacement: L2 norm in space and time %.6e cm^2 s^1/2\n", (double)PetscSqrtReal(integral)));
  report.results.push_back({"interface_displacement_l2", PetscSqrtReal(integral)});
  PetscFunctionReturn(0);
}

} // namespace fsi
