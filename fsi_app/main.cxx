static const char help[] = "fsi_app: monolithic fluid-structure interaction on PETSc. So far: the structure block\n"
                           "(linear elastic, Neo-Hooke and arterial walls; statics and dynamics), the fluid block\n"
                           "(Navier-Stokes, P2-P1, ALE on a moving mesh), the geometry block (harmonic mesh motion)\n"
                           "and their verification.\n"
                           "Scenes are options files: -options_file scenes/X.opts\n";

#include "io/checkpoint.h"
#include "io/report.h"
#include "io/xdmf.h"
#include "mesh/mesh.h"
#include "scene.h"
#include "blocks.h"
#include "geometry/predictor.h"
#include "solver/subdomains.h"
#include "solver/time_loop.h"
#include "verification/errors.h"
#include "verification/mms.h"
#include <petscgdsw.h>

using namespace fsi;

/* The mesh, refined; a label "boundary" on its boundary faces (the manufactured solutions'). */
static PetscErrorCode CreateMesh(const Scene &sc, DM *dm)
{
  std::vector<std::string> groups; /* the groups the scene names */
  auto                     add = [&](const char *list) {
    for (const auto &g : SplitList(list)) groups.push_back(g.substr(0, g.find(':')));
  };
  if (sc.physics == PHYSICS_STRUCTURE) {
    add(sc.clamp), add(sc.region);
    if (sc.pressure != 0) add(sc.loaded);
    add(sc.tractionGroup);
  } else {
    add(sc.fluidRegion);
    if (sc.physics == PHYSICS_FLUID) add(sc.noslip);
    if (sc.physics == PHYSICS_FLUID && (sc.inletPressure != 0 || sc.poiseuille[0] > 0 || sc.inflow)) add(sc.inlet);
    if (sc.physics == PHYSICS_FLUID && (sc.poiseuille[0] > 0 || sc.mms)) add(sc.outlet);
    if (sc.physics == PHYSICS_GEOMETRY || sc.movingMesh) add(sc.slip), add(sc.interface);
  }
  std::vector<std::string> required;
  for (const auto &g : groups)
    if (!g.empty() && g != "boundary") required.push_back(g); /* "boundary" is made below */

  PetscFunctionBegin;
  PetscCall(LoadMesh(PETSC_COMM_WORLD, sc.mesh, required, dm));
  for (PetscInt k = 0; k < sc.refine; k++) {
    DM fine;
    PetscCall(DMRefine(*dm, PETSC_COMM_WORLD, &fine));
    PetscCall(DMDestroy(dm));
    *dm = fine;
  }
  PetscCall(MarkBoundaryFaces(*dm, "boundary"));
  PetscFunctionReturn(0);
}

/* Newton + the KSP/PC of the options database; a linear dynamic operator is set up once; the
   structure's PC gets its element subdomains and rigid-body modes. */
static PetscErrorCode CreateSolver(const Scene &sc, DM dm, PetscInt field, SNES *snes)
{
  Mat J;
  KSP ksp;
  PC  pc;

  PetscFunctionBegin;
  PetscCall(SNESCreate(PETSC_COMM_WORLD, snes));
  PetscCall(SNESSetDM(*snes, dm));
  PetscCall(DMCreateMatrix(dm, &J));
  PetscCall(SNESSetJacobian(*snes, J, J, nullptr, nullptr));
  const PetscBool structure = (PetscBool)(sc.physics == PHYSICS_STRUCTURE);
  if (structure && sc.material == LINEAR_ELASTIC && sc.Dynamic() && !sc.follower) {
    PetscCall(SNESSetLagJacobian(*snes, -2));
    PetscCall(SNESSetLagJacobianPersists(*snes, PETSC_TRUE));
    PetscCall(SNESSetLagPreconditioner(*snes, -2));
    PetscCall(SNESSetLagPreconditionerPersists(*snes, PETSC_TRUE));
  }
  if (structure) { /* the residual norm rejects good full Newton steps of stiff volumetric laws;
                     the critical-point search (a secant on the energy's slope) does not: arterial
                     wall 7 -> 3 steps */
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
  if (structure) PetscCall(SetGDSWSubdomains(pc, dm, J, sc.region, field, sc.subdomains));
  PetscCall(MatDestroy(&J));
  PetscFunctionReturn(0);
}

/* Global unknowns per field, under the names of the monolithic system's blocks (a block a
   scene does not solve has none). */
static PetscErrorCode CountUnknowns(DM dm, RunReport &report)
{
  const std::vector<std::pair<std::string, std::string>> block = {{"displacement", "structure"}, {"velocity", "fluid"}, {"pressure", "pressure"}, {"geometry", "geometry"}, {"multiplier", "multiplier"}};
  IS                                                    *is;
  char                                                 **names;
  PetscInt                                               nf;

  PetscFunctionBegin;
  PetscCall(DMCreateFieldIS(dm, &nf, &names, &is));
  for (const auto &b : block) {
    PetscInt n = 0;
    for (PetscInt f = 0; f < nf; f++)
      if (b.first == names[f]) PetscCall(ISGetSize(is[f], &n));
    report.unknowns.push_back({b.second, n});
  }
  for (PetscInt f = 0; f < nf; f++) {
    PetscCall(ISDestroy(&is[f]));
    PetscCall(PetscFree(names[f]));
  }
  PetscCall(PetscFree(is));
  PetscCall(PetscFree(names));
  PetscFunctionReturn(0);
}

/* The largest entry of a field of the global vector x. */
static PetscErrorCode FieldMax(DM dm, Vec x, PetscInt field, PetscReal *max)
{
  IS      *is;
  PetscInt nf;
  Vec      part;

  PetscFunctionBegin;
  PetscCall(DMCreateFieldIS(dm, &nf, nullptr, &is));
  PetscCall(VecGetSubVector(x, is[field], &part));
  PetscCall(VecNorm(part, NORM_INFINITY, max));
  PetscCall(VecRestoreSubVector(x, is[field], &part));
  for (PetscInt f = 0; f < nf; f++) PetscCall(ISDestroy(&is[f]));
  PetscCall(PetscFree(is));
  PetscFunctionReturn(0);
}

static PetscErrorCode PrintErrors(const char *what, const Errors &e, RunReport &report)
{
  const std::string w = what[0] ? std::string(what) + "_" : "", space = what[0] ? " " : "";
  PetscFunctionBegin;
  for (const auto &n : {std::make_pair("L2", std::make_pair(e.l2, e.l2Exact)), std::make_pair("H1", std::make_pair(e.h1, e.h1Exact))}) {
    const PetscReal err = n.second.first, exact = n.second.second;
    const std::string key = w + (n.first[0] == 'L' ? "l2" : "h1");
    if (exact > 0) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s%s%s error %.6e relative %.6e\n", what, space.c_str(), n.first, (double)err, (double)(err / exact)));
    else PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s%s%s error %.6e (the exact field is zero)\n", what, space.c_str(), n.first, (double)err));
    report.results.push_back({key + "_error", err});
    if (exact > 0) report.results.push_back({key + "_relative", err / exact});
  }
  PetscFunctionReturn(0);
}

/* Errors against the exact solution of the verification scenes at time t, printed and reported. */
static PetscErrorCode Verify(const Scene &sc, DM dm, const Blocks &b, Vec d, PetscReal t, RunReport &report)
{
  Errors            e;
  const FluidBlock &fb   = b.fluid;
  Lame              lame = LameCylinder(sc.E, sc.nu, sc.pressure, sc.lameRadii[0], sc.lameRadii[1]);
  Poiseuille        flow = {sc.poiseuille[0], sc.poiseuille[1], sc.poiseuille[2], sc.muFluid};

  PetscReal         in = 0, out = 0; /* fluxes through inlet and outlet */

  PetscFunctionBegin;
  if (sc.physics == PHYSICS_FLUID) { /* equal to the solver's tolerance: div u is orthogonal to the constants */
    PetscCall(FluidFlux(dm, fb, fb.inletFaces, d, &in));
    PetscCall(FluidFlux(dm, fb, fb.outletFaces, d, &out));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "flux inlet %.6e outlet %.6e\n", (double)in, (double)out));
    report.results.insert(report.results.end(), {{"inlet_flux", in}, {"outlet_flux", out}});
  }
  if (sc.physics == PHYSICS_GEOMETRY) PetscCall(ComputeErrors(dm, b.geometry.cells, d, t, PrescribedDisplacementSolution, &b.motion, e));
  else if (sc.physics == PHYSICS_FLUID && sc.mms) {
    PetscCall(ComputeErrors(dm, fb.pressure, d, t, FlowMMSPressure, &b.flow, e, fb.mesh));
    PetscCall(PrintErrors("pressure", e, report));
    PetscCall(ComputeErrors(dm, fb.velocity, d, t, FlowMMSVelocity, &b.flow, e, fb.mesh));
  } else if (sc.physics == PHYSICS_FLUID && flow.R > 0) {
    const PetscReal exact = PETSC_PI * PetscPowReal(flow.R, 4) * flow.dp / (8 * flow.mu * flow.L), Q = out;
    PetscCall(ComputeErrors(dm, fb.velocity, d, t, PoiseuilleVelocity, &flow, e, fb.mesh));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "flux %.6e exact %.6e relative error %.3e\n", (double)Q, (double)exact, (double)PetscAbsReal(Q / exact - 1)));
    report.results.insert(report.results.end(), {{"flux", Q}, {"flux_relative_error", PetscAbsReal(Q / exact - 1)}});
  } else if (sc.physics == PHYSICS_FLUID) PetscFunctionReturn(0);
  else if (sc.lameRadii[1] > 0) PetscCall(ComputeErrors(dm, b.structure.cells, d, t, LameSolution, &lame, e));
  else if (sc.mms) PetscCall(ComputeErrors(dm, b.structure.cells, d, t, MMSElasticitySolution, &sc.mmsAmplitude, e));
  else PetscFunctionReturn(0);
  PetscCall(PrintErrors("", e, report));
  PetscFunctionReturn(0);
}

/* A dynamic manufactured flow starts from its exact velocity at t = 0, held since t = -infinity
   (the uniform flow: nonzero; the ramped one: zero). */
static PetscErrorCode SetInitialFlow(const Blocks &b, DM dm, Vec x, TimeHistory &h)
{
  Vec          local;
  PetscScalar *a;

  PetscFunctionBegin;
  PetscCall(DMGetLocalVector(dm, &local));
  PetscCall(VecSet(local, 0.0));
  PetscCall(VecGetArray(local, &a));
  SetNodalValues(b.fluid.velocity, [&](const PetscReal X[3], PetscScalar *u) { FlowMMSVelocityBC(3, 0.0, X, 3, u, (void *)&b.flow); }, a);
  PetscCall(VecRestoreArray(local, &a));
  PetscCall(DMLocalToGlobal(dm, local, INSERT_VALUES, x));
  PetscCall(DMRestoreLocalVector(dm, &local));
  PetscCall(TimeHistorySetState(h, x));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  Scene          sc;
  Blocks         b;
  TimeHistory    history;
  DM             dm;
  SNES           snes;
  Vec            d;
  PetscInt       first = 0;
  RunReport      report;
  XdmfSeries     series;

  PetscCall(PetscInitialize(&argc, &argv, nullptr, help));
  PetscCall(PCGDSWRegister());
  PetscCall(PhasesBegin());
  PetscCall(ReadScene(sc));
  PetscCall(CreateMesh(sc, &dm));
  PetscCall(CreateBlocks(sc, dm, b));
  const Fields  &fields = b.fields;
  const PetscInt field  = sc.physics == PHYSICS_STRUCTURE ? fields.displacement : sc.physics == PHYSICS_FLUID ? fields.velocity : fields.geometry; /* reported, written */
  PetscCall(DMCreateGlobalVector(dm, &d));
  PetscCall(PetscObjectSetName((PetscObject)d, "solution"));
  PetscCall(CountUnknowns(dm, report));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "unknowns:"));
  for (const auto &u : report.unknowns) PetscCall(PetscPrintf(PETSC_COMM_WORLD, " %s %" PetscInt_FMT, u.first.c_str(), u.second));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "\n"));
  PetscCall(CreateSolver(sc, dm, field, &snes));
  b.structure.snes = b.fluid.snes = snes;

  const PetscBool dynamic = sc.Dynamic();
  const PetscReal step    = dynamic ? sc.dt : 1.0 / sc.loadSteps;
  PetscCall(TimeHistoryCreate(dm, sc.scheme, step, dynamic, history));
  b.structure.history = b.fluid.history = &history;
  PetscCall(VecSet(d, 0.0));
  if (sc.physics == PHYSICS_FLUID && sc.mms && dynamic) PetscCall(SetInitialFlow(b, dm, d, history));
  if (sc.restart[0]) {
    CheckpointHeader c;
    PetscCall(CheckpointRead(sc.restart, dm, c, d, history));
    first = report.restartedAt = c.step;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "restart from %s: step %" PetscInt_FMT " t %.4e\n", sc.restart, c.step, (double)c.t));
  }
  if (sc.output[0]) {
    std::vector<PetscReal> times; /* frames a run restarted at step `first` has written */
    for (PetscInt k = 0; sc.restart[0] && k <= first; k += sc.outputEvery) times.push_back(k * step);
    if (sc.physics == PHYSICS_FLUID) {
      std::vector<std::pair<std::string, PetscInt>> written = {{"velocity", fields.velocity}, {"pressure", fields.pressure}};
      if (fields.geometry >= 0) written.push_back({"mesh_displacement", fields.geometry}); /* ParaView: Warp By Vector shows the moved mesh */
      PetscCall(XdmfOpen(sc.output, dm, b.fluid.velocity, written, times, series));
    } else PetscCall(XdmfOpen(sc.output, dm, sc.physics == PHYSICS_GEOMETRY ? b.geometry.cells : b.structure.cells, {{"displacement", field}}, times, series));
    if (!sc.restart[0]) PetscCall(XdmfWriteFrame(series, 0, d));
  }

  GeometryPredictor predictor;
  if (sc.movingMesh) PetscCall(GeometryPredictorCreate(dm, fields.geometry, b.geometry, predictor));

  TimeLoop loop;
  loop.snes = snes, loop.history = &history, loop.steps = sc.Steps(), loop.maxCuts = sc.maxCuts, loop.dynamic = dynamic;
  loop.setTime   = [&](PetscReal t) {
    b.structure.load = StructureLoadFactor(sc, t), b.structure.pressure = sc.pressure * b.structure.load, b.fluid.time = b.system.time = t;
    return PetscErrorCode(0);
  };
  if (sc.movingMesh) loop.predict = [&](PetscReal t, Vec x) { return GeometryPredict(predictor, t, x); };
  loop.afterStep = [&](PetscInt k, PetscReal t, Vec x) -> PetscErrorCode {
    PetscFunctionBegin;
    if (sc.output[0] && k % sc.outputEvery == 0) PetscCall(XdmfWriteFrame(series, t, x));
    if (sc.checkpoint[0] && (k % sc.checkpointEvery == 0 || k == loop.steps)) PetscCall(CheckpointWrite(sc.checkpoint, dm, {k, t}, x, history));
    PetscFunctionReturn(0);
  };
  PetscLogDouble t0, t1;
  PetscCall(PetscTime(&t0));
  PetscCall(RunTimeLoop(loop, first, d, report.steps));
  PetscCall(PetscTime(&t1));

  PetscInt            newton = 0, krylov = 0, cuts = 0;
  SNESConvergedReason reason = report.steps.empty() ? SNES_CONVERGED_ITERATING : report.steps.back().reason;
  for (const auto &r : report.steps) newton += r.newton, krylov += r.krylov, cuts += r.cuts;
  const PetscInt solved = (PetscInt)report.steps.size();
  if (dynamic && solved) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "steps %" PetscInt_FMT " newton per step %.2f krylov per newton %.2f\n", solved, (double)newton / solved, newton ? (double)krylov / newton : 0.0));
  PetscReal dmax, mesh = 0; /* the largest displacement, or velocity; the largest mesh displacement */
  PetscCall(FieldMax(dm, d, field, &dmax));
  if (sc.movingMesh) PetscCall(FieldMax(dm, d, fields.geometry, &mesh));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "newton %" PetscInt_FMT " krylov %" PetscInt_FMT " reason %s time %.3f s max %s %.6e\n", newton, krylov, SNESConvergedReasons[reason], t1 - t0, sc.physics == PHYSICS_FLUID ? "velocity" : "displacement", (double)dmax));
  char cure[160]; /* what to change: the load increments (statics) or the time step */
  if (dynamic) PetscCall(PetscSNPrintf(cure, sizeof(cure), "reduce the time step (-dt %g now) or allow more halvings (-max_step_cuts %" PetscInt_FMT " now)", (double)sc.dt, sc.maxCuts));
  else PetscCall(PetscSNPrintf(cure, sizeof(cure), "apply the load in more increments (-structure_load_steps %" PetscInt_FMT " now) or allow more halvings (-max_step_cuts %" PetscInt_FMT " now)", sc.loadSteps, sc.maxCuts));
  PetscCheck(reason != SNES_DIVERGED_FUNCTION_DOMAIN || !sc.movingMesh, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "Newton stopped in step %" PetscInt_FMT ": a cell of the moved fluid mesh inverted (J <= 0): the prescribed interface displacement is too large for its harmonic extension; reduce -geometry_amplitude (%g now)", solved ? report.steps.back().step : 0, (double)sc.geometryAmplitude);
  PetscCheck(reason != SNES_DIVERGED_FUNCTION_DOMAIN, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "Newton stopped in step %" PetscInt_FMT ": an element inverted (det F <= 0) in every step the line search tried, also on the step halved %" PetscInt_FMT " times; %s", solved ? report.steps.back().step : 0, sc.maxCuts, cure);
  if (reason == SNES_DIVERGED_LINEAR_SOLVE) {
    KSP                ksp;
    KSPConvergedReason kreason;
    PetscCall(SNESGetKSP(snes, &ksp));
    PetscCall(KSPGetConvergedReason(ksp, &kreason));
    SETERRQ(PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "the linear solver failed in step %" PetscInt_FMT " (%s, also on the step halved %" PetscInt_FMT " times); see -ksp_monitor_true_residual; CG needs a symmetric preconditioner (PCASM: -pc_asm_type basic); -pc_type lu -pc_factor_mat_solver_type mumps tells whether the preconditioner is the cause", report.steps.back().step, KSPConvergedReasons[kreason], sc.maxCuts);
  }
  PetscCheck(reason >= 0, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "Newton did not converge in step %" PetscInt_FMT " (%s, also on the step halved %" PetscInt_FMT " times); see -snes_monitor, or %s", solved ? report.steps.back().step : 0, SNESConvergedReasons[reason], sc.maxCuts, cure);
  PetscReal dnorm;
  PetscCall(VecNorm(d, NORM_2, &dnorm));
  if (sc.physics != PHYSICS_FLUID) report.results.insert(report.results.end(), {{"max_displacement", dmax}, {"displacement_norm", dnorm}});
  else report.results.insert(report.results.end(), {{"max_velocity", dmax}, {"solution_norm", dnorm}});
  if (sc.movingMesh) {
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "max mesh displacement %.6e\n", (double)mesh));
    report.results.push_back({"max_mesh_displacement", mesh});
  }
  PetscCall(Verify(sc, dm, b, d, dynamic ? loop.steps * step : 1.0, report));
  PetscCall(PhasesMeasure(PETSC_COMM_WORLD, t1 - t0, report.phases));
  const Phases &p = report.phases;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "seconds: assembly %.3f preconditioner setup %.3f krylov %.3f total %.3f; peak memory %.1f MiB\n", p.assembly, p.setup, p.krylov, p.total, p.peakMiB));
  if (sc.report[0]) PetscCall(WriteReport(sc.report, PETSC_COMM_WORLD, report));

  if (sc.output[0]) PetscCall(XdmfClose(series));
  PetscCall(GeometryPredictorDestroy(predictor));
  PetscCall(TimeHistoryDestroy(history));
  PetscCall(VecDestroy(&d));
  PetscCall(SNESDestroy(&snes));
  PetscCall(DMDestroy(&dm));
  PetscCall(PetscFinalize());
  return 0;
}
