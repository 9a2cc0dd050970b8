// SPDX-License-Identifier: BSD-2-Clause
#include "scene.h"
#include "discretization/fields.h"
#include "solver/block.h"
#include "io/files.h"
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>

namespace fsi {

const char *const PhysicsNames[] = {"structure", "fluid", "geometry", "fsi", "Physics", "PHYSICS_", nullptr};

PetscReal SmoothRamp(PetscReal t, PetscReal T, PetscReal *rate)
{
  const PetscBool rising = (PetscBool)(T > 0 && t < T);
  if (rate) *rate = rising ? PETSC_PI / (2 * T) * PetscSinReal(PETSC_PI * t / T) : 0.0;
  return rising ? PetscSqr(PetscSinReal(PETSC_PI * t / (2 * T))) : 1.0;
}

/* v as C's %g writes it (PETSc's %g writes 1 and nan as "1." and "nan."). */
static std::string Number(PetscReal v)
{
  char s[32];
  std::snprintf(s, sizeof(s), "%g", (double)v);
  return s;
}

/* The interval a number read from an option must lie in, each end open or closed: the
   physics' bounds (a density is positive, a ramp's length >= 0); any real number if unbounded. */
struct Range {
  PetscReal lo = -std::numeric_limits<PetscReal>::infinity(), hi = std::numeric_limits<PetscReal>::infinity();
  PetscBool openLo = PETSC_FALSE, openHi = PETSC_FALSE;

  PetscBool Contains(PetscReal v) const { return (PetscBool)((openLo ? v > lo : v >= lo) && (openHi ? v < hi : v <= hi)); }
  std::string Text() const
  {
    if (lo == 0 && openLo && PetscIsInfReal(hi)) return "positive";
    if (PetscIsInfReal(hi)) return std::string(openLo ? "> " : ">= ") + Number(lo);
    return std::string("in ") + (openLo ? "(" : "[") + Number(lo) + ", " + Number(hi) + (openHi ? ")" : "]");
  }
};
static const Range Any{}, Positive = {0, std::numeric_limits<PetscReal>::infinity(), PETSC_TRUE}, NonNegative = {0};
static Range AtLeast(PetscReal lo) { return {lo}; }

enum OptionRole { RUN, PROBLEM }; /* PROBLEM: defines the equations, their unknowns, conditions and loads */

/* Where the scene's options are read: every number is checked where it is read (finite, in its
   range), and the options that define the problem are recorded with their values, which a
   checkpoint keeps and a restart compares. */
struct OptionReader {
  PetscOptionItems *PetscOptionsObject; /* the name PETSc's PetscOptions*() macros use */
  Scene            &sc;

  PetscErrorCode Check(const char *name, const PetscReal *v, PetscInt n, const Range &r) const
  {
    PetscFunctionBegin;
    for (PetscInt i = 0; i < n; i++) {
      char which[32] = "value";
      if (n > 1) PetscCall(PetscSNPrintf(which, sizeof(which), "value %" PetscInt_FMT, i + 1));
      PetscCheck(!PetscIsInfOrNanReal(v[i]), PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "%s: %s must be a finite number (got %s)", name, which, Number(v[i]).c_str());
      PetscCheck(r.Contains(v[i]), PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "%s: %s must be %s (got %s)", name, which, r.Text().c_str(), Number(v[i]).c_str());
    }
    PetscFunctionReturn(0);
  }
  void Record(const char *name, OptionRole role, const std::string &value) const
  {
    if (role == PROBLEM) sc.problem[name] = value;
  }
  void Record(const char *name, OptionRole role, const PetscReal *v, PetscInt n) const
  {
    std::string s;
    char        x[32];
    for (PetscInt i = 0; i < n; i++) {
      std::snprintf(x, sizeof(x), "%.15g", (double)v[i]); /* as given, for a person to compare */
      s += (i ? "," : "") + std::string(x);
    }
    Record(name, role, s);
  }
  PetscErrorCode Real(const char *name, const char *text, PetscReal *v, const Range &r, OptionRole role) const
  {
    PetscBool given;

    PetscFunctionBegin;
    PetscCall(PetscOptionsReal(name, text, nullptr, *v, v, &given));
    if (given) PetscCall(Check(name, v, 1, r));
    Record(name, role, v, 1);
    PetscFunctionReturn(0);
  }
  /* up to *n values; *n is how many were given */
  PetscErrorCode Reals(const char *name, const char *text, PetscReal *v, PetscInt *n, PetscBool *set, const Range &r, OptionRole role) const
  {
    const PetscInt max = *n;
    PetscBool      given;

    PetscFunctionBegin;
    PetscCall(PetscOptionsRealArray(name, text, nullptr, v, n, &given));
    if (given) PetscCall(Check(name, v, *n, r));
    Record(name, role, v, given ? *n : max);
    if (set) *set = given;
    PetscFunctionReturn(0);
  }
  PetscErrorCode Int(const char *name, const char *text, PetscInt *v, const Range &r, OptionRole role) const
  {
    PetscReal x;
    PetscBool given;

    PetscFunctionBegin;
    PetscCall(PetscOptionsInt(name, text, nullptr, *v, v, &given));
    x = (PetscReal)*v;
    if (given) PetscCall(Check(name, &x, 1, r));
    Record(name, role, std::to_string(*v));
    PetscFunctionReturn(0);
  }
  PetscErrorCode String(const char *name, const char *text, char *v, size_t len, OptionRole role) const
  {
    PetscFunctionBegin;
    PetscCall(PetscOptionsString(name, text, nullptr, v, v, len, nullptr));
    Record(name, role, v);
    PetscFunctionReturn(0);
  }
  PetscErrorCode Bool(const char *name, const char *text, PetscBool *v, OptionRole role) const
  {
    PetscFunctionBegin;
    PetscCall(PetscOptionsBool(name, text, nullptr, *v, v, nullptr));
    Record(name, role, *v ? "true" : "false");
    PetscFunctionReturn(0);
  }
  /* A value that is not one of the n names of list stops the run with one message: PETSc's own
     parsers raise it on every rank. */
  PetscErrorCode CheckChoice(const char *name, const char *const *list, PetscInt n) const
  {
    char      value[256];
    PetscBool given, known = PETSC_FALSE;

    PetscFunctionBegin;
    PetscCall(PetscOptionsGetString(PetscOptionsObject->options, PetscOptionsObject->prefix, name, value, sizeof(value), &given));
    if (!given) PetscFunctionReturn(0);
    std::string names;
    for (PetscInt i = 0; i < n; i++) {
      PetscBool same;
      PetscCall(PetscStrcasecmp(value, list[i], &same));
      known = (PetscBool)(known || same);
      names += (i ? ", " : "") + std::string(list[i]);
    }
    PetscCheck(known, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "%s %s is not one of: %s", name, value, names.c_str());
    PetscFunctionReturn(0);
  }
  template <class E>
  PetscErrorCode Enum(const char *name, const char *text, const char *const *list, E *v, OptionRole role) const
  {
    PetscInt n = 0;

    PetscFunctionBegin;
    while (list[n + 2]) n++; /* PETSc's enum lists end with the type name, the prefix and a null */
    PetscCall(CheckChoice(name, list, n));
    PetscCall(PetscOptionsEnum(name, text, nullptr, list, (PetscEnum)*v, (PetscEnum *)v, nullptr));
    Record(name, role, list[*v]);
    PetscFunctionReturn(0);
  }
};

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

/* The files the run will write can be written, before it computes anything; a restart's
   output series continues the one it finds. */
static PetscErrorCode CheckOutputFiles(const Scene &sc)
{
  PetscFunctionBegin;
  if (sc.output[0]) {
    const std::string xdmf = sc.output, base = xdmf.substr(0, xdmf.size() - 5), h5 = base + ".h5";
    PetscCheck(xdmf.size() > 5 && xdmf.substr(xdmf.size() - 5) == ".xdmf", PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-output %s: name the file <name>.xdmf (the data go to <name>.h5)", sc.output);
    PetscCall(CheckWritable(PETSC_COMM_WORLD, "-output", xdmf));
    PetscCall(CheckWritable(PETSC_COMM_WORLD, "-output", h5));
    PetscCall(ClaimFile(PETSC_COMM_WORLD, "-output", xdmf)); /* a second run on the same series would destroy it */
    if (sc.restart[0])
      PetscCall(CheckOnRankZero(PETSC_COMM_WORLD, PETSC_ERR_FILE_OPEN, [&]() {
        return std::ifstream(h5) ? std::string() : "-output " + xdmf + " with -restart: the series continues in " + h5 + ", which is not there; give the -output of the run that wrote the checkpoint";
      }));
  }
  if (sc.checkpoint[0]) PetscCall(CheckWritable(PETSC_COMM_WORLD, "-checkpoint", sc.checkpoint));
  if (sc.report[0]) PetscCall(CheckWritable(PETSC_COMM_WORLD, "-report", sc.report, false)); /* /dev/stdout will do */
  PetscFunctionReturn(0);
}

PetscErrorCode ReadScene(Scene &sc)
{
  PetscInt  n;
  PetscBool set;
  char      blocks[256] = "";

  PetscFunctionBegin;
  PetscOptionsBegin(PETSC_COMM_WORLD, nullptr, "fsi_app scene", nullptr);
  const OptionReader opt{PetscOptionsObject, sc};
  PetscCall(opt.Enum("-physics", "what to solve: the wall, the fluid (with the geometry if -fluid_moving_mesh), the harmonic extension alone, or the coupled problem (fsi: structure, fluid, geometry, coupling)", PhysicsNames, &sc.physics, PROBLEM));
  PetscCall(opt.String("-blocks", "the blocks of the scene, comma separated, from structure, fluid, geometry, coupling (empty: those of -physics)", blocks, sizeof(blocks), PROBLEM));
  PetscCall(opt.String("-mesh", "gmsh mesh file", sc.mesh, sizeof(sc.mesh), PROBLEM));
  PetscCall(opt.Int("-refine", "uniform refinements of the mesh after distribution", &sc.refine, NonNegative, PROBLEM));
  PetscCall(opt.String("-structure_region", "physical group of the wall's cells (empty: every cell)", sc.region, sizeof(sc.region), PROBLEM));
  PetscCall(opt.String("-structure_clamp", "groups of faces where the displacement is zero, comma separated; group:xz fixes only those components", sc.clamp, sizeof(sc.clamp), PROBLEM));
  PetscCall(opt.Real("-structure_pressure", "pressure on the faces of -structure_pressure_group (dyn/cm^2)", &sc.pressure, Any, PROBLEM));
  PetscCall(opt.String("-structure_pressure_group", "group of faces the pressure acts on", sc.loaded, sizeof(sc.loaded), PROBLEM));
  PetscCall(opt.Bool("-structure_pressure_follower", "the pressure acts on the deformed face (follower load) rather than the reference one", &sc.follower, PROBLEM));
  n = 3;
  PetscCall(opt.Reals("-structure_body_force", "body force bx,by,bz per unit reference volume (dyn/cm^3)", sc.bodyForce, &n, &set, Any, PROBLEM));
  PetscCheck(!set || n == 3, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-structure_body_force: give bx,by,bz (got %" PetscInt_FMT " values)", n);
  n = 3;
  PetscCall(opt.Reals("-structure_traction", "dead traction tx,ty,tz per unit reference area on -structure_traction_group (dyn/cm^2)", sc.traction, &n, &set, Any, PROBLEM));
  PetscCheck(!set || n == 3, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-structure_traction: give tx,ty,tz (got %" PetscInt_FMT " values)", n);
  PetscCall(opt.String("-structure_traction_group", "group of faces the traction acts on", sc.tractionGroup, sizeof(sc.tractionGroup), PROBLEM));
  PetscCheck(!(sc.traction[0] != 0 || sc.traction[1] != 0 || sc.traction[2] != 0) || sc.tractionGroup[0], PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-structure_traction: name the faces it acts on with -structure_traction_group");
  PetscCall(opt.Real("-structure_pressure_ramp", "the pressure rises smoothly (sin^2) from 0 over this time (s); 0: a step at t = 0", &sc.ramp, NonNegative, PROBLEM));
  PetscCall(opt.Real("-structure_pressure_until", "the pressure acts while t <= this (s); 0: always", &sc.pulseEnd, NonNegative, PROBLEM));
  PetscCall(opt.Enum("-material", "constitutive law of the wall", MaterialNames, &sc.material, PROBLEM));
  PetscCall(opt.Real("-E", "Young's modulus (linear elastic)", &sc.E, Positive, PROBLEM));
  PetscCall(opt.Real("-nu", "Poisson ratio (linear elastic)", &sc.nu, Range{-1, 0.5, PETSC_TRUE, PETSC_TRUE}, PROBLEM));
  PetscCall(opt.Real("-nh_mu", "Neo-Hooke shear modulus (dyn/cm^2)", &sc.mu, Positive, PROBLEM));
  PetscCall(opt.Real("-nh_kappa", "Neo-Hooke bulk modulus (dyn/cm^2)", &sc.kappa, Positive, PROBLEM));
  n = 5;
  PetscCall(opt.Reals("-arterial", "arterial wall c1,eps1,eps2,alpha1,alpha2 (dyn/cm^2 for c1, eps1, alpha1)", sc.arterial, &n, &set, Any, PROBLEM));
  PetscCheck(!set || n == 5, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-arterial: give all five of c1,eps1,eps2,alpha1,alpha2 (got %" PetscInt_FMT ")", n);
  PetscCheck(sc.arterial[0] > 0 && sc.arterial[1] > 0 && sc.arterial[2] > 1 && sc.arterial[3] >= 0 && sc.arterial[4] >= 2, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE,
             "-arterial %g,%g,%g,%g,%g: need c1 > 0, eps1 > 0, eps2 > 1, alpha1 >= 0, alpha2 >= 2 (polyconvexity and a C2 energy)", (double)sc.arterial[0], (double)sc.arterial[1], (double)sc.arterial[2], (double)sc.arterial[3], (double)sc.arterial[4]);
  PetscCall(opt.Real("-arterial_fibre_angle", "angle of the two fibre families from the circumferential direction (degrees)", &sc.fibreAngle, Range{0, 90}, PROBLEM));
  PetscCall(opt.Real("-structure_density", "density of the wall (g/cm^3)", &sc.rho, Positive, PROBLEM));
  PetscCall(opt.Int("-structure_degree", "polynomial degree of the displacement", &sc.degree, Range{1, 3}, PROBLEM));
  PetscCall(opt.Int("-structure_subdomains", "GDSW subdomains per rank (METIS on the rank's cells)", &sc.subdomains, AtLeast(1), RUN));
  PetscCall(opt.CheckChoice("-structure_pc_setup", SplitSetUpNames, 3));
  PetscCall(PetscOptionsEList("-structure_pc_setup", "when the structure split's preconditioner is rebuilt (default: once for a linear wall, every time step otherwise)", nullptr, SplitSetUpNames, 3, sc.pcSetUp < 0 ? "auto" : SplitSetUpNames[sc.pcSetUp], &sc.pcSetUp, nullptr));
  PetscCall(opt.String("-fluid_region", "physical group of the fluid's cells", sc.fluidRegion, sizeof(sc.fluidRegion), PROBLEM));
  PetscCall(opt.String("-fluid_noslip", "groups of faces where the velocity is zero, comma separated", sc.noslip, sizeof(sc.noslip), PROBLEM));
  PetscCall(opt.Real("-fluid_density", "density of the fluid (g/cm^3)", &sc.rhoFluid, Positive, PROBLEM));
  PetscCall(opt.Real("-fluid_viscosity", "dynamic viscosity of the fluid (poise)", &sc.muFluid, Positive, PROBLEM));
  PetscCall(opt.Real("-fluid_inlet_pressure", "normal stress: traction -p n on the faces of -fluid_inlet (dyn/cm^2); the pulse ends at -structure_pressure_until", &sc.inletPressure, Any, PROBLEM));
  n = 3;
  PetscCall(opt.Reals("-fluid_inflow_velocity", "prescribed velocity ux,uy,uz on the faces of -fluid_inlet (cm/s; no-slip groups keep u = 0 on their nodes)", sc.inflowVelocity, &n, &sc.inflow, Any, PROBLEM));
  PetscCheck(!sc.inflow || n == 3, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-fluid_inflow_velocity: give ux,uy,uz (got %" PetscInt_FMT " values)", n);
  for (auto probe : {std::make_pair("-structure_probes", &sc.structureProbes), std::make_pair("-fluid_probes", &sc.fluidProbes)}) {
    PetscReal xyz[63] = {0}; /* room for a 21st point: PETSc drops values beyond the array silently */
    n = 63;
    PetscCall(opt.Reals(probe.first, probe.second == &sc.fluidProbes ? "points x1,y1,z1,x2,... (at most 20, reference configuration) where the pressure is recorded every step (in the run report); with -fluid_inlet_pressure, when the pulse's front (half its pressure) passes each and the wave speed" : "points x1,y1,z1,x2,... (at most 20, reference configuration) where the wall's displacement is recorded every step (in the run report)", xyz, &n, &set, Any, RUN));
    PetscCheck(!set || n <= 60, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "%s: at most 20 points (got more than 20)", probe.first);
    PetscCheck(!set || (n > 0 && n % 3 == 0), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s: give x,y,z for each point (got %" PetscInt_FMT " values)", probe.first, n);
    if (set) probe.second->assign(xyz, xyz + n);
  }
  PetscCall(opt.String("-fluid_inlet", "group of the inflow faces", sc.inlet, sizeof(sc.inlet), PROBLEM));
  PetscCall(opt.String("-fluid_outlet", "group of the outflow faces (stress-free)", sc.outlet, sizeof(sc.outlet), PROBLEM));
  PetscCall(opt.String("-geometry_interface", "group where the fluid's mesh displacement is the structure's", sc.interface, sizeof(sc.interface), PROBLEM));
  PetscCall(opt.String("-geometry_slip", "groups where the mesh slides: the listed components are zero (planar ends: group:z)", sc.slip, sizeof(sc.slip), PROBLEM));
  PetscCall(opt.Real("-geometry_amplitude", "amplitude a of the prescribed interface displacement a s(t) (x^2 - y^2, -2xy, 0) (-physics geometry, -fluid_moving_mesh)", &sc.geometryAmplitude, Any, PROBLEM));
  PetscCall(opt.Real("-geometry_ramp", "the prescribed interface displacement rises as s(t) = sin^2(pi t / 2T) over this time T (s); 0: at once", &sc.geometryRamp, NonNegative, PROBLEM));
  PetscCall(opt.Bool("-fluid_shape_derivatives", "on a moving mesh, the fluid's Jacobian holds its derivative in the mesh displacement (exact Newton); false: quasi-Newton", &sc.shapeDerivatives, RUN));
  PetscCall(opt.Bool("-fluid_moving_mesh", "-physics fluid: the mesh moves (ALE) with the harmonic extension of the prescribed interface displacement", &sc.movingMesh, PROBLEM));
  n = 3;
  PetscCall(opt.Reals("-poiseuille", "verification: Hagen-Poiseuille flow in a tube of radius R and length L along z driven by a pressure drop: R,L,dp", sc.poiseuille, &n, &set, Any, PROBLEM));
  PetscCheck(!set || (n == 3 && sc.poiseuille[0] > 0 && sc.poiseuille[1] > 0), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-poiseuille: give R,L,dp with R > 0 and L > 0");
  PetscCall(opt.Real("-dt", "time step (s); 0 solves the static problem", &sc.dt, NonNegative, RUN)); /* the checkpoint's header compares it */
  PetscCall(opt.Real("-t_final", "end time (s), a whole number of steps", &sc.tFinal, NonNegative, RUN));
  PetscCall(opt.Enum("-time_scheme", "differences in time for the inertia", TimeSchemeNames, &sc.scheme, RUN));
  PetscCall(opt.Int("-structure_load_steps", "apply the load in this many equal increments (statics)", &sc.loadSteps, Range{1, 10000}, RUN));
  PetscCall(opt.Int("-max_step_cuts", "a failed step (Newton diverged, element inverted) is halved up to this many times before the run stops", &sc.maxCuts, Range{0, 20}, RUN));
  PetscCall(opt.Bool("-mms", "manufactured solution d = a sin(pi x)sin(pi y)sin(pi z)(1,1,1) on the unit cube", &sc.mms, PROBLEM));
  PetscCall(opt.Real("-mms_amplitude", "the amplitude a of the manufactured solution", &sc.mmsAmplitude, Any, PROBLEM));
  PetscCall(opt.Enum("-mms_flow", "-physics fluid -mms: the manufactured flow (exact velocity on the boundary but -fluid_outlet, exact traction there)", FlowMMSKindNames, &sc.mmsFlow, PROBLEM));
  PetscCall(opt.Real("-mms_ramp", "the trigonometric manufactured flow rises as sin^2(pi t / 2T) over this time T (s); 0: steady", &sc.mmsRamp, NonNegative, PROBLEM));
  n = 2;
  PetscCall(opt.Reals("-lame", "verification against Lame's cylinder: inner,outer radius", sc.lameRadii, &n, &set, Positive, RUN));
  PetscCheck(!set || n == 2, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-lame: give the inner and the outer radius, Ri,Ro (got %" PetscInt_FMT " values)", n);
  PetscCheck(!set || sc.lameRadii[0] < sc.lameRadii[1], PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-lame %s,%s: the inner radius must be smaller than the outer one (give Ri,Ro)", Number(sc.lameRadii[0]).c_str(), Number(sc.lameRadii[1]).c_str());
  PetscCall(opt.String("-output", "XDMF file of the solution over time (+ .h5 beside it); empty: none", sc.output, sizeof(sc.output), RUN));
  PetscCall(opt.Int("-output_every", "write every n-th step", &sc.outputEvery, AtLeast(1), RUN));
  PetscCall(opt.String("-checkpoint", "checkpoint file (PETSc binary); empty: none", sc.checkpoint, sizeof(sc.checkpoint), RUN));
  PetscCall(opt.Int("-checkpoint_every", "write the checkpoint every n-th step", &sc.checkpointEvery, AtLeast(1), RUN));
  PetscCall(opt.String("-restart", "continue from this checkpoint (same mesh, options and number of ranks)", sc.restart, sizeof(sc.restart), RUN));
  PetscCall(opt.String("-report", "run report (JSON): unknowns, iterations per step, errors, time per phase, memory; empty: none", sc.report, sizeof(sc.report), RUN));
  PetscOptionsEnd();
  PetscCall(CheckTimeSteps(sc));
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
  PetscCall(CheckOutputFiles(sc));
  PetscFunctionReturn(0);
}

} // namespace fsi
