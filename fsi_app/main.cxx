// SPDX-License-Identifier: BSD-2-Clause
static const char help[] = "fsi_app: monolithic fluid-structure interaction on PETSc. A scene is a list of blocks:\n"
                           "the structure (linear elastic, Neo-Hooke and arterial walls; statics and dynamics), the\n"
                           "fluid (Navier-Stokes, P2-P1, ALE on a moving mesh), the geometry (harmonic mesh motion)\n"
                           "and the coupling (a Lagrange multiplier on the interface), solved as one Newton system.\n"
                           "Scenes are options files: -options_file scenes/X.opts\n";

#include "io/checkpoint.h"
#include "io/files.h"
#include "io/report.h"
#include "io/xdmf.h"
#include "mesh/mesh.h"
#include "blocks.h"
#include "discretization/fields.h"
#include "facsi/fluid_pc.h"
#include "solver/time_loop.h"
#include <petscgdsw.h>

using namespace fsi;

/* The mesh with the groups the blocks need, its cells balanced over the ranks region by
   region, refined; a label "boundary" on its boundary faces (the manufactured solutions'). */
static PetscErrorCode CreateMesh(const Scene &sc, const Blocks &b, DM *dm)
{
  std::vector<GroupUse>    groups, required;
  std::vector<std::string> regions;

  PetscFunctionBegin;
  for (const Block *blk : b.list) {
    blk->Groups(groups);
    if (!blk->Region().empty() && std::find(regions.begin(), regions.end(), blk->Region()) == regions.end()) regions.push_back(blk->Region());
  }
  for (const auto &g : groups) /* "boundary" is made below; a group named by the same option twice is checked once */
    if (!g.group.empty() && g.group != "boundary" && std::none_of(required.begin(), required.end(), [&](const GroupUse &r) { return r.group == g.group && r.option == g.option; })) required.push_back(g);
  PetscCall(LoadMesh(PETSC_COMM_WORLD, sc.mesh, sc.meshOrder, required, regions, dm));
  PetscCheck(!sc.refine || !MeshIsCurved(*dm), PETSC_COMM_WORLD, PETSC_ERR_SUP, "-refine %" PetscInt_FMT " on the curved cells of '%s': refinement would place the new nodes on the straight edges; make a finer second-order mesh (scripts/make-meshes NAME LEVEL 2) or read this one with -mesh_order 1", sc.refine, sc.mesh);
  if (sc.refine > 0) { /* each refinement makes 8 tetrahedra of one; a tetrahedral mesh has about 4.3 points (cells, faces, edges, vertices) per cell */
    PetscInt  cStart, cEnd;
    PetscReal cells, fine;
    PetscCall(DMPlexGetHeightStratum(*dm, 0, &cStart, &cEnd));
    PetscReal local = (PetscReal)(cEnd - cStart);
    PetscCallMPI(MPIU_Allreduce(&local, &cells, 1, MPIU_REAL, MPIU_SUM, PETSC_COMM_WORLD));
    fine = cells * PetscPowReal(8.0, (PetscReal)sc.refine);
    PetscCheck(4.3 * fine <= (PetscReal)PETSC_MAX_INT, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE,
               "-refine %" PetscInt_FMT ": the mesh's %.0f cells would become %.3g (each refinement multiplies them by 8), more than PETSc's %d-bit indices can number (about %.3g cells); refine less, or start from a finer mesh file",
               sc.refine, (double)cells, (double)fine, (int)(8 * sizeof(PetscInt)), (double)PETSC_MAX_INT / 4.3);
  }
  for (PetscInt k = 0; k < sc.refine; k++) {
    DM fine;
    PetscCall(DMRefine(*dm, PETSC_COMM_WORLD, &fine));
    PetscCall(DMDestroy(dm));
    *dm = fine;
  }
  PetscCall(MarkBoundaryFaces(*dm, "boundary"));
  PetscFunctionReturn(0);
}

/* Newton + the KSP/PC of the options database. A dynamic scene of linear blocks factors its
   operator once; rows with an energy take the critical-point line search (it does not reject
   good full Newton steps of stiff volumetric laws: arterial wall 7 -> 3 steps), the others
   PETSc's default backtracking on the residual norm. A single block configures the whole PC
   (gdsw: the wall's subdomains); several split it by name. */
static PetscErrorCode CreateSolver(const Scene &sc, DM dm, const Blocks &b, SNES *snes)
{
  Mat       J;
  KSP       ksp;
  PC        pc;
  PetscBool linear = PETSC_TRUE, energy = PETSC_TRUE;

  PetscFunctionBegin;
  for (const Block *blk : b.list) linear = (PetscBool)(linear && blk->Linear()), energy = (PetscBool)(energy && blk->HasEnergy());
  PetscCall(SNESCreate(PETSC_COMM_WORLD, snes));
  PetscCall(SNESSetDM(*snes, dm));
  PetscCall(SystemCreateMatrix(dm, &J));
  PetscCall(SNESSetJacobian(*snes, J, J, nullptr, nullptr));
  if (linear && sc.Dynamic()) {
    PetscCall(SNESSetLagJacobian(*snes, -2));
    PetscCall(SNESSetLagJacobianPersists(*snes, PETSC_TRUE));
    PetscCall(SNESSetLagPreconditioner(*snes, -2));
    PetscCall(SNESSetLagPreconditionerPersists(*snes, PETSC_TRUE));
  }
  if (energy) {
    SNESLineSearch ls;
    PetscCall(SNESGetLineSearch(*snes, &ls));
    PetscCall(SNESLineSearchSetType(ls, SNESLINESEARCHCP));
  }
  PetscCall(SNESGetKSP(*snes, &ksp));
  /* a Krylov solve that needs more iterations has failed (an indefinite tangent far from the
     solution): the step is halved instead of iterating for minutes (PETSc's default is 10000) */
  PetscCall(KSPSetTolerances(ksp, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, 500));
  PetscCall(SNESSetFromOptions(*snes));
  PetscCall(KSPGetPC(ksp, &pc));
  if (b.list.size() == 1) {
    MatNullSpace nsp;
    PetscCall(b.list[0]->ConfigurePC(dm, pc, &nsp));
    if (nsp) PetscCall(MatSetNearNullSpace(J, nsp));
    PetscCall(MatNullSpaceDestroy(&nsp));
  } else PetscCall(SetNamedSplits(*snes, dm, b.Splits()));
  PetscCall(MatDestroy(&J));
  PetscFunctionReturn(0);
}

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

/* Why the run stopped, as a sentence that names the cure; nothing if it did not. */
static PetscErrorCode CheckFinished(const Scene &sc, const Blocks &b, SNES snes, const RunReport &report)
{
  SNESConvergedReason reason = report.steps.empty() ? SNES_CONVERGED_ITERATING : report.steps.back().reason;
  const PetscInt      step   = report.steps.empty() ? 0 : report.steps.back().step;
  char                cure[160]; /* what to change: the load increments (statics) or the time step */
  std::string         cause;

  PetscFunctionBegin;
  if (sc.Dynamic()) PetscCall(PetscSNPrintf(cure, sizeof(cure), "reduce the time step (-dt %g now) or allow more halvings (-max_step_cuts %" PetscInt_FMT " now)", (double)sc.dt, sc.maxCuts));
  else PetscCall(PetscSNPrintf(cure, sizeof(cure), "apply the load in more increments (-structure_load_steps %" PetscInt_FMT " now) or allow more halvings (-max_step_cuts %" PetscInt_FMT " now)", sc.loadSteps, sc.maxCuts));
  if (reason == SNES_DIVERGED_FUNCTION_DOMAIN || reason == SNES_DIVERGED_LINE_SEARCH) { /* the line search may end on a point with no value */
    PetscMPIInt rank, first = 0, any;
    PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
    for (const Block *blk : b.list)
      if (cause.empty()) cause = blk->InvertedCause();
    PetscMPIInt mine = cause.empty() ? PETSC_MPI_INT_MAX : rank;
    PetscCallMPI(MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD)); /* the cause as the first rank that saw it says */
    if (reason == SNES_DIVERGED_FUNCTION_DOMAIN || any != PETSC_MPI_INT_MAX) {
      first   = any == PETSC_MPI_INT_MAX ? 0 : any;
      int len = (int)cause.size();
      PetscCallMPI(MPI_Bcast(&len, 1, MPI_INT, first, PETSC_COMM_WORLD));
      cause.resize(len);
      PetscCallMPI(MPI_Bcast(&cause[0], len, MPI_CHAR, first, PETSC_COMM_WORLD));
      SETERRQ(PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "Newton stopped in step %" PetscInt_FMT ": %s in every step the line search tried, also on the step halved %" PetscInt_FMT " times; %s", step, cause.empty() ? "the residual had no value" : cause.c_str(), sc.maxCuts, cure);
    }
  }
  if (reason == SNES_DIVERGED_LINEAR_SOLVE) {
    KSP                ksp;
    KSPConvergedReason kreason;
    PetscCall(SNESGetKSP(snes, &ksp));
    PetscCall(KSPGetConvergedReason(ksp, &kreason));
    SETERRQ(PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "the linear solver failed in step %" PetscInt_FMT " (%s, also on the step halved %" PetscInt_FMT " times); see -ksp_monitor_true_residual; CG needs a symmetric preconditioner (PCASM: -pc_asm_type basic); -pc_type lu -pc_factor_mat_solver_type mumps tells whether the preconditioner is the cause", step, KSPConvergedReasons[kreason], sc.maxCuts);
  }
  PetscCheck(reason >= 0, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "Newton did not converge in step %" PetscInt_FMT " (%s, also on the step halved %" PetscInt_FMT " times); see -snes_monitor, or %s", step, SNESConvergedReasons[reason], sc.maxCuts, cure);
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  Scene       sc;
  Blocks      b;
  TimeHistory history;
  DM          dm;
  SNES        snes;
  Vec         x;
  PetscInt    first = 0;
  RunReport   report;
  XdmfSeries  series;

  PetscCall(PetscInitialize(&argc, &argv, nullptr, help));
  PetscCall(PCGDSWRegister());
  PetscCall(PCRegisterFaCSIFluid());
  PetscCall(PhasesBegin());
  PetscCall(ReadScene(sc));
  PetscCall(CreateBlocks(sc, b));
  PetscCall(CheckSceneFiles(sc));
  if (sc.checkpoint[0] || sc.restart[0]) PetscCall(FileDigest(PETSC_COMM_WORLD, sc.mesh, &sc.problem[MeshDigestKey]));
  PetscCall(CreateMesh(sc, b, &dm));
  PetscCall(SetUpBlocks(dm, b));
  PetscCall(DMCreateGlobalVector(dm, &x));
  PetscCall(PetscObjectSetName((PetscObject)x, "solution"));
  PetscCall(CountUnknowns(dm, b, report));
  PetscCall(CreateSolver(sc, dm, b, &snes));

  const PetscBool dynamic = sc.Dynamic();
  const PetscReal step    = dynamic ? sc.dt : 1.0 / sc.loadSteps;
  PetscBool       initial = PETSC_FALSE;
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
  if (sc.restart[0]) {
    CheckpointHeader c;
    PetscCall(CheckpointRead(sc.restart, dm, sc.problem, c, x, history));
    PetscCheck(c.step < sc.Steps(), PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-restart %s: the checkpoint is at step %" PetscInt_FMT " (t %g) and this run ends at step %" PetscInt_FMT ": nothing is left to do; give a %s beyond it", sc.restart, c.step, (double)c.t, sc.Steps(),
               dynamic ? "-t_final" : "-structure_load_steps");
    first = report.restartedAt = c.step;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "restart from %s: step %" PetscInt_FMT " t %.4e\n", sc.restart, c.step, (double)c.t));
  }
  if (sc.output[0]) {
    std::vector<PetscReal>  times; /* frames a run restarted at step `first` has written */
    std::vector<OutputPart> parts;
    for (PetscInt k = 0; sc.restart[0] && k <= first; k += sc.outputEvery) times.push_back(k * step);
    for (const Block *blk : b.list) blk->Output(parts);
    PetscCall(XdmfOpen(sc.output, dm, parts, times, series));
    if (!sc.restart[0]) PetscCall(XdmfWriteFrame(series, 0, x));
  }

  TimeLoop loop;
  loop.snes = snes, loop.history = &history, loop.steps = sc.Steps(), loop.maxCuts = sc.maxCuts, loop.dynamic = dynamic;
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
  loop.afterStep = [&](PetscInt k, PetscReal t, Vec y) -> PetscErrorCode {
    PetscFunctionBegin;
    for (Block *blk : b.list) PetscCall(blk->AfterStep(dm, k, t, y));
    if (sc.output[0] && k % sc.outputEvery == 0) PetscCall(XdmfWriteFrame(series, t, y));
    if (sc.checkpoint[0] && (k % sc.checkpointEvery == 0 || k == loop.steps)) PetscCall(CheckpointWrite(sc.checkpoint, dm, {k, t}, sc.problem, y, history));
    PetscFunctionReturn(0);
  };
  PetscLogDouble t0, t1;
  PetscCall(PetscTime(&t0));
  PetscCall(RunTimeLoop(loop, first, x, report.steps));
  PetscCall(PetscTime(&t1));

  PetscInt            newton = 0, krylov = 0;
  SNESConvergedReason reason = report.steps.empty() ? SNES_CONVERGED_ITERATING : report.steps.back().reason;
  for (const auto &r : report.steps) newton += r.newton, krylov += r.krylov;
  const PetscInt solved = (PetscInt)report.steps.size();
  if (dynamic && solved) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "steps %" PetscInt_FMT " newton per step %.2f krylov per newton %.2f\n", solved, (double)newton / solved, newton ? (double)krylov / newton : 0.0));
  Headline h{"solution", -1, "solution_norm"};
  for (const Block *blk : b.list)
    if (blk->Summary(&h)) break;
  PetscReal hmax, xnorm;
  PetscCall(FieldNorm(dm, x, h.field, NORM_INFINITY, &hmax));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "newton %" PetscInt_FMT " krylov %" PetscInt_FMT " reason %s time %.3f s max %s %.6e\n", newton, krylov, SNESConvergedReasons[reason], t1 - t0, h.name.c_str(), (double)hmax));
  PetscCall(CheckFinished(sc, b, snes, report));
  PetscCall(VecNorm(x, NORM_2, &xnorm));
  report.results.insert(report.results.end(), {{"max_" + h.name, hmax}, {h.norm, xnorm}});
  for (Block *blk : b.list) PetscCall(blk->Results(dm, x, dynamic ? loop.steps * step : 1.0, report));
  PetscCall(PhasesMeasure(PETSC_COMM_WORLD, t1 - t0, loop.splits, report.phases));
  const Phases &p = report.phases;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "seconds: assembly %.3f preconditioner setup %.3f", p.assembly, p.setup));
  for (const auto &s : p.splitSetUp) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s%s %.3f", &s == &p.splitSetUp.front() ? " (" : ", ", s.first.c_str(), s.second));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s krylov %.3f total %.3f; peak memory %.1f MiB\n", p.splitSetUp.empty() ? "" : ")", p.krylov, p.total, p.peakMiB));
  if (sc.report[0]) PetscCall(WriteReport(sc.report, PETSC_COMM_WORLD, report));

  if (sc.output[0]) PetscCall(XdmfClose(series));
  if (sc.output[0]) PetscCall(ReleaseFile(PETSC_COMM_WORLD, sc.output));
  PetscCall(TimeHistoryDestroy(history));
  PetscCall(VecDestroy(&x));
  PetscCall(SNESDestroy(&snes));
  PetscCall(DMDestroy(&dm));
  b = Blocks(); /* before PETSc finalizes: the blocks hold PETSc objects */
  PetscCall(PetscFinalize());
  return 0;
}
