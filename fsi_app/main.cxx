static const char help[] = "fsi_app: monolithic fluid-structure interaction on PETSc (so far: the structure block,\n"
                           "linear elastic statics, and its verification). Scenes are options files: -options_file scenes/X.opts\n";

#include "discretization/fields.h"
#include "mesh/mesh.h"
#include "solver/subdomains.h"
#include "structure/assembly.h"
#include "verification/mms.h"
#include <petscgdsw.h>
#include <petscsnes.h>

using namespace fsi;

struct Scene {
  char      mesh[PETSC_MAX_PATH_LEN] = "meshes/cube_L0.msh";
  PetscInt  refine                   = 0;
  char      region[64]               = "";   /* group of the structure's cells ("" all) */
  char      clamp[256]               = "";   /* groups with d = 0 */
  PetscBool mms                      = PETSC_FALSE;
  PetscReal lameRadii[2]             = {0, 0}; /* Lame verification: inner and outer radius */
  PetscReal pressure                 = 0;    /* dead pressure on the faces of group `loaded` */
  char      loaded[64]               = "interface";
  Material  material                 = LINEAR_ELASTIC;
  PetscReal E = 1.0, nu = 0.3;        /* linear elastic */
  PetscReal mu = 7.72e4, kappa = 3.833e6; /* Neo-Hooke (dyn/cm^2: 7.72 kPa, 383.3 kPa) */
  PetscInt  degree = 2, subdomains = 1;
  PetscInt  loadSteps = 1; /* statics: the load in equal increments, one Newton solve each */
  PetscReal dt = 0, tFinal = 0.01, rho = 1.2; /* dynamics when dt > 0 (s, g/cm^3) */
  PetscReal pulseEnd = 0;                      /* the pressure acts for t <= pulseEnd (0: always) */
};

static std::vector<std::string> Split(const char *s)
{
  std::vector<std::string> out;
  for (std::string r = s; !r.empty();) {
    const size_t k = r.find(',');
    out.push_back(r.substr(0, k));
    r = k == std::string::npos ? "" : r.substr(k + 1);
  }
  return out;
}

static PetscErrorCode ReadScene(Scene &sc)
{
  PetscFunctionBegin;
  PetscOptionsBegin(PETSC_COMM_WORLD, nullptr, "fsi_app scene", nullptr);
  PetscCall(PetscOptionsString("-mesh", "gmsh mesh file", nullptr, sc.mesh, sc.mesh, sizeof(sc.mesh), nullptr));
  PetscCall(PetscOptionsInt("-refine", "uniform refinements of the mesh after distribution", nullptr, sc.refine, &sc.refine, nullptr));
  PetscCall(PetscOptionsString("-structure_region", "physical group of the wall's cells (empty: every cell)", nullptr, sc.region, sc.region, sizeof(sc.region), nullptr));
  PetscCall(PetscOptionsString("-structure_clamp", "groups of faces where the displacement is zero, comma separated; group:xz fixes only those components", nullptr, sc.clamp, sc.clamp, sizeof(sc.clamp), nullptr));
  PetscCall(PetscOptionsReal("-structure_pressure", "pressure on the faces of -structure_pressure_group (dyn/cm^2)", nullptr, sc.pressure, &sc.pressure, nullptr));
  PetscCall(PetscOptionsReal("-dt", "time step (s); 0 solves the static problem", nullptr, sc.dt, &sc.dt, nullptr));
  PetscCall(PetscOptionsReal("-t_final", "end time (s)", nullptr, sc.tFinal, &sc.tFinal, nullptr));
  PetscCall(PetscOptionsReal("-structure_density", "density of the wall (g/cm^3)", nullptr, sc.rho, &sc.rho, nullptr));
  PetscCall(PetscOptionsReal("-structure_pressure_until", "the pressure acts while t <= this (s); 0: always", nullptr, sc.pulseEnd, &sc.pulseEnd, nullptr));
  PetscCall(PetscOptionsInt("-structure_load_steps", "apply the load in this many equal increments (statics)", nullptr, sc.loadSteps, &sc.loadSteps, nullptr));
  PetscCall(PetscOptionsString("-structure_pressure_group", "group of faces the pressure acts on", nullptr, sc.loaded, sc.loaded, sizeof(sc.loaded), nullptr));
  PetscInt nradii = 2;
  PetscCall(PetscOptionsRealArray("-lame", "verification against Lame's cylinder: inner,outer radius", nullptr, sc.lameRadii, &nradii, nullptr));
  PetscCall(PetscOptionsBool("-mms", "manufactured solution d = sin(pi x)sin(pi y)sin(pi z)(1,1,1) on the unit cube", nullptr, sc.mms, &sc.mms, nullptr));
  PetscCall(PetscOptionsEnum("-material", "constitutive law of the wall", nullptr, MaterialNames, (PetscEnum)sc.material, (PetscEnum *)&sc.material, nullptr));
  PetscCall(PetscOptionsReal("-E", "Young's modulus (linear elastic)", nullptr, sc.E, &sc.E, nullptr));
  PetscCall(PetscOptionsReal("-nu", "Poisson ratio (linear elastic)", nullptr, sc.nu, &sc.nu, nullptr));
  PetscCall(PetscOptionsReal("-nh_mu", "Neo-Hooke shear modulus (dyn/cm^2)", nullptr, sc.mu, &sc.mu, nullptr));
  PetscCall(PetscOptionsReal("-nh_kappa", "Neo-Hooke bulk modulus (dyn/cm^2)", nullptr, sc.kappa, &sc.kappa, nullptr));
  PetscCall(PetscOptionsInt("-structure_degree", "polynomial degree of the displacement", nullptr, sc.degree, &sc.degree, nullptr));
  PetscCall(PetscOptionsInt("-structure_subdomains", "GDSW subdomains per rank (METIS on the rank's cells)", nullptr, sc.subdomains, &sc.subdomains, nullptr));
  PetscOptionsEnd();
  PetscCheck(sc.E > 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-E %g: Young's modulus must be positive", (double)sc.E);
  PetscCheck(sc.nu > -1 && sc.nu < 0.5, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-nu %g: the Poisson ratio must lie in (-1, 0.5)", (double)sc.nu);
  PetscCheck(sc.mu > 0 && sc.kappa > 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-nh_mu %g -nh_kappa %g: both moduli must be positive", (double)sc.mu, (double)sc.kappa);
  PetscCheck(!sc.mms || sc.material == LINEAR_ELASTIC, PETSC_COMM_WORLD, PETSC_ERR_SUP, "-mms: the manufactured solution is for -material linear");
  PetscCheck(sc.degree >= 1 && sc.degree <= 3, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-structure_degree %" PetscInt_FMT ": use 1, 2 or 3", sc.degree);
  PetscCheck(sc.dt >= 0 && (sc.dt == 0 || sc.tFinal >= sc.dt), PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-dt %g -t_final %g: need 0 <= dt <= t_final", (double)sc.dt, (double)sc.tFinal);
  PetscCheck(sc.rho > 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-structure_density %g: must be positive", (double)sc.rho);
  PetscCheck(sc.loadSteps >= 1, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-structure_load_steps %" PetscInt_FMT ": at least 1", sc.loadSteps);
  PetscCheck(sc.subdomains >= 1, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "-structure_subdomains %" PetscInt_FMT ": at least 1", sc.subdomains);
  PetscFunctionReturn(0);
}

/* The mesh, refined; a label "boundary" on its boundary faces for the manufactured solution. */
static PetscErrorCode CreateMesh(const Scene &sc, DM *dm)
{
  std::vector<std::string> required;
  for (const auto &g : Split(sc.clamp)) required.push_back(g.substr(0, g.find(':')));
  if (sc.region[0]) required.push_back(sc.region);
  if (sc.pressure != 0) required.push_back(sc.loaded);

  PetscFunctionBegin;
  PetscCall(LoadMesh(PETSC_COMM_WORLD, sc.mesh, required, dm));
  for (PetscInt k = 0; k < sc.refine; k++) {
    DM fine;
    PetscCall(DMRefine(*dm, PETSC_COMM_WORLD, &fine));
    PetscCall(DMDestroy(dm));
    *dm = fine;
  }
  PetscCall(DMCreateLabel(*dm, "boundary"));
  DMLabel boundary;
  PetscCall(DMGetLabel(*dm, "boundary", &boundary));
  PetscCall(DMPlexMarkBoundaryFaces(*dm, 1, boundary));
  PetscFunctionReturn(0);
}

static PetscErrorCode ZeroDisplacement(PetscInt, PetscReal, const PetscReal[], PetscInt nc, PetscScalar *u, void *)
{
  for (PetscInt c = 0; c < nc; c++) u[c] = 0;
  return 0;
}

/* The structure block: displacement field on its region, material, body force, Dirichlet
   conditions (clamped groups, or the exact solution on the whole boundary). */
static PetscErrorCode SetUpStructure(const Scene &sc, DM dm, StructureBlock &sb, PetscInt *field)
{
  DMLabel        label;
  const PetscInt one = 1;

  PetscFunctionBegin;
  PetscCall(AddLagrangeField(dm, "displacement", sc.region, 3, sc.degree, field));
  PetscCall(DMCreateDS(dm));
  PetscCheck(sc.degree == 2, PETSC_COMM_WORLD, PETSC_ERR_SUP, "-structure_degree %" PetscInt_FMT ": the element loops are P2 (use 2)", sc.degree);
  PetscCall(GetMaterialLaw(sc.material, &sb.law));
  if (sc.material == LINEAR_ELASTIC) sb.param[0] = sc.E / (2 * (1 + sc.nu)), sb.param[1] = sc.E * sc.nu / ((1 + sc.nu) * (1 - 2 * sc.nu));
  else sb.param[0] = sc.mu, sb.param[1] = sc.kappa;
  sb.mms      = sc.mms;
  if (sc.region[0]) PetscCall(DMGetLabel(dm, (std::string("region_") + sc.region).c_str(), &sb.region));
  /* affine P2 stiffness: degree 2; the mass matrix: 4; the trigonometric load: more */
  PetscCall(CreateP2Rule(sc.mms ? 5 : (sc.dt > 0 ? 4 : 2), sb.rule));
  PetscCall(CreateFaceRule(2, sb.faceRule));          /* P2 times a constant normal */
  sb.pressure = sc.pressure;
  if (sc.pressure != 0) PetscCall(DMGetLabel(dm, sc.loaded, &sb.loaded));
  if (sc.mms) {
    PetscCall(DMGetLabel(dm, "boundary", &label));
    PetscCall(DMAddBoundary(dm, DM_BC_ESSENTIAL, "boundary", label, 1, &one, *field, 0, nullptr, (void (*)(void))MMSElasticityExact, nullptr, nullptr, nullptr));
  }
  for (const auto &spec : Split(sc.clamp)) {
    const std::string g = spec.substr(0, spec.find(':'));
    std::vector<PetscInt> comps; /* empty: all */
    if (spec.find(':') != std::string::npos)
      for (char c : spec.substr(spec.find(':') + 1)) {
        PetscCheck(c == 'x' || c == 'y' || c == 'z', PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-structure_clamp %s: components are x, y, z", spec.c_str());
        comps.push_back(c - 'x');
      }
    DMLabel         group;
    IS              values;
    PetscInt        nv;
    const PetscInt *v;
    PetscCall(DMGetLabel(dm, g.c_str(), &group));
    PetscCall(DMLabelGetValueIS(group, &values));
    PetscCall(ISGetLocalSize(values, &nv));
    PetscCall(ISGetIndices(values, &v));
    std::vector<PetscInt> ids(v, v + nv);
    PetscCall(ISRestoreIndices(values, &v));
    PetscCall(ISDestroy(&values));
    PetscInt any = nv, gany;
    PetscCallMPI(MPIU_Allreduce(&any, &gany, 1, MPIU_INT, MPI_MAX, PETSC_COMM_WORLD));
    if (ids.empty() && gany) ids.push_back(0); /* the label's value lives on other ranks */
    PetscCall(DMAddBoundary(dm, DM_BC_ESSENTIAL, spec.c_str(), group, (PetscInt)ids.size(), ids.data(), *field, (PetscInt)comps.size(), comps.empty() ? nullptr : comps.data(), (void (*)(void))ZeroDisplacement, nullptr, nullptr, nullptr));
  }
  PetscCall(DMSNESSetFunctionLocal(dm, StructureResidual, &sb));
  PetscCall(DMSNESSetJacobianLocal(dm, StructureJacobian, &sb));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  Scene          sc;
  StructureBlock sb;
  DM             dm;
  SNES           snes;
  Vec            d;
  Mat            J;
  PetscInt       field, N;

  PetscCall(PetscInitialize(&argc, &argv, nullptr, help));
  PetscCall(PCGDSWRegister());
  PetscCall(ReadScene(sc));
  PetscCall(CreateMesh(sc, &dm));
  PetscCall(SetUpStructure(sc, dm, sb, &field));
  PetscCall(DMCreateGlobalVector(dm, &d));
  PetscCall(PetscObjectSetName((PetscObject)d, "displacement"));
  PetscCall(VecGetSize(d, &N));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "unknowns: structure %" PetscInt_FMT " fluid 0 pressure 0 geometry 0 multiplier 0\n", N));

  PetscCall(SNESCreate(PETSC_COMM_WORLD, &snes));
  sb.snes = snes;
  PetscCall(SNESSetDM(snes, dm));
  PetscCall(DMCreateMatrix(dm, &J));
  PetscCall(SNESSetJacobian(snes, J, J, nullptr, nullptr));
  if (sc.material == LINEAR_ELASTIC && sc.dt > 0) { /* the operator never changes: assemble and set up once */
    PetscCall(SNESSetLagJacobian(snes, -2));
    PetscCall(SNESSetLagJacobianPersists(snes, PETSC_TRUE));
    PetscCall(SNESSetLagPreconditioner(snes, -2));
    PetscCall(SNESSetLagPreconditionerPersists(snes, PETSC_TRUE));
  }
  PetscCall(SNESSetFromOptions(snes));
  KSP ksp;
  PC  pc;
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(SetGDSWSubdomains(pc, dm, J, sc.region, field, sc.subdomains));

  PetscCall(VecSet(d, 0.0));
  PetscLogDouble      t0, t1;
  PetscInt            newton = 0, krylov = 0, solves = 0;
  SNESConvergedReason reason = SNES_CONVERGED_ITERATING;
  const PetscBool     dynamic = (PetscBool)(sc.dt > 0);
  const PetscInt      nsteps  = dynamic ? (PetscInt)PetscCeilReal(sc.tFinal / sc.dt - 1e-9) : sc.loadSteps;
  if (dynamic) { /* d^n and d^(n-1) start at rest */
    sb.inertia = sc.rho / (sc.dt * sc.dt);
    for (auto &v : sb.previous) {
      PetscCall(DMCreateLocalVector(dm, &v));
      PetscCall(VecSet(v, 0.0));
    }
  }
  PetscCall(PetscTime(&t0));
  for (PetscInt step = 1; step <= nsteps; step++) {
    PetscInt       n, k;
    const PetscReal t = dynamic ? step * sc.dt : 0;
    sb.pressure       = dynamic ? (sc.pulseEnd == 0 || t <= sc.pulseEnd + 1e-12 ? sc.pressure : 0.0) : sc.pressure * step / nsteps;
    PetscCall(SNESSolve(snes, nullptr, d));
    PetscCall(SNESGetIterationNumber(snes, &n));
    PetscCall(SNESGetLinearSolveIterations(snes, &k));
    PetscCall(SNESGetConvergedReason(snes, &reason));
    newton += n, krylov += k, solves++;
    if (nsteps > 1) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s %" PetscInt_FMT "/%" PetscInt_FMT " t %.4e newton %" PetscInt_FMT " krylov %" PetscInt_FMT " %s\n", dynamic ? "step" : "load step", step, nsteps, (double)t, n, k, SNESConvergedReasons[reason]));
    if (reason < 0) break;
    if (dynamic) { /* d^(n-1) <- d^n <- d */
      PetscCall(VecCopy(sb.previous[0], sb.previous[1]));
      PetscCall(DMGlobalToLocal(dm, d, INSERT_VALUES, sb.previous[0]));
    }
  }
  if (dynamic && solves) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "steps %" PetscInt_FMT " newton per step %.2f krylov per newton %.2f\n", solves, (double)newton / solves, newton ? (double)krylov / newton : 0.0));
  PetscCall(PetscTime(&t1));
  PetscReal dmax;
  PetscCall(VecNorm(d, NORM_INFINITY, &dmax));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "newton %" PetscInt_FMT " krylov %" PetscInt_FMT " reason %s time %.3f s max displacement %.6e\n", newton, krylov, SNESConvergedReasons[reason], t1 - t0, (double)dmax));
  char cure[128]; /* what to change: the load increments (statics) or the time step */
  if (dynamic) PetscCall(PetscSNPrintf(cure, sizeof(cure), "reduce the time step (-dt %g now)", (double)sc.dt));
  else PetscCall(PetscSNPrintf(cure, sizeof(cure), "apply the load in more increments (-structure_load_steps %" PetscInt_FMT " now)", sc.loadSteps));
  PetscCheck(reason != SNES_DIVERGED_FUNCTION_DOMAIN, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "Newton stopped after %" PetscInt_FMT " steps: an element inverted (det F <= 0) in every step the line search tried; %s", newton, cure);
  PetscCheck(reason > 0, PETSC_COMM_WORLD, PETSC_ERR_NOT_CONVERGED, "Newton did not converge (%s after %" PetscInt_FMT " steps in all); see -snes_monitor, or %s", SNESConvergedReasons[reason], newton, cure);
  if (sc.lameRadii[1] > 0) {
    PetscErrorCode (*exact[1])(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *, void *) = {LameDisplacement};
    Lame      lame = LameCylinder(sc.E, sc.nu, sc.pressure, sc.lameRadii[0], sc.lameRadii[1]);
    void     *ctx[1] = {&lame};
    PetscReal err, norm;
    Vec       zero;
    PetscCall(DMComputeL2Diff(dm, 0.0, exact, ctx, d, &err));
    PetscCall(VecDuplicate(d, &zero));
    PetscCall(VecSet(zero, 0.0));
    PetscCall(DMComputeL2Diff(dm, 0.0, exact, ctx, zero, &norm));
    PetscCall(VecDestroy(&zero));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "L2 error %.6e relative %.6e\n", (double)err, (double)(err / norm)));
  }
  if (sc.mms) {
    PetscErrorCode (*exact[1])(PetscInt, PetscReal, const PetscReal[], PetscInt, PetscScalar *, void *) = {MMSElasticityExact}; /* PetscFE quadrature of the field */
    PetscReal err;
    PetscCall(DMComputeL2Diff(dm, 0.0, exact, nullptr, d, &err));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "L2 error %.6e\n", (double)err));
  }
  for (auto &v : sb.previous) PetscCall(VecDestroy(&v));
  PetscCall(MatDestroy(&J));
  PetscCall(VecDestroy(&d));
  PetscCall(SNESDestroy(&snes));
  PetscCall(DMDestroy(&dm));
  PetscCall(PetscFinalize());
  return 0;
}
