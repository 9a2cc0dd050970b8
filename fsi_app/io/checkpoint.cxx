#include "checkpoint.h"
#include "discretization/conditions.h"
#include <cstdio>

namespace fsi {

static const PetscInt Magic = 0x46534943; /* "FSIC" */

/* header: magic, step, ranks, global size, scheme, past states; then t, dt */
PetscErrorCode CheckpointWrite(const char *file, DM dm, const CheckpointHeader &c, Vec x, const TimeHistory &h)
{
  PetscViewer viewer;
  PetscMPIInt size, rank;
  PetscInt    N;
  char        tmp[PETSC_MAX_PATH_LEN];
  Vec         g;

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
  const PetscInt  head[6] = {Magic, c.step, size, N, h.scheme, (PetscInt)h.past.size()};
  const PetscReal times[2] = {c.t, h.dt};
  PetscCall(PetscViewerBinaryWrite(viewer, head, 6, PETSC_INT));
  PetscCall(PetscViewerBinaryWrite(viewer, times, 2, PETSC_REAL));
  PetscCall(VecView(x, viewer));
  PetscCall(DMGetGlobalVector(dm, &g));
  for (Vec past : h.past) {
    PetscCall(DMLocalToGlobal(dm, past, INSERT_VALUES, g));
    PetscCall(VecView(g, viewer));
  }
  PetscCall(DMRestoreGlobalVector(dm, &g));
  PetscCall(PetscViewerDestroy(&viewer));
  PetscCheck(rank || std::rename(tmp, file) == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "cannot rename checkpoint %s to %s", tmp, file);
  PetscCallMPI(MPI_Barrier(PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

PetscErrorCode CheckpointRead(const char *file, DM dm, CheckpointHeader &c, Vec x, TimeHistory &h)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)dm);
  PetscViewer viewer;
  PetscMPIInt size;
  PetscInt    N, head[6];
  PetscReal   times[2];
  PetscBool   exists;
  Vec         g;

  PetscFunctionBegin;
  PetscCall(PetscTestFile(file, 'r', &exists));
  PetscCheck(exists, comm, PETSC_ERR_FILE_OPEN, "-restart %s: no such checkpoint (written by -checkpoint <file> -checkpoint_every <n>)", file);
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(VecGetSize(x, &N));
  PetscCall(PetscViewerCreate(comm, &viewer));
  PetscCall(PetscViewerSetType(viewer, PETSCVIEWERBINARY));
  PetscCall(PetscViewerBinarySetSkipInfo(viewer, PETSC_TRUE));
  PetscCall(PetscViewerFileSetMode(viewer, FILE_MODE_READ));
  PetscCall(PetscViewerFileSetName(viewer, file));
  PetscCall(PetscViewerBinaryRead(viewer, head, 6, nullptr, PETSC_INT));
  PetscCheck(head[0] == Magic, comm, PETSC_ERR_FILE_UNEXPECTED, "-restart %s: not an fsi_app checkpoint", file);
  PetscCheck(head[2] == size, comm, PETSC_ERR_ARG_INCOMP, "-restart %s: written by %" PetscInt_FMT " ranks; restart on as many (mpiexec -n %" PetscInt_FMT "): the unknowns are numbered per partition", file, head[2], head[2]);
  PetscCheck(head[3] == N, comm, PETSC_ERR_ARG_INCOMP, "-restart %s: holds %" PetscInt_FMT " unknowns, this scene has %" PetscInt_FMT ": use the mesh and options of the run that wrote it", file, head[3], N);
  PetscCheck(head[4] == h.scheme && head[5] == (PetscInt)h.past.size(), comm, PETSC_ERR_ARG_INCOMP, "-restart %s: written with -time_scheme %s and %" PetscInt_FMT " past states, this run has -time_scheme %s (%s)", file,
             TimeSchemeNames[head[4]], head[5], TimeSchemeNames[h.scheme], h.past.empty() ? "statics" : "dynamics");
  PetscCall(PetscViewerBinaryRead(viewer, times, 2, nullptr, PETSC_REAL));
  PetscCheck(PetscAbsReal(times[1] - h.dt) <= 1e-12 * PetscAbsReal(h.dt), comm, PETSC_ERR_ARG_INCOMP, "-restart %s: written with step %g, this run has %g", file, (double)times[1], (double)h.dt);
  c.step = head[1], c.t = times[0];
  PetscCall(VecLoad(x, viewer));
  PetscCall(DMGetGlobalVector(dm, &g));
  for (size_t j = 0; j < h.past.size(); j++) { /* x^(n-j) at t - j dt, with its essential values */
    PetscCall(VecLoad(g, viewer));
    PetscCall(DMGlobalToLocal(dm, g, INSERT_VALUES, h.past[j]));
    PetscCall(InsertEssentialValues(dm, c.t - j * h.dt, h.past[j]));
  }
  PetscCall(DMRestoreGlobalVector(dm, &g));
  PetscCall(PetscViewerDestroy(&viewer));
  PetscFunctionReturn(0);
}

} // namespace fsi
