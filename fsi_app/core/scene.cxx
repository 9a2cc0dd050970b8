// SPDX-License-Identifier: BSD-2-Clause
#include "scene.h"
#include "discretization/fields.h"
#include "base/options.h"

namespace fsi {

/* dt and t_final give a whole number of steps, at least one, that a PetscInt counts. */
static PetscErrorCode CheckTimeSteps(const Scene &sc)
{
  const PetscReal   steps = sc.tFinal / sc.dt, whole = PetscFloorReal(steps + 0.5);
  const std::string both  = "-dt " + Number(sc.dt) + " -t_final " + Number(sc.tFinal);

  PetscFunctionBegin;
  if (!sc.Dynamic()) PetscFunctionReturn(0);
  PetscCheck(steps > 1 - 1e-6, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "%s: the end time must be at least one step", both.c_str());
  PetscCheck(whole <= PETSC_MAX_INT, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "%s: %s steps, more than a run can count (%d)", both.c_str(), Number(steps).c_str(), PETSC_MAX_INT);
  PetscCheck(PetscAbsReal(steps - whole) <= 1e-6, PETSC_COMM_WORLD, PETSC_ERR_ARG_INCOMP, "%s: the end time must be a whole number of steps (it is %s steps): take -t_final %s or %s, or a -dt that divides it", both.c_str(), Number(steps).c_str(),
             Number(PetscFloorReal(steps) * sc.dt).c_str(), Number(PetscCeilReal(steps) * sc.dt).c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode ReadScene(Scene &sc)
{
  char blocks[256] = "structure";

  PetscFunctionBegin;
  PetscOptionsBegin(PETSC_COMM_WORLD, nullptr, "fsi_app: the scene (each block's options follow under its own title)", nullptr);
  const OptionReader opt{PetscOptionsObject, sc.problem};
  PetscCall(opt.String("-blocks", "the blocks of the scene, comma separated, from structure, fluid, geometry, coupling: structure,fluid,geometry,coupling is the coupled problem; fluid,geometry a fluid on a mesh moved by a prescribed interface displacement (ALE)", blocks, sizeof(blocks), PROBLEM));
  PetscCall(opt.String("-mesh", "gmsh mesh file (named in an options file: relative to that file)", sc.mesh, sizeof(sc.mesh), PROBLEM));
  PetscCall(opt.Int("-refine", "uniform refinements of the mesh after distribution (each multiplies the cells by 8)", &sc.refine, NonNegative, PROBLEM));
  PetscCall(opt.Int("-mesh_order", "the cells' geometry: 2 curved (isoparametric P2) by the file's second-order nodes, 1 straight (the vertices only), 0 as the file is", &sc.meshOrder, Range{0, 2}, PROBLEM));
  PetscCall(opt.Bool("-mesh_reorder", "number the mesh's points by reverse Cuthill-McKee of its cells before distributing them, so that a cell's unknowns lie near each other in vectors and matrices (the Jacobian's assembly and products run from cache); false: the file's order", &sc.meshReorder, PROBLEM));
  PetscCall(opt.Real("-dt", "time step (s); 0 solves the static problem", &sc.dt, NonNegative, RUN)); /* the checkpoint's header compares it */
  PetscCall(opt.Real("-t_final", "end time (s), a whole number of steps", &sc.tFinal, NonNegative, RUN));
  PetscCall(opt.Enum("-time_scheme", "differences in time for the inertia", TimeSchemeNames, &sc.scheme, RUN));
  PetscCall(opt.Int("-structure_load_steps", "apply the load in this many equal increments (statics)", &sc.loadSteps, Range{1, 10000}, RUN));
  PetscCall(opt.Int("-max_step_cuts", "a failed step (Newton diverged, element inverted) is halved up to this many times before the run stops", &sc.maxCuts, Range{0, 20}, RUN));
  PetscCall(opt.Int("-max_workspace_raises", "a direct solver (MUMPS) that runs out of workspace gets twice its room (its -..._mat_mumps_icntl_14, said on stdout) and the step is repeated, up to this many times in the run; 0: the run stops and names the option", &sc.maxWorkspaceRaises, Range{0, 10}, RUN));
  PetscCall(opt.Int("-time_predictor_order", "Newton's first iterate of a time step: the polynomial through the last k+1 states extrapolated to the new time (0: the last state; at most 1 with backward_euler, 3 with bdf2)", &sc.predictorOrder, Range{0, 3}, RUN));
  PetscCall(opt.Bool("-jacobian_keep_constant", "assemble the Jacobian rows that never change (the harmonic extension's) once and keep their values; false: at every Newton step", &sc.keepConstant, RUN));
  PetscCall(opt.Bool("-jacobian_direct_add", "add the element matrices straight into the Jacobian's CSR storage (AIJ); false: through MatSetValues", &sc.directAdd, RUN));
  PetscCall(opt.Bool("-mms", "verification: each block's manufactured solution (the wall: -mms_amplitude on the unit cube; the fluid: -mms_flow)", &sc.mms, PROBLEM));
  PetscCall(opt.String("-output", "XDMF file of the solution over time (+ .h5 beside it); empty: none", sc.output, sizeof(sc.output), RUN));
  PetscCall(opt.Int("-output_every", "write every n-th step", &sc.outputEvery, AtLeast(1), RUN));
  PetscCall(opt.String("-checkpoint", "checkpoint file (PETSc binary); empty: none", sc.checkpoint, sizeof(sc.checkpoint), RUN));
  PetscCall(opt.Int("-checkpoint_every", "write the checkpoint every n-th step", &sc.checkpointEvery, AtLeast(1), RUN));
  PetscCall(opt.Int("-checkpoint_keep", "keep the newest n checkpoints as <checkpoint>.<step> too (hard links; the file of -checkpoint is always the newest)", &sc.checkpointKeep, AtLeast(1), RUN));
  PetscCall(opt.String("-restart", "continue from this checkpoint (same mesh, options and number of ranks)", sc.restart, sizeof(sc.restart), RUN));
  PetscCall(opt.String("-report", "run report (JSON): unknowns, iterations per step, errors, time per phase, memory; empty: none", sc.report, sizeof(sc.report), RUN));
  PetscOptionsEnd();
  PetscCall(CheckTimeSteps(sc));
  PetscCheck(sc.predictorOrder <= (sc.scheme == BDF2 ? 3 : 1), PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-time_predictor_order %" PetscInt_FMT ": backward_euler keeps 2 past states, so the order is at most 1 (bdf2: 3)", sc.predictorOrder);
  sc.blocks = SplitList(blocks);
  PetscFunctionReturn(0);
}

} // namespace fsi
