// SPDX-License-Identifier: BSD-2-Clause
#include "block.h"
#include "discretization/ale_map.h"
#include "discretization/fields.h"
#include "discretization/nodes.h"
#include "mesh/mesh.h"
#include "base/options.h"
#include "base/ramp.h"
#include "structure/subdomains.h"
#include "verification/errors.h"
#include "verification/mms.h"

namespace fsi {

PetscErrorCode StructureBlock::ReadOptions(std::map<std::string, std::string> &problem)
{
  StructureOptions &o = opt;
  PetscInt          n;
  PetscBool         set;

  PetscFunctionBegin;
  PetscOptionsBegin(PETSC_COMM_WORLD, nullptr, "fsi_app: the structure block", nullptr);
  const OptionReader r{PetscOptionsObject, problem};
  const std::pair<const char *, const char *> renamed[] = {{"-material", "-structure_material"}, {"-E", "-structure_E"}, {"-nu", "-structure_nu"}, {"-nh_mu", "-structure_nh_mu"}, {"-nh_kappa", "-structure_nh_kappa"}, {"-arterial", "-structure_arterial"}, {"-arterial_fibre_angle", "-structure_arterial_fibre_angle"}};
  for (const auto &old : renamed) PetscCall(r.Renamed(old.first, old.second));
  PetscCall(r.String("-structure_region", "physical group of the wall's cells (empty: every cell)", o.region, sizeof(o.region), PROBLEM));
  PetscCall(r.String("-structure_clamp", "groups of faces where the displacement is zero, comma separated; group:xz fixes only those components", o.clamp, sizeof(o.clamp), PROBLEM));
  PetscCall(r.Real("-structure_pressure", "pressure on the faces of -structure_pressure_group (dyn/cm^2)", &o.pressure, Any, PROBLEM));
  PetscCall(r.String("-structure_pressure_group", "group of faces the pressure acts on", o.loaded, sizeof(o.loaded), PROBLEM));
  PetscCall(r.Bool("-structure_pressure_follower", "the pressure acts on the deformed face (follower load) rather than the reference one", &o.follower, PROBLEM));
  n = 3;
  PetscCall(r.Reals("-structure_body_force", "body force bx,by,bz per unit reference volume (dyn/cm^3)", o.bodyForce, &n, &set, Any, PROBLEM));
  PetscCheck(!set || n == 3, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-structure_body_force: give bx,by,bz (got %" PetscInt_FMT " values)", n);
  n = 3;
  PetscCall(r.Reals("-structure_traction", "dead traction tx,ty,tz per unit reference area on -structure_traction_group (dyn/cm^2)", o.traction, &n, &set, Any, PROBLEM));
  PetscCheck(!set || n == 3, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-structure_traction: give tx,ty,tz (got %" PetscInt_FMT " values)", n);
  PetscCall(r.String("-structure_traction_group", "group of faces the traction acts on", o.tractionGroup, sizeof(o.tractionGroup), PROBLEM));
  PetscCheck(!(o.traction[0] != 0 || o.traction[1] != 0 || o.traction[2] != 0) || o.tractionGroup[0], PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-structure_traction: name the faces it acts on with -structure_traction_group");
  n = 2;
  PetscCall(r.Reals("-structure_support", "tissue support k_s[,c_s] on -structure_support_group: a spring (dyn/cm^3) and a damper (dyn s/cm^3) per unit reference area", o.support, &n, &set, NonNegative, PROBLEM));
  PetscCheck(!set || n == 1 || n == 2, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-structure_support: give k_s or k_s,c_s (got %" PetscInt_FMT " values)", n);
  if (set && n == 1) o.support[1] = 0;
  PetscCall(r.String("-structure_support_group", "group of faces the tissue support holds", o.supportGroup, sizeof(o.supportGroup), PROBLEM));
  PetscCall(r.Bool("-structure_support_normal", "the support acts only on the displacement along the reference normal (the wall slides freely along the tissue)", &o.supportNormal, PROBLEM));
  PetscCall(r.Real("-structure_pressure_ramp", "the pressure rises smoothly (sin^2) from 0 over this time (s); 0: a step at t = 0", &o.ramp, NonNegative, PROBLEM));
  PetscCall(r.Real("-structure_pressure_until", "the pressure acts while t <= this (s); 0: always", &o.pulseEnd, NonNegative, PROBLEM));
  PetscCall(r.Enum("-structure_material", "constitutive law of the wall", MaterialNames, &o.material, PROBLEM));
  PetscCall(r.Real("-structure_E", "Young's modulus (linear elastic; dyn/cm^2)", &o.E, Positive, PROBLEM));
  PetscCall(r.Real("-structure_nu", "Poisson ratio (linear elastic; dimensionless)", &o.nu, Range{-1, 0.5, PETSC_TRUE, PETSC_TRUE}, PROBLEM));
  PetscCall(r.Real("-structure_nh_mu", "Neo-Hooke shear modulus (dyn/cm^2)", &o.mu, Positive, PROBLEM));
  PetscCall(r.Real("-structure_nh_kappa", "Neo-Hooke bulk modulus (dyn/cm^2)", &o.kappa, Positive, PROBLEM));
  n = 5;
  PetscCall(r.Reals("-structure_arterial", "arterial wall c1,eps1,eps2,alpha1,alpha2 (dyn/cm^2 for c1, eps1, alpha1)", o.arterial, &n, &set, Any, PROBLEM));
  PetscCheck(!set || n == 5, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-structure_arterial: give all five of c1,eps1,eps2,alpha1,alpha2 (got %" PetscInt_FMT ")", n);
  PetscCheck(o.arterial[0] > 0 && o.arterial[1] > 0 && o.arterial[2] > 1 && o.arterial[3] >= 0 && o.arterial[4] >= 2, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE,
             "-structure_arterial %g,%g,%g,%g,%g: need c1 > 0, eps1 > 0, eps2 > 1, alpha1 >= 0, alpha2 >= 2 (polyconvexity and a C2 energy)", (double)o.arterial[0], (double)o.arterial[1], (double)o.arterial[2], (double)o.arterial[3], (double)o.arterial[4]);
  PetscCall(r.Real("-structure_arterial_fibre_angle", "angle of the two fibre families from the circumferential direction (degrees)", &o.fibreAngle, Range{0, 90}, PROBLEM));
  PetscCall(r.String("-structure_centerline", "the arterial fibres' frame from the vessel's centreline: a file of points 'x y z' (cm), a blank line between branches (named in an options file: relative to that file); empty: about the z-axis", o.centerline, sizeof(o.centerline), PROBLEM));
  PetscCall(r.Bool("-structure_frame_check_z_axis", "verification: report the computed frame's largest deviation from the frame about the z-axis (a straight tube)", &o.frameCheck, RUN));
  PetscCall(r.Real("-structure_density", "density of the wall (g/cm^3)", &o.rho, Positive, PROBLEM));
  PetscCall(r.Int("-structure_subdomains", "GDSW subdomains per rank (METIS on the rank's cells)", &o.subdomains, AtLeast(1), RUN));
  {
    const char *const policies[] = {"every_newton", "every_step", "once", "auto", "SplitSetUp", "", nullptr}; /* SplitSetUp's order, then auto */
    PetscInt          policy     = o.pcSetUp < 0 ? 3 : o.pcSetUp;
    PetscCall(r.Choice("-structure_pc_setup", "when the structure split's preconditioner is rebuilt (auto: once for a linear wall, every time step otherwise)", policies, &policy, RUN));
    o.pcSetUp = policy == 3 ? -1 : policy;
  }
  PetscCall(ReadSetUpInterval(r, "structure", &o.pcSetUpInterval));
  PetscCall(r.Points("-structure_probes", "points x1,y1,z1,x2,... (at most 20, reference configuration) where the wall's displacement is recorded every step (in the run report)", o.probes));
  PetscCall(r.Real("-mms_amplitude", "-mms: the amplitude a of the manufactured displacement d = a sin(pi x)sin(pi y)sin(pi z)(1,1,1) on the unit cube (cm)", &o.mmsAmplitude, Any, PROBLEM));
  n = 2;
  PetscCall(r.Reals("-lame", "verification against Lame's cylinder: inner,outer radius (cm)", o.lameRadii, &n, &set, Positive, RUN));
  PetscCheck(!set || n == 2, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-lame: give the inner and the outer radius, Ri,Ro (got %" PetscInt_FMT " values)", n);
  PetscCheck(!set || o.lameRadii[0] < o.lameRadii[1], PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "-lame %s,%s: the inner radius must be smaller than the outer one (give Ri,Ro)", Number(o.lameRadii[0]).c_str(), Number(o.lameRadii[1]).c_str());
  PetscOptionsEnd();
  PetscCheck(!o.centerline[0] || o.material == ARTERIAL, PETSC_COMM_WORLD, PETSC_ERR_ARG_INCOMP, "-structure_centerline %s: only the arterial law (-structure_material arterial) has fibres", o.centerline);
  PetscCheck(!o.frameCheck || o.centerline[0], PETSC_COMM_WORLD, PETSC_ERR_ARG_INCOMP, "-structure_frame_check_z_axis: it checks the frame of a centreline (-structure_centerline FILE)");
  PetscCall(CheckSetUpInterval("structure", o.pcSetUpInterval, SetUpPolicy()));
  if (o.centerline[0]) PetscCall(CenterlineRead(PETSC_COMM_WORLD, "-structure_centerline", o.centerline, centerline)); /* checked before the mesh */
  PetscFunctionReturn(0);
}

void StructureBlock::Groups(std::vector<GroupUse> &groups) const
{
  for (const auto &g : SplitList(opt.region)) groups.push_back({g, "-structure_region", 3, RegionsRole});
  for (const auto &g : SplitList(opt.clamp)) groups.push_back({g.substr(0, g.find(':')), "-structure_clamp", 2});
  for (const auto &g : SplitList(opt.tractionGroup)) groups.push_back({g, "-structure_traction_group", 2});
  if (opt.pressure != 0) groups.push_back({opt.loaded, "-structure_pressure_group", 2});
  if (Supported()) groups.push_back({opt.supportGroup, "-structure_support_group", 2});
}

/* Each cell's nearest centreline segment and the fibres at its quadrature points; every
   quadrature point must have a frame (off the
   centreline), and a cell's radial directions must agree (a centreline through the wall turns
   them over inside a cell). */
PetscErrorCode StructureBlock::SetUpFrame(DM dm)
{
  StructureForms &sb = forms;
  PetscInt        undefined = 0, crossed = 0;

  PetscFunctionBegin;
  sb.centerline = &centerline;
  sb.segment.resize(sb.cells.Size());
  sb.fibresAt.resize(sb.cells.Size());
  sb.fibres.clear();
  for (PetscInt k = 0; k < sb.cells.Size(); k++) {
    const CellGeometry &g    = sb.cells.geom[k];
    const P2Rule       &rule = g.curved ? sb.curvedRule : sb.rule;
    PetscReal           centre[3] = {0, 0, 0};
    for (int v = 0; v < 4; v++)
      for (int d = 0; d < 3; d++) centre[d] += g.x[v][d] / 4;
    sb.segment[k] = CenterlineNearest(centerline, centre);
    PetscReal first[3] = {0, 0, 0};
    sb.fibresAt[k] = (PetscInt)sb.fibres.size();
    sb.fibres.resize(sb.fibres.size() + 6 * rule.nq, 0.0);
    for (PetscInt q = 0; q < rule.nq; q++) {
      PetscReal dN[10][3], X[3], frame[9], theta[6];
      ReferenceGradients(g, rule, q, dN, X);
      if (!CenterlineFrame(centerline, sb.segment[k], X, frame)) {
        undefined++;
        continue;
      }
      FrameFibres(frame, sb.fibreAngle, &sb.fibres[sb.fibresAt[k] + 6 * q]); /* once: the frame does not change */
      if (q == 0)
        for (int d = 0; d < 3; d++) first[d] = frame[3 + d];
      if (first[0] * frame[3] + first[1] * frame[4] + first[2] * frame[5] < 0) crossed++;
      ArterialFibres(X, 0, theta); /* e_theta about the z-axis */
      const PetscReal ez[3] = {0, 0, 1};
      for (int d = 0; d < 3; d++) frameDeviation[0] = PetscMax(frameDeviation[0], PetscAbsReal(frame[d] - ez[d])), frameDeviation[1] = PetscMax(frameDeviation[1], PetscAbsReal(frame[6 + d] - theta[d]));
    }
  }
  PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, &undefined, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)dm)));
  PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, &crossed, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)dm)));
  PetscCheck(!crossed, PetscObjectComm((PetscObject)dm), PETSC_ERR_ARG_WRONG, "-structure_centerline %s: the centreline passes through the wall (the radial direction turns over inside %" PetscInt_FMT " quadrature points' cells): it must run inside the lumen", opt.centerline, crossed);
  PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, frameDeviation, 2, MPIU_REAL, MPIU_MAX, PetscObjectComm((PetscObject)dm)));
  PetscCheck(!undefined, PetscObjectComm((PetscObject)dm), PETSC_ERR_ARG_WRONG, "-structure_centerline %s: %" PetscInt_FMT " points of the wall lie on the centreline, where the wall has no radial direction: the centreline must run inside the lumen", opt.centerline, undefined);
  PetscFunctionReturn(0);
}

PetscErrorCode StructureBlock::AddFields(DM dm)
{
  PetscFunctionBegin;
  PetscCall(AddLagrangeField(dm, "displacement", opt.region, 3, 2, &field));
  PetscFunctionReturn(0);
}

PetscErrorCode StructureBlock::AddConditions(DM dm, Conditions &list)
{
  PetscFunctionBegin;
  if (sc.mms) {
    Condition c;
    const PetscReal *a = &opt.mmsAmplitude;
    c.name = "-mms (the manufactured displacement on the boundary)", c.field = field;
    PetscCall(DMGetLabel(dm, "boundary", &c.label));
    c.value = [a](const PetscReal x[3], PetscReal t, PetscScalar *v) { MMSElasticityExact(3, t, x, 3, v, (void *)a); };
    list.push_back(c);
  }
  PetscCall(AddDirichlet(dm, list, opt.clamp, field, "-structure_clamp"));
  PetscFunctionReturn(0);
}

PetscErrorCode StructureBlock::SetUp(DM dm)
{
  StructureForms &sb = forms;

  PetscFunctionBegin;
  PetscCall(GetMaterialLaw(opt.material, &sb.law));
  switch (opt.material) {
  case LINEAR_ELASTIC:
    sb.param[0] = opt.E / (2 * (1 + opt.nu)), sb.param[1] = opt.E * opt.nu / ((1 + opt.nu) * (1 - 2 * opt.nu));
    break;
  case NEO_HOOKE:
    sb.param[0] = opt.mu, sb.param[1] = opt.kappa;
    break;
  case ARTERIAL:
    for (int k = 0; k < 5; k++) sb.param[k] = opt.arterial[k];
    sb.fibreAngle = opt.fibreAngle * PETSC_PI / 180;
    break;
  }
  sb.mms = sc.mms ? opt.mmsAmplitude : 0.0;
  if (opt.region[0]) PetscCall(GetRegionLabel(dm, opt.region, &sb.region));
  /* affine P2 stiffness: degree 2 (exact for the linear law); the trigonometric load: more */
  PetscCall(CreateP2Rule(sc.mms ? 5 : 2, sb.rule));
  /* curved cells: the mass N_a N_b J (degree 4 + the bend's) and the stiffness, rational in l: degree 6 */
  PetscCall(CreateP2Rule(6, sb.curvedRule));
  PetscCall(CreateP2Mass(sb.mass));
  PetscCall(CreateFaceRule(opt.follower || MeshIsCurved(dm) ? 4 : 2, sb.faceRule)); /* P2 times the normal: constant (dead, straight) or quadratic (follower, or curved faces) */
  sb.follower = opt.follower;
  sb.rho      = opt.rho;
  PetscCall(FieldCellsCreate(dm, sb.region, field, sb.cells));
  StructureCurvedMasses(sb);
  if (opt.material == ARTERIAL && opt.centerline[0]) PetscCall(SetUpFrame(dm));
  if (opt.material == ARTERIAL) {
    PetscInt pStart, pEnd;
    PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
    fibres[0].assign(3 * pEnd, 0), fibres[1].assign(3 * pEnd, 0);
    NodeFibres();
  }
  if (opt.pressure != 0) {
    DMLabel loaded;
    PetscCall(DMGetLabel(dm, opt.loaded, &loaded));
    PetscCall(CellFacesCreate(dm, sb.cells, loaded, sb.loaded));
  }
  if (opt.tractionGroup[0]) {
    DMLabel group;
    PetscCall(DMGetLabel(dm, opt.tractionGroup, &group));
    PetscCall(CellFacesCreate(dm, sb.cells, group, sb.tractionFaces));
  }
  if (Supported()) {
    DMLabel group;
    PetscCall(DMGetLabel(dm, opt.supportGroup, &group));
    PetscCall(CellFacesCreate(dm, sb.cells, group, sb.supported));
    sb.spring = opt.support[0], sb.damper = opt.support[1], sb.supportNormal = opt.supportNormal;
  }
  for (int d = 0; d < 3; d++) sb.bodyForce[d] = opt.bodyForce[d], sb.traction[d] = opt.traction[d];
  if (!opt.probes.empty()) PetscCall(ProbesCreate(PetscObjectComm((PetscObject)dm), sb.cells, opt.probes, "-structure_probes", probes));
  PetscFunctionReturn(0);
}

/* The fibres at each node of the wall's cells, where the law places them (a node's cells agree:
   the frame is a function of the position, and of the nearest segment, which a node's cells
   share but near a branch's end). */
void StructureBlock::NodeFibres()
{
  const StructureForms &sb = forms;
  for (PetscInt k = 0; k < sb.cells.Size(); k++) {
    const CellGeometry &g = sb.cells.geom[k];
    for (int a = 0; a < 10; a++) {
      PetscReal X[3], f[6], frame[9];
      for (int d = 0; d < 3; d++) X[d] = a < 4 ? g.x[a][d] : (g.x[EdgeVertex[a - 4][0]][d] + g.x[EdgeVertex[a - 4][1]][d]) / 2 + (g.curved ? g.bend[3 * a + d] : 0.0);
      if (!sb.centerline) ArterialFibres(X, sb.fibreAngle, f);
      else if (CenterlineFrame(*sb.centerline, sb.segment[k], X, frame)) FrameFibres(frame, sb.fibreAngle, f);
      else continue;
      const PetscInt p = sb.cells.point[10 * k + a];
      for (int d = 0; d < 3; d++) fibres[0][3 * p + d] = f[d], fibres[1][3 * p + d] = f[3 + d];
    }
  }
}

void StructureBlock::Output(std::vector<OutputPart> &parts) const
{
  OutputPart p{"wall", &forms.cells, {{"displacement", field}}, {}};
  if (opt.material == ARTERIAL) p.derived = {{"fibre_1", 3, &fibres[0]}, {"fibre_2", 3, &fibres[1]}}; /* in the reference configuration */
  parts.push_back(p);
}

PetscReal StructureBlock::LoadFactor(PetscReal t) const
{
  if (!sc.Dynamic()) return t;
  if (opt.pulseEnd > 0 && t > opt.pulseEnd + 1e-12) return 0.0;
  return SmoothRamp(t, opt.ramp);
}

PetscErrorCode StructureBlock::SetTime(PetscReal t)
{
  forms.load     = LoadFactor(t);
  forms.pressure = opt.pressure * forms.load;
  return 0;
}

PetscErrorCode StructureBlock::ConfigurePC(DM dm, PC pc, MatNullSpace *nsp)
{
  PetscInt f;

  PetscFunctionBegin;
  PetscCall(FieldByName(dm, "displacement", &f));
  PetscCall(RigidBodyModes(dm, f, nsp));
  PetscCall(ConfigureGDSW(pc, dm, opt.region, opt.subdomains));
  PetscFunctionReturn(0);
}

std::string StructureBlock::InvertedCause() const
{
  return forms.inverted ? "an element inverted (det F <= 0)" : "";
}

PetscErrorCode StructureBlock::AfterStep(DM dm, PetscInt, PetscReal t, Vec x)
{
  return probes.cell.empty() ? 0 : ProbesRecordGlobal(dm, forms.cells, x, t, probes);
}

PetscErrorCode StructureBlock::Results(DM dm, Vec x, PetscReal t, RunReport &report)
{
  Errors e;
  Lame   lame = LameCylinder(opt.E, opt.nu, opt.pressure, opt.lameRadii[0], opt.lameRadii[1], opt.support[0]);

  PetscFunctionBegin;
  if (!probes.cell.empty()) report.series.push_back({"displacement", &probes});
  if (opt.frameCheck) {
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "wall frame against the frame about the z-axis: largest |e_a - e_z| %.3e, |e_c - e_theta| %.3e\n", (double)frameDeviation[0], (double)frameDeviation[1]));
    report.results.insert(report.results.end(), {{"frame_axial_deviation", frameDeviation[0]}, {"frame_circumferential_deviation", frameDeviation[1]}});
  }
  if (opt.lameRadii[1] > 0) PetscCall(ComputeErrors(dm, forms.cells, x, t, LameSolution, &lame, e));
  else if (sc.mms) PetscCall(ComputeErrors(dm, forms.cells, x, t, MMSElasticitySolution, &opt.mmsAmplitude, e));
  else PetscFunctionReturn(0);
  PetscCall(ReportErrors("", e, report));
  PetscFunctionReturn(0);
}

} // namespace fsi
