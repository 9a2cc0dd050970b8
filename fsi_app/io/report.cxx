// SPDX-License-Identifier: BSD-2-Clause
#include "report.h"
#include "files.h"
#include <cerrno>
#include <cstdio>
#include <cstring>
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

PetscErrorCode WriteReport(const char *file, MPI_Comm comm, const RunReport &r)
{
  FILE *fp = nullptr; /* rank 0's; PetscFPrintf() writes there only */

  PetscFunctionBegin;
  PetscCall(CheckOnRankZero(comm, PETSC_ERR_FILE_OPEN, [&]() { return (fp = std::fopen(file, "w")) ? std::string() : std::string("-report ") + file + ": cannot open it for writing (" + std::strerror(errno) + ")"; }));
  PetscCall(PetscFPrintf(comm, fp, "{\n  \"unknowns\": {"));
  for (size_t k = 0; k < r.unknowns.size(); k++) PetscCall(PetscFPrintf(comm, fp, "%s\"%s\": %" PetscInt_FMT, k ? ", " : "", r.unknowns[k].first.c_str(), r.unknowns[k].second));
  PetscCall(PetscFPrintf(comm, fp, "},\n  \"unknowns_per_rank\": {"));
  for (size_t k = 0; k < r.unknownsPerRank.size(); k++) {
    PetscCall(PetscFPrintf(comm, fp, "%s\"%s\": [", k ? ", " : "", r.unknownsPerRank[k].first.c_str()));
    for (size_t j = 0; j < r.unknownsPerRank[k].second.size(); j++) PetscCall(PetscFPrintf(comm, fp, "%s%" PetscInt_FMT, j ? ", " : "", r.unknownsPerRank[k].second[j]));
    PetscCall(PetscFPrintf(comm, fp, "]"));
  }
  PetscCall(PetscFPrintf(comm, fp, "},\n  \"restarted_at_step\": %" PetscInt_FMT ",\n  \"steps\": [", r.restartedAt));
  for (size_t k = 0; k < r.steps.size(); k++) {
    const StepRecord &s = r.steps[k];
    PetscCall(PetscFPrintf(comm, fp, "%s\n    {\"step\": %" PetscInt_FMT ", \"t\": %.10g, \"newton\": %" PetscInt_FMT ", \"krylov\": %" PetscInt_FMT ", \"cuts\": %" PetscInt_FMT ", \"reason\": \"%s\"}", k ? "," : "", s.step, (double)s.t, s.newton, s.krylov, s.cuts, SNESConvergedReasons[s.reason]));
  }
  PetscCall(PetscFPrintf(comm, fp, "\n  ],\n  \"results\": {"));
  for (size_t k = 0; k < r.results.size(); k++) PetscCall(PetscFPrintf(comm, fp, "%s\"%s\": %.10e", k ? ", " : "", r.results[k].first.c_str(), (double)r.results[k].second));
  PetscCall(PetscFPrintf(comm, fp, "},\n  \"probes\": ["));
  for (size_t k = 0; k < r.series.size(); k++) {
    const Probes &s = *r.series[k].second;
    auto list = [&](const char *key, const std::vector<PetscReal> &v, const char *after) -> PetscErrorCode {
      PetscFunctionBegin;
      PetscCall(PetscFPrintf(comm, fp, "\"%s\": [", key));
      for (size_t j = 0; j < v.size(); j++) PetscCall(PetscFPrintf(comm, fp, "%s%.10e", j ? ", " : "", (double)v[j]));
      PetscCall(PetscFPrintf(comm, fp, "]%s", after));
      PetscFunctionReturn(0);
    };
    PetscCall(PetscFPrintf(comm, fp, "%s\n    {\"field\": \"%s\", \"components\": %" PetscInt_FMT ", ", k ? "," : "", r.series[k].first.c_str(), s.nc));
    PetscCall(list("points", s.X, ", "));
    PetscCall(list("t", s.t, ", "));
    PetscCall(list("values", s.values, "}"));
  }
  const Phases &p = r.phases;
  PetscCall(PetscFPrintf(comm, fp, "\n  ],\n  \"seconds\": {\"assembly\": %.4f, \"preconditioner_setup\": %.4f, \"krylov\": %.4f, \"total\": %.4f", p.assembly, p.setup, p.krylov, p.total));
  for (const auto &s : p.splitSetUp) PetscCall(PetscFPrintf(comm, fp, ", \"setup_%s\": %.4f", s.first.c_str(), s.second));
  PetscCall(PetscFPrintf(comm, fp, "},\n  \"peak_memory_mib\": %.1f\n}\n", p.peakMiB));
  PetscCall(CloseWritten(comm, "-report", file, fp));
  PetscFunctionReturn(0);
}

} // namespace fsi
