// SPDX-License-Identifier: BSD-2-Clause
#include "checkpoint.h"
#include "base/files.h"
#include "discretization/conditions.h"
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <unistd.h>
#include <sstream>
#include <vector>

namespace fsi {

static const PetscInt Magic = 0x46534935; /* "FSI5": with the problem's options, the header's and the states' checksums, the running sums */

/* header: magic, step, ranks, global size, scheme, past states, length of the problem's text,
   length of the running sums (all ranks'); then t, dt; the checksums of the header (the
   integers, t, dt and the text) and of the states (two reals each, in the order of the
   states, the running sums last); the text ("-option value" lines); the solution, the past
   states and the running sums */
enum { HEAD_MAGIC, HEAD_STEP, HEAD_RANKS, HEAD_SIZE, HEAD_SCHEME, HEAD_PAST, HEAD_TEXT, HEAD_SUMS, HEAD_LEN };

static std::string ProblemText(const std::map<std::string, std::string> &problem)
{
  std::string text;
  for (const auto &o : problem) text += o.first + " " + o.second + "\n";
  return text;
}

/* Bytes of a checkpoint with this header: PETSc binary writes each vector as its class id
   and size, then its entries. */
static long long CheckpointBytes(const PetscInt head[HEAD_LEN])
{
  const long long vec = 2 * sizeof(PetscInt) + (long long)head[HEAD_SIZE] * sizeof(PetscScalar), sums = 2 * sizeof(PetscInt) + (long long)head[HEAD_SUMS] * sizeof(PetscScalar);
  return HEAD_LEN * sizeof(PetscInt) + (2 + 2 * (3 + head[HEAD_PAST])) * sizeof(PetscReal) + head[HEAD_TEXT] + (1 + head[HEAD_PAST]) * vec + sums;
}

/* What a checkpoint keeps of a state to tell a damaged file: a 64-bit FNV-1a hash of its
   entries' bytes, rank after rank (the same ranks read it as wrote it, with the same rows:
   checked), as two 32-bit halves, which reals hold exactly. Norms would not do: their sums
   are rounded differently as the array's alignment changes. */
static PetscErrorCode Checksum(Vec v, PetscReal sum[2])
{
  const PetscScalar *a;
  PetscInt           n;
  PetscMPIInt        size;
  MPI_Comm           comm = PetscObjectComm((PetscObject)v);

  PetscFunctionBegin;
  PetscCall(VecGetLocalSize(v, &n));
  PetscCall(VecGetArrayRead(v, &a));
  unsigned long long local = Fnv1a(a, (size_t)n * sizeof(PetscScalar), FnvStart);
  PetscCall(VecRestoreArrayRead(v, &a));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<unsigned long long> all(size);
  PetscCallMPI(MPI_Allgather(&local, 1, MPI_UNSIGNED_LONG_LONG, all.data(), 1, MPI_UNSIGNED_LONG_LONG, comm));
  const unsigned long long h = Fnv1a(all.data(), all.size() * sizeof(all[0]), FnvStart);
  sum[0] = (PetscReal)(h >> 32), sum[1] = (PetscReal)(h & 0xffffffffull);
  PetscFunctionReturn(0);
}

/* The header's checksum (as Checksum's two halves): a stored time or option changed by hand is
   a damaged file, not a different problem. */
static void HeaderChecksum(const PetscInt head[HEAD_LEN], const PetscReal times[2], const std::string &text, PetscReal sum[2])
{
  unsigned long long h = Fnv1a(head, HEAD_LEN * sizeof(PetscInt), FnvStart);
  h                    = Fnv1a(times, 2 * sizeof(PetscReal), h);
  h                    = Fnv1a(text.data(), text.size(), h);
  sum[0] = (PetscReal)(h >> 32), sum[1] = (PetscReal)(h & 0xffffffffull);
}

/* The first option whose value differs from the checkpoint's, as a sentence; "" if none. */
static std::string ProblemDifference(const char *file, const std::string &written, const std::map<std::string, std::string> &problem)
{
  std::map<std::string, std::string> then;
  std::istringstream                 in(written);
  auto                               shown = [](const std::string &v) { return v.empty() ? std::string("(empty)") : v; };
  for (std::string line; std::getline(in, line);) {
    const size_t space = line.find(' ');
    then[line.substr(0, space)] = space == std::string::npos ? "" : line.substr(space + 1);
  }
  for (const auto &o : problem) {
    const auto t = then.find(o.first);
    if (o.first == MeshDigestKey && t != then.end() && t->second != o.second)
      return std::string("-restart ") + file + ": the mesh file " + (problem.count("-mesh") ? problem.at("-mesh") : std::string("")) + " has changed since the checkpoint was written (its contents differ): restart with the mesh of the run that wrote it";
    if (t == then.end()) return std::string("-restart ") + file + ": written without " + o.first + " (by another version of fsi_app); restart from a checkpoint of this version";
    if (t->second != o.second) return std::string("-restart ") + file + ": written with " + o.first + " " + shown(t->second) + ", this run has " + o.first + " " + shown(o.second) + ": a restart continues the problem of the run that wrote it; give the same options";
  }
  return "";
}

/* This rank's running sums as a vector of all ranks' (their place in the file). */
static PetscErrorCode SumsVector(MPI_Comm comm, std::vector<PetscReal> &sums, Vec *v)
{
  PetscFunctionBegin;
  PetscCall(VecCreateMPIWithArray(comm, 1, (PetscInt)sums.size(), PETSC_DECIDE, (PetscScalar *)sums.data(), v));
  PetscFunctionReturn(0);
}

PetscErrorCode CheckpointWrite(CheckpointSeries &s, DM dm, const CheckpointHeader &c, const std::map<std::string, std::string> &problem, Vec x, const TimeHistory &h, std::vector<PetscReal> &running)
{
  const char *file = s.file.c_str();
  PetscViewer viewer;
  PetscMPIInt size, rank;
  PetscInt    N;
  char        tmp[PETSC_MAX_PATH_LEN];

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)dm), &size));
  PetscCallMPI(MPI_Comm_rank(PetscObjectComm((PetscObject)dm), &rank));
  PetscCall(VecGetSize(x, &N));
  PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", file));
  PetscCall(PetscViewerCreate(PetscObjectComm((PetscObject)dm), &viewer));
  PetscCall(PetscViewerSetType(viewer, PETSCVIEWERBINARY));
  PetscCall(PetscViewerBinarySetSkipInfo(viewer, PETSC_TRUE));
  PetscCall(PetscViewerFileSetMode(viewer, FILE_MODE_WRITE));
  PetscCall(PetscViewerFileSetName(viewer, tmp));
  Vec      runningSums;
  PetscInt M;
  PetscCall(SumsVector(PetscObjectComm((PetscObject)dm), running, &runningSums));
  PetscCall(VecGetSize(runningSums, &M));
  const std::string text           = ProblemText(problem);
  const PetscInt    head[HEAD_LEN] = {Magic, c.step, size, N, h.scheme, (PetscInt)h.past.size(), (PetscInt)text.size(), M};
  const PetscReal   times[2]       = {c.t, h.dt};
  std::vector<Vec>  states(1 + h.past.size(), x);
  for (size_t j = 0; j < h.past.size(); j++) {
    PetscCall(DMGetGlobalVector(dm, &states[1 + j]));
    PetscCall(DMLocalToGlobal(dm, h.past[j], INSERT_VALUES, states[1 + j]));
  }
  states.push_back(runningSums);
  std::vector<PetscReal> sums(2 + 2 * states.size());
  HeaderChecksum(head, times, text, &sums[0]);
  for (size_t j = 0; j < states.size(); j++) PetscCall(Checksum(states[j], &sums[2 + 2 * j]));
  PetscCall(PetscViewerBinaryWrite(viewer, head, HEAD_LEN, PETSC_INT));
  PetscCall(PetscViewerBinaryWrite(viewer, times, 2, PETSC_REAL));
  PetscCall(PetscViewerBinaryWrite(viewer, sums.data(), (PetscInt)sums.size(), PETSC_REAL));
  PetscCall(PetscViewerBinaryWrite(viewer, text.c_str(), (PetscInt)text.size(), PETSC_CHAR));
  for (Vec v : states) PetscCall(VecView(v, viewer));
  for (size_t j = 1; j + 1 < states.size(); j++) PetscCall(DMRestoreGlobalVector(dm, &states[j]));
  PetscCall(VecDestroy(&runningSums));
  PetscCall(PetscViewerDestroy(&viewer));
  PetscCheck(rank || std::rename(tmp, file) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "cannot rename checkpoint %s to %s", tmp, file);
  if (s.keep > 1) { /* file.<step> beside it, the older ones of this run removed */
    const std::string numbered = s.file + "." + std::to_string(c.step);
    if (!rank) {
      std::remove(numbered.c_str());
      PetscCheck(link(file, numbered.c_str()) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "-checkpoint_keep %" PetscInt_FMT ": cannot keep %s as %s (%s); give -checkpoint_keep 1 on a file system without hard links", s.keep, file, numbered.c_str(), std::strerror(errno));
    }
    s.numbered.push_back(numbered);
    for (; (PetscInt)s.numbered.size() > s.keep; s.numbered.pop_front())
      if (!rank) std::remove(s.numbered.front().c_str());
  }
  PetscCallMPI(MPI_Barrier(PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

PetscErrorCode CheckpointRead(const char *file, DM dm, const std::map<std::string, std::string> &problem, CheckpointHeader &c, Vec x, TimeHistory &h, std::vector<PetscReal> &running)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)dm);
  PetscViewer viewer;
  PetscMPIInt size;
  PetscInt    N, head[HEAD_LEN];
  PetscReal   times[2];
  PetscBool   exists;
  long long   bytes;
  std::string text;
  Vec         g;

  PetscFunctionBegin;
  PetscCall(PetscTestFile(file, 'r', &exists));
  PetscCheck(exists, comm, PETSC_ERR_FILE_OPEN, "-restart %s: no such checkpoint (written by -checkpoint <file> -checkpoint_every <n>)", file);
  PetscCall(FileSize(comm, file, &bytes));
  PetscCheck(bytes >= (long long)(HEAD_LEN * sizeof(PetscInt)), comm, PETSC_ERR_FILE_UNEXPECTED, "-restart %s: %lld bytes, shorter than a checkpoint's header: the file is truncated or not an fsi_app checkpoint", file, bytes);
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(VecGetSize(x, &N));
  PetscCall(PetscViewerCreate(comm, &viewer));
  PetscCall(PetscViewerSetType(viewer, PETSCVIEWERBINARY));
  PetscCall(PetscViewerBinarySetSkipInfo(viewer, PETSC_TRUE));
  PetscCall(PetscViewerFileSetMode(viewer, FILE_MODE_READ));
  PetscCall(PetscViewerFileSetName(viewer, file));
  PetscCall(PetscViewerBinaryRead(viewer, head, HEAD_LEN, nullptr, PETSC_INT));
  PetscCheck(head[HEAD_MAGIC] == Magic, comm, PETSC_ERR_FILE_UNEXPECTED, "-restart %s: not an fsi_app checkpoint (or one of an older version)", file);
  PetscCheck(bytes == CheckpointBytes(head), comm, PETSC_ERR_FILE_UNEXPECTED, "-restart %s: %lld bytes where its header announces %lld: the file is truncated or damaged, not a whole checkpoint", file, bytes, CheckpointBytes(head));
  PetscCall(PetscViewerBinaryRead(viewer, times, 2, nullptr, PETSC_REAL));
  std::vector<PetscReal> sums(2 * (3 + head[HEAD_PAST])), now(2);
  PetscCall(PetscViewerBinaryRead(viewer, sums.data(), (PetscInt)sums.size(), nullptr, PETSC_REAL));
  text.resize(head[HEAD_TEXT]);
  PetscCall(PetscViewerBinaryRead(viewer, &text[0], head[HEAD_TEXT], nullptr, PETSC_CHAR));
  HeaderChecksum(head, times, text, now.data());
  PetscCheck(now[0] == sums[0] && now[1] == sums[1], comm, PETSC_ERR_FILE_UNEXPECTED, "-restart %s: its header (step, time, step size or options) does not match its checksum: the file was changed after it was written", file);
  const std::string differs = ProblemDifference(file, text, problem);
  PetscCheck(differs.empty(), comm, PETSC_ERR_ARG_INCOMP, "%s", differs.c_str());
  PetscCheck(head[HEAD_RANKS] == size, comm, PETSC_ERR_ARG_INCOMP, "-restart %s: written by %" PetscInt_FMT " ranks; restart on as many (mpiexec -n %" PetscInt_FMT "): the unknowns are numbered per partition", file, head[HEAD_RANKS], head[HEAD_RANKS]);
  PetscCheck(head[HEAD_SIZE] == N, comm, PETSC_ERR_ARG_INCOMP, "-restart %s: holds %" PetscInt_FMT " unknowns, this scene has %" PetscInt_FMT ": use the mesh and options of the run that wrote it", file, head[HEAD_SIZE], N);
  PetscCheck(head[HEAD_SCHEME] == h.scheme && head[HEAD_PAST] == (PetscInt)h.past.size(), comm, PETSC_ERR_ARG_INCOMP, "-restart %s: written with -time_scheme %s and %" PetscInt_FMT " past states, this run has -time_scheme %s (%s)", file,
             TimeSchemeNames[head[HEAD_SCHEME]], head[HEAD_PAST], TimeSchemeNames[h.scheme], h.past.empty() ? "statics" : "dynamics");
  PetscCheck(PetscAbsReal(times[1] - h.dt) <= 1e-12 * PetscAbsReal(h.dt), comm, PETSC_ERR_ARG_INCOMP, "-restart %s: written with step %g, this run has %g", file, (double)times[1], (double)h.dt);
  c.step = head[HEAD_STEP], c.t = times[0];
  auto intact = [&](Vec v, size_t j) -> PetscErrorCode {
    PetscFunctionBegin;
    PetscCall(Checksum(v, now.data()));
    PetscCheck(now[0] == sums[2 + 2 * j] && now[1] == sums[3 + 2 * j], comm, PETSC_ERR_FILE_UNEXPECTED, "-restart %s: %s stored in it does not match its checksum: the file was damaged after it was written", file,
               j == 0 ? "the solution" : j <= h.past.size() ? "a past state" : "the output's running sums");
    PetscFunctionReturn(0);
  };
  PetscCall(VecLoad(x, viewer));
  PetscCall(intact(x, 0));
  PetscCall(DMGetGlobalVector(dm, &g));
  for (size_t j = 0; j < h.past.size(); j++) { /* x^(n-j) at t - j dt, with its essential values */
    PetscCall(VecLoad(g, viewer));
    PetscCall(intact(g, 1 + j));
    PetscCall(DMGlobalToLocal(dm, g, INSERT_VALUES, h.past[j]));
    PetscCall(InsertEssentialValues(dm, c.t - j * h.dt, h.past[j]));
  }
  PetscCall(DMRestoreGlobalVector(dm, &g));
  Vec      runningSums;
  PetscInt M;
  PetscCall(SumsVector(comm, running, &runningSums));
  PetscCall(VecGetSize(runningSums, &M));
  PetscCheck(M == head[HEAD_SUMS], comm, PETSC_ERR_ARG_INCOMP, "-restart %s: holds %" PetscInt_FMT " running sums of the output (time averages), this scene has %" PetscInt_FMT ": use the mesh and options of the run that wrote it", file, head[HEAD_SUMS], M);
  PetscCall(VecLoad(runningSums, viewer)); /* into `running`: the vector wraps it */
  PetscCall(intact(runningSums, 1 + h.past.size()));
  PetscCall(VecDestroy(&runningSums));
  PetscCall(PetscViewerDestroy(&viewer));
  PetscFunctionReturn(0);
}

} // namespace fsi
