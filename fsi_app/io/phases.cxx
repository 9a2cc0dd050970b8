// SPDX-License-Identifier: BSD-2-Clause
#include "phases.h"
#include <sys/resource.h>

namespace fsi {

PetscErrorCode PhasesBegin()
{
  PetscBool active;

  PetscFunctionBegin;
  PetscCall(PetscLogIsActive(&active));
  if (!active) PetscCall(PetscLogDefaultBegin());
  PetscFunctionReturn(0);
}

/* Seconds in event `name` on this rank, main stage; 0 if it never ran. */
static PetscErrorCode EventTime(const char *name, double *t)
{
  PetscLogEvent      id;
  PetscEventPerfInfo info;

  PetscFunctionBegin;
  PetscCall(PetscLogEventGetId(name, &id));
  PetscCall(PetscLogEventGetPerfInfo(0, id, &info));
  *t = info.time;
  PetscFunctionReturn(0);
}

PetscErrorCode PhasesMeasure(MPI_Comm comm, double total, const std::vector<std::string> &splits, Phases &p)
{
  double        t[4], tmax[4];
  struct rusage u;

  PetscFunctionBegin;
  PetscCall(EventTime("SNESFunctionEval", &t[0]));
  PetscCall(EventTime("SNESJacobianEval", &t[1]));
  PetscCall(EventTime("PCSetUp", &t[2]));
  PetscCall(EventTime("KSPSolve", &t[3]));
  PetscCallMPI(MPIU_Allreduce(t, tmax, 4, MPI_DOUBLE, MPI_MAX, comm));
  p.assembly = tmax[0] + tmax[1], p.setup = tmax[2], p.krylov = tmax[3], p.total = total;
  p.splitSetUp.clear();
  for (const std::string &split : splits) {
    const std::string event = "SplitSetUp_" + split;
    PetscLogEvent     id;
    double            ts, tsmax;
    PetscCall(PetscLogEventGetId(event.c_str(), &id));
    if (id < 0) continue; /* the PC was not split by name */
    PetscCall(EventTime(event.c_str(), &ts));
    PetscCallMPI(MPIU_Allreduce(&ts, &tsmax, 1, MPI_DOUBLE, MPI_MAX, comm));
    p.splitSetUp.push_back({split, tsmax});
  }
  getrusage(RUSAGE_SELF, &u);
  double mib = u.ru_maxrss / 1024.0; /* kB on Linux */
  PetscCallMPI(MPIU_Allreduce(&mib, &p.peakMiB, 1, MPI_DOUBLE, MPI_SUM, comm));
  PetscFunctionReturn(0);
}

Phases PhasesSince(const Phases &before, const Phases &now)
{
  Phases d = now;
  d.assembly -= before.assembly, d.setup -= before.setup, d.krylov -= before.krylov, d.total -= before.total;
  for (auto &s : d.splitSetUp)
    for (const auto &b : before.splitSetUp)
      if (b.first == s.first) s.second -= b.second;
  return d;
}

} // namespace fsi
