#include "scene.h"
#include "discretization/fields.h"
#include "solver/block.h"
#include <algorithm>

namespace fsi {

const char *const PhysicsNames[] = {"structure", "fluid", "geometry", "fsi", "Physics", "PHYSICS_", nullptr};

PetscReal SmoothRamp(PetscReal t, PetscReal T, PetscReal *rate)
{
  const PetscBool rising = (PetscBool)(T > 0 && t < T);
  if (rate) *rate = rising ? PETSC_PI / (2 * T) * PetscSinReal(PETSC_PI * t / T) : 0.0;
  return rising ? PetscSqr(PetscSinReal(PETSC_PI * t / (2 * T))) : 1.0;
}

PetscErrorCode ReadScene(Scene &sc)
{
  PetscInt  n;
  PetscBool set;
  char      blocks[256] = "";

  PetscFunctionBegin;
  PetscOptionsBegin(PETSC_COMM_WORLD, nullptr, "fsi_app scene", nullptr);
  PetscCall(PetscOptionsEnum("-physics", "what to solve: the wall, the fluid (with the geometry if -fluid_moving_mesh), the harmonic extension alone, or the coupled problem (fsi: structure, fluid, geometry, coupling)", nullptr, PhysicsNames, (PetscEnum)sc.physics, (PetscEnum *)&sc.physics, nullptr));
  PetscCall(PetscOptionsString("-blocks", "the blocks of the scene, comma separated, from structure, fluid, geometry, coupling (empty: those of -physics)", nullptr, blocks, blocks, sizeof(blocks), nullptr));
  PetscCall(PetscOptionsString("-mesh", "gmsh mesh file", nullptr, sc.mesh, sc.mesh, sizeof(sc.mesh), nullptr));
  PetscCall(PetscOptionsInt("-refine", "uniform refinements of the mesh after distribution", nullptr, sc.refine, &sc.refine, nullptr));
  PetscCall(PetscOptionsString("-structure_region", "physical group of the wall's cells (empty: every cell)", nullptr, sc.region, sc.region, sizeof(sc.region), nullptr));
  PetscCall(PetscOptionsString("-structure_clamp", "groups of faces where the displacement is zero, comma separated; group:xz fixes only those components", nullptr, sc.clamp, sc.clamp, sizeof(sc.clamp), nullptr));
  PetscCall(PetscOptionsReal("-structure_pressure", "pressure on the faces of -structure_pressure_group (dyn/cm^2)", nullptr, sc.pressure, &sc.pressure, nullptr));
  PetscCall(PetscOptionsString("-structure_pressure_group", "group of faces the pressure acts on", nullptr, sc.loaded, sc.loaded, sizeof(sc.loaded), nullptr));
  PetscCall(PetscOptionsBool("-structure_pressure_follower", "the pressure acts on the deformed face (follower load) rather than the reference one", nullptr, sc.follower, &sc.follower, nullptr));
  n = 3;
  PetscCall(PetscOptionsRealArray("-structure_body_force", "body force bx,by,bz per unit reference volume (dyn/cm^3)", nullptr, sc.bodyForce, &n, &set));
  PetscCheck(!set || n == 3, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-structure_body_force: give bx,by,bz (got %" PetscInt_FMT " values)", n);
  n = 3;
  PetscCall(PetscOptionsRealArray("-structure_traction", "dead traction tx,ty,tz per unit reference area on -structure_traction_group (dyn/cm^2)", nullptr, sc.traction, &n, &set));
  PetscCheck(!set || n == 3, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-structure_traction: give tx,ty,tz (got %" PetscInt_FMT " values)", n);
  PetscCall(PetscOptionsString("-structure_traction_group", "group of faces the traction acts on", nullptr, sc.tractionGroup, sc.tractionGroup, sizeof(sc.tractionGroup), nullptr));
  PetscCheck(!(sc.traction[0] != 0 || sc.traction[1] != 0 || sc.traction[2] != 0) || sc.tractionGroup[0], PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-structure_traction: name the faces it acts on with -structure_traction_group");
  PetscCall(PetscOptionsReal("-structure_pressure_ramp", "the pressure rises smoothly (sin^2) from 0 over this time (s); 0: a step at t = 0", nullptr, sc.ramp, &sc.ramp, nullptr));
  PetscCall(PetscOptionsReal("-structure_pressure_until", "the pressure acts while t <= this (s); 0: always", nullptr, sc.pulseEnd, &sc.pulseEnd, nullptr));
  PetscCall(PetscOptionsEnum("-material", "constitutive law of the wall", nullptr, MaterialNames, (PetscEnum)sc.material, (PetscEnum *)&sc.material, nullptr));
  PetscCall(PetscOptionsReal("-E", "Young's modulus (linear elastic)", nullptr, sc.E, &sc.E, nullptr));
  PetscCall(PetscOptionsReal("-nu", "Poisson ratio (linear elastic)", nullptr, sc.nu, &sc.nu, nullptr));
  PetscCall(PetscOptionsReal("-nh_mu", "Neo-Hooke shear modulus (dyn/cm^2)", nullptr, sc.mu, &sc.mu, nullptr));
  PetscCall(PetscOptionsReal("-nh_kappa", "Neo-Hooke bulk modulus (dyn/cm^2)", nullptr, sc.kappa, &sc.kappa, nullptr));
  n = 5;
  PetscCall(PetscOptionsRealArray("-arterial", "arterial wall c1,eps1,eps2,alpha1,alpha2 (dyn/cm^2 for c1, eps1, alpha1)", nullptr, sc.arterial, &n, &set));
  PetscCheck(!set || n == 5, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-arterial: give all five of c1,eps1,eps2,alpha1,alpha2 (got %" PetscInt_FMT ")", n);
  PetscCall(PetscOptionsReal("-arterial_fibre_angle", "angle of the two fibre families from the circumferential direction (degrees)", nullptr, sc.fibreAngle, &sc.fibreAngle, nullptr));
  PetscCall(PetscOptionsReal("-structure_density", "density of the wall (g/cm^3)", nullptr, sc.rho, &sc.rho, nullptr));
  PetscCall(PetscOptionsInt("-structure_degree", "polynomial degree of the displacement", nullptr, sc.degree, &sc.degree, nullptr));
  PetscCall(PetscOptionsInt("-structure_subdomains", "GDSW subdomains per rank (METIS on the rank's cells)", nullptr, sc.subdomains, &sc.subdomains, nullptr));
  PetscCall(PetscOptionsEList("-structure_pc_setup", "when the structure split's preconditioner is rebuilt (default: once for a linear wall, every time step otherwise)", nullptr, SplitSetUpNames, 3, sc.pcSetUp < 0 ? "auto" : SplitSetUpNames[sc.pcSetUp], &sc.pcSetUp, nullptr));
  PetscCall(PetscOptionsString("-fluid_region", "physical group of the fluid's cells", nullptr, sc.fluidRegion, sc.fluidRegion, sizeof(sc.fluidRegion), nullptr));
  PetscCall(PetscOptionsString("-fluid_noslip", "groups of faces where the velocity is zero, comma separated", nullptr, sc.noslip, sc.noslip, sizeof(sc.noslip), nullptr));
  PetscCall(PetscOptionsReal("-fluid_density", "density of the fluid (g/cm^3)", nullptr, sc.rhoFluid, &sc.rhoFluid, nullptr));
  PetscCall(PetscOptionsReal("-fluid_viscosity", "dynamic viscosity of the fluid (poise)", nullptr, sc.muFluid, &sc.muFluid, nullptr));
  PetscCall(PetscOptionsReal("-fluid_inlet_pressure", "normal stress: traction -p n on the faces of -fluid_inlet (dyn/cm^2); the pulse ends at -structure_pressure_until", nullptr, sc.inletPressure, &sc.inletPressure, nullptr));
  n = 3;
  PetscCall(PetscOptionsRealArray("-fluid_inflow_velocity", "prescribed velocity ux,uy,uz on the faces of -fluid_inlet (cm/s; no-slip groups keep u = 0 on their nodes)", nullptr, sc.inflowVelocity, &n, &sc.inflow));
  PetscCheck(!sc.inflow || n == 3, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-fluid_inflow_velocity: give ux,uy,uz (got %" PetscInt_FMT " values)", n);
  for (auto probe : {std::make_pair("-structure_probes", &sc.structureProbes), std::make_pair("-fluid_probes", &sc.fluidProbes)}) {
    PetscReal xyz[60];
    n = 60;
    PetscCall(PetscOptionsRealArray(probe.first, probe.second == &sc.fluidProbes ? "points x1,y1,z1,x2,... (at most 20, reference configuration) where the pressure is recorded every step (in the run report); with -fluid_inlet_pressure, when the pulse's front (half its pressure) passes each and the wave speed" : "points x1,y1,z1,x2,... (at most 20, reference configuration) where the wall's displacement is recorded every step (in the run report)", nullptr, xyz, &n, &set));
    PetscCheck(!set || (n > 0 && n % 3 == 0), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s: give x,y,z for each point (got %" PetscInt_FMT " values)", probe.first, n);
    if (set) probe.second->assign(xyz, xyz + n);
  }
  PetscCall(PetscOptionsString("-fluid_inlet", "group of the inflow faces", nullptr, sc.inlet, sc.inlet, sizeof(sc.inlet), nullptr));
  PetscCall(PetscOptionsString("-fluid_outlet", "group of the outflow faces (stress-free)", nullptr, sc.outlet, sc.outlet, sizeof(sc.outlet), nullptr));
  PetscCall(PetscOptionsString("-geometry_interface", "group where the fluid's mesh displacement is the structure's", nullptr, sc.interface, sc.interface, sizeof(sc.interface), nullptr));
  PetscCall(PetscOptionsString("-geometry_slip", "groups where the mesh slides: the listed components are zero (planar ends: group:z)", nullptr, sc.slip, sc.slip, sizeof(sc.slip), nullptr));
  PetscCall(PetscOptionsReal("-geometry_amplitude", "amplitude a of the prescribed interface displacement a s(t) (x^2 - y^2, -2xy, 0) (-physics geometry, -fluid_moving_mesh)", nullptr, sc.geometryAmplitude, &sc.geometryAmplitude, nullptr));
  PetscCall(PetscOptionsReal("-geometry_ramp", "the prescribed interface displacement rises as s(t) = sin^2(pi t / 2T) over this time T (s); 0: at once", nullptr, sc.geometryRamp, &sc.geometryRamp, nullptr));
  PetscCall(PetscOptionsBool("-fluid_shape_derivatives", "on a moving mesh, the fluid's Jacobian holds its derivative in the mesh displacement (exact Newton); false: quasi-Newton", nullptr, sc.shapeDerivatives, &sc.shapeDerivatives, nullptr));
  PetscCall(PetscOptionsBool("-fluid_moving_mesh", "-physics fluid: the mesh moves (ALE) with the harmonic extension of the prescribed interface displacement", nullptr, sc.movingMesh, &sc.movingMesh, nullptr));
  n = 3;
  PetscCall(PetscOptionsRealArray("-poiseuille", "verification: Hagen-Poiseuille flow in a tube of radius R and length L along z driven by a pressure drop: R,L,dp", nullptr, sc.poiseuille, &n, &set));
  PetscCheck(!set || (n == 3 && sc.poiseuille[0] > 0 && sc.poiseuille[1] > 0), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-poiseuille: give R,L,dp with R > 0 and L > 0");
  PetscCall(PetscOptionsReal("-dt", "time step (s); 0 solves the static problem", nullptr, sc.dt, &sc.dt, nullptr));
  PetscCall(PetscOptionsReal("-t_final", "end time (s)", nullptr, sc.tFinal, &sc.tFinal, nullptr));
  PetscCall(PetscOptionsEnum("-time_scheme", "differences in time for the inertia", nullptr, TimeSchemeNames, (PetscEnum)sc.scheme, (PetscEnum *)&sc.scheme, nullptr));
  PetscCall(PetscOptionsInt("-structure_load_steps", "apply the load in this many equal increments (statics)", nullptr, sc.loadSteps, &sc.loadSteps, nullptr));
  PetscCall(PetscOptionsInt("-max_step_cuts", "a failed step (Newton diverged, element inverted) is halved up to this many times before the run stops", nullptr, sc.maxCuts, &sc.maxCuts, nullptr));
  PetscCall(PetscOptionsBool("-mms", "manufactured solution d = a sin(pi x)sin(pi y)sin(pi z)(1,1,1) on the unit cube", nullptr, sc.mms, &sc.mms, nullptr));
  PetscCall(PetscOptionsReal("-mms_amplitude", "the amplitude a of the manufactured solution", nullptr, sc.mmsAmplitude, &sc.mmsAmplitude, nullptr));
  PetscCall(PetscOptionsEnum("-mms_flow", "-physics fluid -mms: the manufactured flow (exact velocity on the boundary but -fluid_outlet, exact traction there)", nullptr, FlowMMSKindNames, (PetscEnum)sc.mmsFlow, (PetscEnum *)&sc.mmsFlow, nullptr));
  PetscCall(PetscOptionsReal("-mms_ramp", "the trigonometric manufactured flow rises as sin^2(pi t / 2T) over this time T (s); 0: steady", nullptr, sc.mmsRamp, &sc.mmsRamp, nullptr));
  n = 2;
  PetscCall(PetscOptionsRealArray("-lame", "verification against Lame's cylinder: inner,outer radius", nullptr, sc.lameRadii, &n, nullptr));
  PetscCall(PetscOptionsString("-output", "XDMF file of the solution over time (+ .h5 beside it); empty: none", nullptr, sc.output, sc.output, sizeof(sc.output), nullptr));
  PetscCall(PetscOptionsInt("-output_every", "write every n-th step", nullptr, sc.outputEvery, &sc.outputEvery, nullptr));
  PetscCall(PetscOptionsString("-checkpoint", "checkpoint file (PETSc binary); empty: none", nullptr, sc.checkpoint, sc.checkpoint, sizeof(sc.checkpoint), nullptr));
  PetscCall(PetscOptionsInt("-checkpoint_every", "write the checkpoint every n-th step", nullptr, sc.checkpointEvery, &sc.checkpointEvery, nullptr));
  PetscCall(PetscOptionsString("-restart", "continue from this checkpoint (same mesh, options and number of ranks)", nullptr, sc.restart, sc.restart, sizeof(sc.restart), nullptr));
  PetscCall(PetscOptionsString("-report", "run report (JSON): unknowns, iterations per step, errors, time per phase, memory; empty: none", nullptr, sc.report, sc.report, sizeof(sc.report), nullptr));
  PetscOptionsEnd();
  PetscCheck(sc.E > 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-E %g: Young's modulus must be positive", (double)sc.E);
  PetscCheck(sc.nu > -1 && sc.nu < 0.5, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-nu %g: the Poisson ratio must lie in (-1, 0.5)", (double)sc.nu);
  PetscCheck(sc.mu > 0 && sc.kappa > 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-nh_mu %g -nh_kappa %g: both moduli must be positive", (double)sc.mu, (double)sc.kappa);
  PetscCheck(sc.arterial[0] > 0 && sc.arterial[1] > 0 && sc.arterial[2] > 1 && sc.arterial[3] >= 0 && sc.arterial[4] >= 2, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE,
             "-arterial %g,%g,%g,%g,%g: need c1 > 0, eps1 > 0, eps2 > 1, alpha1 >= 0, alpha2 >= 2 (polyconvexity and a C2 energy)", (double)sc.arterial[0], (double)sc.arterial[1], (double)sc.arterial[2], (double)sc.arterial[3], (double)sc.arterial[4]);
  PetscCheck(sc.fibreAngle >= 0 && sc.fibreAngle <= 90, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-arterial_fibre_angle %g: degrees in [0, 90]", (double)sc.fibreAngle);
  PetscCheck(sc.degree >= 1 && sc.degree <= 3, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-structure_degree %" PetscInt_FMT ": use 1, 2 or 3", sc.degree);
  PetscCheck(sc.dt >= 0 && (sc.dt == 0 || sc.tFinal >= sc.dt), PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-dt %g -t_final %g: need 0 <= dt <= t_final", (double)sc.dt, (double)sc.tFinal);
  PetscCheck(sc.geometryRamp >= 0 && sc.mmsRamp >= 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-geometry_ramp %g -mms_ramp %g: must be >= 0", (double)sc.geometryRamp, (double)sc.mmsRamp);
  PetscCheck(!sc.movingMesh || sc.physics == PHYSICS_FLUID, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-fluid_moving_mesh: only with -physics fluid (-physics %s)", PhysicsNames[sc.physics]);
  if (blocks[0]) sc.blocks = SplitList(blocks);
  else if (sc.physics == PHYSICS_FSI) sc.blocks = {"structure", "fluid", "geometry", "coupling"};
  else if (sc.physics == PHYSICS_FLUID && sc.movingMesh) sc.blocks = {"fluid", "geometry"};
  else sc.blocks = {PhysicsNames[sc.physics]};
  const PetscBool coupled = (PetscBool)(std::find(sc.blocks.begin(), sc.blocks.end(), "coupling") != sc.blocks.end());
  for (const auto &g : SplitList(sc.noslip))
    PetscCheck(!coupled || g.substr(0, g.find(':')) != sc.interface, PETSC_COMM_WORLD, PETSC_ERR_ARG_INCOMP, "-fluid_noslip %s: on the interface %s the fluid moves with the wall (the coupling's u = d_t d_s); remove it from -fluid_noslip", sc.noslip, sc.interface);
  PetscCheck(!sc.inflow || (sc.inletPressure == 0 && !sc.mms && sc.poiseuille[0] == 0), PETSC_COMM_WORLD, PETSC_ERR_ARG_INCOMP, "-fluid_inflow_velocity: the inlet cannot also take -fluid_inlet_pressure, -mms or -poiseuille (one condition per face)");
  PetscCheck(!sc.movingMesh || !sc.noslip[0], PETSC_COMM_WORLD, PETSC_ERR_SUP, "-fluid_moving_mesh with -fluid_noslip %s: a wall that moves needs u = w (the mesh velocity) there, which the coupling to the structure will impose; until then a moving mesh takes the manufactured flows' boundary values (-mms) and -fluid_noslip must be empty", sc.noslip);
  PetscCheck(sc.ramp >= 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-structure_pressure_ramp %g: must be >= 0", (double)sc.ramp);
  PetscCheck(sc.rhoFluid > 0 && sc.muFluid > 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-fluid_density %g -fluid_viscosity %g: both must be positive", (double)sc.rhoFluid, (double)sc.muFluid);
  PetscCheck(sc.rho > 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-structure_density %g: must be positive", (double)sc.rho);
  PetscCheck(sc.loadSteps >= 1, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-structure_load_steps %" PetscInt_FMT ": at least 1", sc.loadSteps);
  PetscCheck(sc.maxCuts >= 0 && sc.maxCuts <= 20, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-max_step_cuts %" PetscInt_FMT ": between 0 and 20", sc.maxCuts);
  PetscCheck(sc.subdomains >= 1, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-structure_subdomains %" PetscInt_FMT ": at least 1", sc.subdomains);
  PetscCheck(sc.outputEvery >= 1 && sc.checkpointEvery >= 1, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-output_every %" PetscInt_FMT " -checkpoint_every %" PetscInt_FMT ": at least 1", sc.outputEvery, sc.checkpointEvery);
  PetscFunctionReturn(0);
}

} // namespace fsi
