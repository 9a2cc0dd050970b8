// SPDX-License-Identifier: BSD-2-Clause
#include "run.h"
#include "base/files.h"
#include "base/options.h"
#include "discretization/fields.h"
#include "io/xdmf.h"
#include "run/checkpoint.h"
#include "run/registry.h"
#include "run/scene_files.h"
#include "run/solver.h"
#include "run/time_loop.h"

namespace fsi {

/* Global unknowns of each block's fields, under the names the blocks give them, and per rank. */
static PetscErrorCode CountUnknowns(DM dm, const Blocks &b, RunReport &report)
{
  std::vector<std::pair<std::string, PetscInt>> fields;
  IS                                           *is;
  char                                        **names;
  PetscInt                                      nf;
  PetscMPIInt                                   size;

  PetscFunctionBegin;
  for (const Block *blk : b.list) blk->Unknowns(fields);
  PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)dm), &size));
  PetscCall(DMCreateFieldIS(dm, &nf, &names, &is));
  for (const auto &f : fields) {
    PetscInt              n = 0, mine = 0;
    std::vector<PetscInt> perRank(size, 0);
    PetscCall(ISGetSize(is[f.second], &n));
    PetscCall(ISGetLocalSize(is[f.second], &mine));
    PetscCallMPI(MPI_Allgather(&mine, 1, MPIU_INT, perRank.data(), 1, MPIU_INT, PetscObjectComm((PetscObject)dm)));
    report.unknowns.push_back({f.first, n});
    report.unknownsPerRank.push_back({f.first, perRank});
  }
  for (PetscInt f = 0; f < nf; f++) {
    PetscCall(ISDestroy(&is[f]));
    PetscCall(PetscFree(names[f]));
  }
  PetscCall(PetscFree(is));
  PetscCall(PetscFree(names));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "unknowns:"));
  for (const auto &u : report.unknowns) PetscCall(PetscPrintf(PETSC_COMM_WORLD, " %s %" PetscInt_FMT, u.first.c_str(), u.second));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "\n"));
  if (size > 1) {
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "unknowns per rank:"));
    for (const auto &u : report.unknownsPerRank) {
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, " %s", u.first.c_str()));
      for (size_t r = 0; r < u.second.size(); r++) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s%" PetscInt_FMT, r ? "," : " ", u.second[r]));
    }
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "\n"));
  }
  PetscFunctionReturn(0);
}

/* The state a restart continues from: step, time, solution and past states. */
/* The blocks' running sums, one after another (RunningSums), and back. */
static std::vector<PetscReal> GatherSums(const Blocks &b)
{
  std::vector<PetscReal> all;
  for (Block *blk : b.list)
    if (const std::vector<PetscReal> *s = blk->RunningSums()) all.insert(all.end(), s->begin(), s->end());
  return all;
}

static void ScatterSums(const std::vector<PetscReal> &all, Blocks &b)
{
  size_t at = 0;
  for (Block *blk : b.list)
    if (std::vector<PetscReal> *s = blk->RunningSums()) std::copy(all.begin() + at, all.begin() + at + s->size(), s->begin()), at += s->size();
}

static PetscErrorCode Restart(const Scene &sc, Blocks &b, DM dm, Vec x, TimeHistory &history, RunReport &report)
{
  CheckpointHeader       c;
  std::vector<PetscReal> sums = GatherSums(b);

  PetscFunctionBegin;
  PetscCall(CheckpointRead(sc.restart, dm, sc.problem, c, x, history, sums));
  ScatterSums(sums, b);
  PetscCheck(c.step < sc.Steps(), PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-restart %s: the checkpoint is at step %" PetscInt_FMT " (t %g) and this run ends at step %" PetscInt_FMT ": nothing is left to do; give a %s beyond it", sc.restart, c.step, (double)c.t, sc.Steps(),
             sc.Dynamic() ? "-t_final" : "-structure_load_steps");
  report.restartedAt = c.step;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "restart from %s: step %" PetscInt_FMT " t %.4e\n", sc.restart, c.step, (double)c.t));
  PetscFunctionReturn(0);
}

/* The output series of the blocks' parts; a restarted run keeps the frames up to step `first`. */
static PetscErrorCode OpenOutput(const Scene &sc, const Blocks &b, DM dm, PetscInt first, PetscReal step, Vec x, XdmfSeries &series)
{
  std::vector<PetscReal>  times;
  std::vector<OutputPart> parts;

  PetscFunctionBegin;
  for (PetscInt k = 0; sc.restart[0] && k <= first; k += sc.outputEvery) times.push_back(k * step);
  for (const Block *blk : b.list) blk->Output(parts);
  PetscCall(XdmfOpen(sc.output, dm, parts, times, series));
  if (!sc.restart[0]) PetscCall(XdmfWriteFrame(series, 0, x));
  PetscFunctionReturn(0);
}

/* The summary lines, the blocks' results and the report (report.phases: the time loop's). */
static PetscErrorCode Summarize(const Scene &sc, Blocks &b, DM dm, SNES snes, Vec x, PetscReal tEnd, RunReport &report)
{
  PetscInt            newton = 0, krylov = 0;
  SNESConvergedReason reason = report.steps.empty() ? SNES_CONVERGED_ITERATING : report.steps.back().reason;
  const PetscInt      solved = (PetscInt)report.steps.size();
  Headline            h{"solution", -1, "solution_norm", PETSC_TRUE};
  PetscReal           hmax, xnorm;

  PetscFunctionBegin;
  for (const auto &r : report.steps) newton += r.newton, krylov += r.krylov;
  if (sc.Dynamic() && solved) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "steps %" PetscInt_FMT " newton per step %.2f krylov per newton %.2f\n", solved, (double)newton / solved, newton ? (double)krylov / newton : 0.0));
  for (const Block *blk : b.list)
    if (blk->Summary(&h)) break;
  PetscCall(FieldNorm(dm, x, h.field, NORM_INFINITY, &hmax));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "newton %" PetscInt_FMT " krylov %" PetscInt_FMT " reason %s time %.3f s max %s %.6e\n", newton, krylov, SNESConvergedReasons[reason], report.phases.total, h.name.c_str(), (double)hmax));
  PetscCall(CheckFinished(sc, b, snes, report));
  if (h.whole) PetscCall(VecNorm(x, NORM_2, &xnorm));
  else PetscCall(FieldNorm(dm, x, h.field, NORM_2, &xnorm));
  report.results.insert(report.results.end(), {{"max_" + h.name, hmax}, {h.norm, xnorm}});
  for (Block *blk : b.list) PetscCall(blk->Results(dm, x, tEnd, report));
  const Phases &p = report.phases;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "seconds: assembly %.3f preconditioner setup %.3f", p.assembly, p.setup));
  for (const auto &s : p.splitSetUp) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s%s %.3f", &s == &p.splitSetUp.front() ? " (" : ", ", s.first.c_str(), s.second));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s krylov %.3f total %.3f; peak memory %.1f MiB\n", p.splitSetUp.empty() ? "" : ")", p.krylov, p.total, p.peakMiB));
  if (sc.report[0]) PetscCall(WriteReport(sc.report, PETSC_COMM_WORLD, report));
  PetscFunctionReturn(0);
}

/* The time steps (or load increments) from the initial state or a restart, with output,
   checkpoints and the summary. */
static PetscErrorCode Solve(const Scene &sc, Blocks &b, DM dm, SNES snes, Vec x, RunReport &report)
{
  TimeHistory history;
  XdmfSeries  series;
  PetscBool   initial = PETSC_FALSE;

  PetscFunctionBegin;
  const PetscBool dynamic = sc.Dynamic();
  const PetscReal step    = dynamic ? sc.dt : 1.0 / sc.loadSteps;
  PetscCall(TimeHistoryCreate(dm, sc.scheme, step, dynamic, history));
  for (Block *blk : b.list) blk->Attach(snes, &history);
  b.system.snes = snes;
  PetscCall(VecSet(x, 0.0));
  for (Block *blk : b.list) {
    PetscBool set;
    PetscCall(blk->InitialState(dm, x, &set));
    initial = (PetscBool)(initial || set);
  }
  if (initial && dynamic) PetscCall(TimeHistorySetState(history, x));
  if (sc.restart[0]) PetscCall(Restart(sc, b, dm, x, history, report));
  const PetscInt first = PetscMax(report.restartedAt, 0);
  if (sc.output[0]) PetscCall(OpenOutput(sc, b, dm, first, step, x, series));

  CheckpointSeries checkpoints{sc.checkpoint, sc.checkpointKeep, {}};
  TimeLoop         loop;
  loop.snes = snes, loop.history = &history, loop.steps = sc.Steps(), loop.maxCuts = sc.maxCuts, loop.predictorOrder = sc.predictorOrder, loop.dynamic = dynamic;
  for (const Split &s : b.Splits()) loop.splits.push_back(s.name);
  loop.setTime = [&](PetscReal t) -> PetscErrorCode {
    PetscFunctionBegin;
    b.system.time = t;
    for (Block *blk : b.list) PetscCall(blk->SetTime(t));
    PetscFunctionReturn(0);
  };
  loop.predict = [&](PetscReal t, Vec y) -> PetscErrorCode {
    PetscFunctionBegin;
    for (Block *blk : b.list) PetscCall(blk->Predict(t, y));
    PetscFunctionReturn(0);
  };
  PetscInt raisesLeft = sc.maxWorkspaceRaises;
  loop.repair = [&](PetscInt k, PetscBool halving, PetscBool *repeat) { return RepairFactors(snes, k, halving, &raisesLeft, repeat); };
  loop.afterStep = [&](PetscInt k, PetscReal t, Vec y) -> PetscErrorCode {
    PetscFunctionBegin;
    for (Block *blk : b.list) PetscCall(blk->AfterStep(dm, k, t, y));
    if (sc.output[0] && k % sc.outputEvery == 0) PetscCall(XdmfWriteFrame(series, t, y));
    if (sc.checkpoint[0] && (k % sc.checkpointEvery == 0 || k == loop.steps)) {
      std::vector<PetscReal> sums = GatherSums(b);
      PetscCall(CheckpointWrite(checkpoints, dm, {k, t}, sc.problem, y, history, sums));
    }
    PetscFunctionReturn(0);
  };
  PetscLogDouble t0, t1;
  PetscCall(PetscTime(&t0));
  PetscCall(RunTimeLoop(loop, first, x, report.steps));
  PetscCall(PetscTime(&t1));
  PetscCall(PhasesMeasure(PETSC_COMM_WORLD, t1 - t0, loop.splits, report.phases)); /* of the time loop, as its steps' */
  PetscCall(Summarize(sc, b, dm, snes, x, dynamic ? loop.steps * step : 1.0, report));
  if (sc.output[0]) PetscCall(XdmfClose(series));
  PetscCall(TimeHistoryDestroy(history));
  PetscFunctionReturn(0);
}

PetscErrorCode RunScene()
{
  Scene     sc;
  Blocks    b;
  DM        dm;
  SNES      snes;
  Vec       x;
  RunReport report;
  PetscBool help;

  PetscFunctionBegin;
  PetscCall(PhasesBegin());
  PetscCall(ReadScene(sc));
  PetscCall(CreateBlocks(sc, b));
  PetscCall(CheckSceneFiles(sc));
  if (sc.checkpoint[0] || sc.restart[0]) PetscCall(FileDigest(PETSC_COMM_WORLD, sc.mesh, &sc.problem[MeshDigestKey]));
  PetscCall(CreateSceneMesh(sc, b, &dm));
  b.system.keepConstant = sc.keepConstant;
  b.system.directAdd    = sc.directAdd;
  PetscCall(SetUpBlocks(dm, b));
  PetscCall(DMCreateGlobalVector(dm, &x));
  PetscCall(PetscObjectSetName((PetscObject)x, "solution"));
  PetscCall(CountUnknowns(dm, b, report));
  PetscCall(CreateSolver(sc, dm, b, &snes));
  PetscCall(PetscOptionsHasHelp(nullptr, &help));
  if (help) /* every option of the scene, its blocks and its solver is printed: nothing to solve */
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "-help: the options are listed above; nothing was solved (run without -help to solve; the splits' inner solvers list their options in -ksp_view)\n"));
  else {
    PetscCall(CheckUnusedOptions(PETSC_COMM_WORLD, b.Prefixes()));
    PetscCall(ClaimSceneFiles(sc));
    PetscCall(Solve(sc, b, dm, snes, x, report));
    PetscCall(ReleaseSceneFiles(sc));
  }
  PetscCall(VecDestroy(&x));
  PetscCall(SNESDestroy(&snes));
  PetscCall(DMDestroy(&dm));
  b = Blocks(); /* before PETSc finalizes: the blocks hold PETSc objects */
  PetscFunctionReturn(0);
}

} // namespace fsi
