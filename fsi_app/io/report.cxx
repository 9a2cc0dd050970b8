// SPDX-License-Identifier: BSD-2-Clause
#include "report.h"
#include "base/files.h"
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace fsi {

/* "seconds": {...} of a run or a step */
static PetscErrorCode WriteSeconds(MPI_Comm comm, FILE *fp, const Phases &p)
{
  PetscFunctionBegin;
  PetscCall(PetscFPrintf(comm, fp, "\"seconds\": {\"assembly\": %.4f, \"preconditioner_setup\": %.4f, \"krylov\": %.4f, \"total\": %.4f", p.assembly, p.setup, p.krylov, p.total));
  for (const auto &s : p.splitSetUp) PetscCall(PetscFPrintf(comm, fp, ", \"setup_%s\": %.4f", s.first.c_str(), s.second));
  PetscCall(PetscFPrintf(comm, fp, "}"));
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
    PetscCall(PetscFPrintf(comm, fp, "%s\n    {\"step\": %" PetscInt_FMT ", \"t\": %.10g, \"newton\": %" PetscInt_FMT ", \"krylov\": %" PetscInt_FMT ", \"cuts\": %" PetscInt_FMT ", \"first_residual\": %.10e, \"reason\": \"%s\", ", k ? "," : "", s.step, (double)s.t, s.newton, s.krylov, s.cuts, (double)s.residual0, SNESConvergedReasons[s.reason]));
    PetscCall(WriteSeconds(comm, fp, s.phases));
    PetscCall(PetscFPrintf(comm, fp, ", \"peak_memory_mib\": %.1f}", s.phases.peakMiB));
  }
  PetscCall(PetscFPrintf(comm, fp, "\n  ],\n  \"results\": {"));
  for (size_t k = 0; k < r.results.size(); k++) PetscCall(PetscFPrintf(comm, fp, "%s\"%s\": %.10e", k ? ", " : "", r.results[k].first.c_str(), (double)r.results[k].second));
  PetscCall(PetscFPrintf(comm, fp, "},\n  \"probes\": ["));
  for (size_t k = 0; k < r.series.size(); k++) {
    const Probes &s = *r.series[k].second;
    auto list = [&](const char *key, const std::vector<PetscReal> &v, const char *after) -> PetscErrorCode {
      PetscFunctionBegin;
      PetscCall(PetscFPrintf(comm, fp, "\"%s\": [", key));
      for (size_t j = 0; j < v.size(); j++) PetscCall(PetscFPrintf(comm, fp, "%s%.16e", j ? ", " : "", (double)v[j])); /* every digit: tests recompute from them */
      PetscCall(PetscFPrintf(comm, fp, "]%s", after));
      PetscFunctionReturn(0);
    };
    PetscCall(PetscFPrintf(comm, fp, "%s\n    {\"field\": \"%s\", \"components\": %" PetscInt_FMT ", ", k ? "," : "", r.series[k].first.c_str(), s.nc));
    PetscCall(list("points", s.X, ", "));
    PetscCall(list("t", s.t, ", "));
    PetscCall(list("values", s.values, "}"));
  }
  PetscCall(PetscFPrintf(comm, fp, "\n  ],\n  "));
  PetscCall(WriteSeconds(comm, fp, r.phases));
  PetscCall(PetscFPrintf(comm, fp, ",\n  \"peak_memory_mib\": %.1f\n}\n", r.phases.peakMiB));
  PetscCall(CloseWritten(comm, "-report", file, fp));
  PetscFunctionReturn(0);
}

} // namespace fsi
