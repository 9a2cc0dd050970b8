// SPDX-License-Identifier: BSD-2-Clause
/* The tutorial's problem and solver (pc_gdsw/examples/elasticity.cxx, its main() renamed), solved
   as there and then looked into: what the tests assert beyond the summary line. */
#define main ElasticityTutorialMain
#include "../pc_gdsw/examples/elasticity.cxx"
#undef main

static const std::string diagnostics_help = std::string(help) +
                                            "Diagnostics, after the solve:\n"
                                            "  -prefix <>          the solver's options prefix (as the inner solver of PCFIELDSPLIT has one), read after the unprefixed ones\n"
                                            "  -check_phi          how well the coarse basis reproduces the rigid-body modes\n"
                                            "  -check_coarse       the coarse operator against Phi^T (A Phi), the coarse solver (AIJ only; after each set-up)\n"
                                            "  -report_subdomains  the dofs of all nonoverlapping and of all overlapping subdomains, how many of the former are connected\n"
                                            "  -resolve_jump <0>   then reassemble with this -jump (same pattern) and solve again\n"
                                            "  -resolve_clamp_both then reassemble with x = 1 clamped too (more Dirichlet rows, same pattern) and solve again\n"
                                            "Each solve prints the summary line and then ||b - Ax|| / ||b||.\n";

/* max over rigid modes z of |Phi c - z| / |z| with c the least-squares coefficients */
static PetscErrorCode CheckPhi(PC pc, MatNullSpace rigid)
{
  Mat        Phi, PtP;
  KSP        ksp;
  PetscInt   nv;
  const Vec *z;
  PetscBool  hasConst;
  Vec        c, Ptz, r;
  PetscReal  worst = 0;

  PetscFunctionBegin;
  PetscCall(PCGDSWGetCoarseBasis(pc, &Phi));
  PetscCall(MatTransposeMatMult(Phi, Phi, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &PtP));
  PetscCall(KSPCreate(PETSC_COMM_WORLD, &ksp));
  PetscCall(KSPSetOperators(ksp, PtP, PtP));
  PetscCall(KSPSetType(ksp, KSPCG));
  PetscCall(KSPSetTolerances(ksp, 1e-14, 1e-30, PETSC_DEFAULT, 2000));
  PetscCall(MatCreateVecs(Phi, &c, &r));
  PetscCall(VecDuplicate(c, &Ptz));
  PetscCall(MatNullSpaceGetVecs(rigid, &hasConst, &nv, &z));
  for (PetscInt k = 0; k < nv; k++) {
    PetscReal nr, nz;
    PetscCall(MatMultTranspose(Phi, z[k], Ptz));
    PetscCall(KSPSolve(ksp, Ptz, c));
    PetscCall(MatMult(Phi, c, r));
    PetscCall(VecAXPY(r, -1.0, z[k]));
    PetscCall(VecNorm(r, NORM_2, &nr));
    PetscCall(VecNorm(z[k], NORM_2, &nz));
    worst = std::max(worst, nr / nz);
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "rigid-body modes reproduced by Phi: max relative error %.3e\n", (double)worst));
  PetscCall(VecDestroy(&c));
  PetscCall(VecDestroy(&Ptz));
  PetscCall(VecDestroy(&r));
  PetscCall(KSPDestroy(&ksp));
  PetscCall(MatDestroy(&PtP));
  PetscFunctionReturn(0);
}

/* The coarse operator against an independent product Phi^T (A Phi), the coarse solver as the
   options made it, and for the balanced combination M A Phi = Phi. */
static PetscErrorCode CheckCoarse(PC pc, Mat A)
{
  Mat             Phi, A0, AP, PtAP, K;
  KSP             ksp;
  PC              kpc;
  KSPType         ktype;
  PCType          ptype;
  const char     *prefix;
  PetscInt        m, n;
  PetscReal       diff, norm;
  PCCompositeType comb;

  PetscFunctionBegin;
  PetscCall(PCGDSWGetCoarseBasis(pc, &Phi));
  PetscCall(PCGDSWGetCoarseOperator(pc, &A0));
  PetscCall(PCGDSWGetCoarseKSP(pc, &ksp));
  PetscCall(MatMatMult(A, Phi, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &AP));
  PetscCall(MatTransposeMatMult(Phi, AP, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &PtAP));
  PetscCall(MatNorm(PtAP, NORM_FROBENIUS, &norm));
  PetscCall(MatAXPY(PtAP, -1.0, A0, DIFFERENT_NONZERO_PATTERN));
  PetscCall(MatNorm(PtAP, NORM_FROBENIUS, &diff));
  PetscCall(MatGetSize(A0, &m, &n));
  PetscCall(KSPGetOperators(ksp, &K, nullptr));
  PetscCall(KSPGetOptionsPrefix(ksp, &prefix));
  PetscCall(KSPGetType(ksp, &ktype));
  PetscCall(KSPGetPC(ksp, &kpc));
  PetscCall(PCGetType(kpc, &ptype));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "coarse operator %" PetscInt_FMT " x %" PetscInt_FMT " relative difference to Phi^T A Phi %.3e; coarse solver prefix %s ksp %s pc %s operator %s\n", m, n, (double)(diff / norm), prefix, ktype, ptype,
                        K == A0 ? "A0" : "other"));
  PetscCall(MatDestroy(&AP));
  PetscCall(MatDestroy(&PtAP));
  PetscCall(PCGDSWGetCombinationType(pc, &comb));
  if (comb == PC_COMPOSITE_SYMMETRIC_MULTIPLICATIVE) { /* M A v = v for v = Phi c: the coarse space is solved exactly */
    Vec       c, v, Av, z;
    PetscReal nv;
    PetscCall(MatCreateVecs(Phi, &c, &v));
    PetscCall(VecDuplicate(v, &Av));
    PetscCall(VecDuplicate(v, &z));
    PetscCall(VecSetRandom(c, nullptr));
    PetscCall(MatMult(Phi, c, v));
    PetscCall(MatMult(A, v, Av));
    PetscCall(PCApply(pc, Av, z));
    PetscCall(VecAXPY(z, -1.0, v));
    PetscCall(VecNorm(z, NORM_2, &diff));
    PetscCall(VecNorm(v, NORM_2, &nv));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "balanced combination: |M A Phi c - Phi c| / |Phi c| %.3e\n", (double)(diff / nv)));
    PetscCall(VecDestroy(&c));
    PetscCall(VecDestroy(&v));
    PetscCall(VecDestroy(&Av));
    PetscCall(VecDestroy(&z));
  }
  PetscFunctionReturn(0);
}

/* Whether a set of dofs is connected in the graph of A (A(S, S) extracted, depth-first search).
   Collective: every rank calls it, with an empty set if it has none. */
static PetscErrorCode Connected(Mat A, IS S, PetscBool *connected)
{
  Mat            *sub;
  const PetscInt *ia, *ja;
  PetscInt        n;
  PetscBool       done;

  PetscFunctionBegin;
  PetscCall(MatCreateSubMatrices(A, 1, &S, &S, MAT_INITIAL_MATRIX, &sub));
  PetscCall(MatGetRowIJ(sub[0], 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  std::vector<char>     seen(n, 0);
  std::vector<PetscInt> stack;
  PetscInt              reached = 0;
  if (n) seen[0] = 1, stack.push_back(0);
  while (!stack.empty()) {
    const PetscInt a = stack.back();
    stack.pop_back();
    reached++;
    for (PetscInt k = ia[a]; k < ia[a + 1]; k++)
      if (!seen[ja[k]]) seen[ja[k]] = 1, stack.push_back(ja[k]);
  }
  *connected = (PetscBool)(reached == n);
  PetscCall(MatRestoreRowIJ(sub[0], 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  PetscCall(MatDestroySubMatrices(1, &sub));
  PetscFunctionReturn(0);
}

/* The dofs of all nonoverlapping and of all overlapping subdomains, as the PC uses them, and how
   many of the nonoverlapping ones are connected in the graph of A. */
static PetscErrorCode ReportSubdomains(PC pc, Mat A)
{
  PetscInt n, local[4] = {0, 0, 0, 0}, total[4];
  IS      *non, *ovl;

  PetscFunctionBegin;
  PetscCall(PCGDSWGetSubdomains(pc, &n, &non, &ovl));
  local[0] = n;
  for (PetscInt i = 0; i < n; i++) {
    PetscInt a, b;
    PetscCall(ISGetLocalSize(non[i], &a));
    PetscCall(ISGetLocalSize(ovl[i], &b));
    local[1] += a, local[2] += b;
  }
  PetscInt nmax;
  IS       empty;
  PetscCallMPI(MPIU_Allreduce(&n, &nmax, 1, MPIU_INT, MPI_MAX, PETSC_COMM_WORLD));
  PetscCall(ISCreateStride(PETSC_COMM_SELF, 0, 0, 1, &empty));
  for (PetscInt i = 0; i < nmax; i++) {
    PetscBool connected;
    PetscCall(Connected(A, i < n ? non[i] : empty, &connected));
    local[3] += i < n && connected;
  }
  PetscCall(ISDestroy(&empty));
  PetscCallMPI(MPIU_Allreduce(local, total, 4, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "subdomains %" PetscInt_FMT " nonoverlapping dofs %" PetscInt_FMT " overlapping dofs %" PetscInt_FMT " connected %" PetscInt_FMT "\n", total[0], total[1], total[2], total[3]));
  PetscFunctionReturn(0);
}

/* The solve's true relative residual: what a KSP's own convergence test may not see. */
static PetscErrorCode ReportResidual(const System &s)
{
  Vec       r;
  PetscReal nr, nb;

  PetscFunctionBegin;
  PetscCall(VecDuplicate(s.b, &r));
  PetscCall(MatMult(s.A, s.x, r));
  PetscCall(VecAYPX(r, -1.0, s.b));
  PetscCall(VecNorm(r, NORM_2, &nr));
  PetscCall(VecNorm(s.b, NORM_2, &nb));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "true relative residual %.3e\n", (double)(nr / nb)));
  PetscCall(VecDestroy(&r));
  PetscFunctionReturn(0);
}

/* again: the operator has new values, which only PCSetUp() sees before the solve */
static PetscErrorCode SolveAndReport(KSP ksp, const System &s, PetscBool again)
{
  PetscLogDouble t0, t1, t2;
  PC             pc;

  PetscFunctionBegin;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PetscTime(&t0));
  if (again) PetscCall(PCSetUp(pc));
  else PetscCall(KSPSetUp(ksp));
  PetscCall(PetscTime(&t1));
  PetscCall(KSPSolve(ksp, s.b, s.x));
  PetscCall(PetscTime(&t2));
  PetscCall(Report(ksp, s.A, t1 - t0, t2 - t1));
  PetscCall(ReportResidual(s));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  Problem         p;
  System          s;
  KSP             ksp;
  PC              pc;
  std::vector<IS> boxes, grown;
  char            prefix[256] = "";
  PetscBool       checkPhi = PETSC_FALSE, checkCoarse = PETSC_FALSE, reportSubdomains = PETSC_FALSE, resolveClamp = PETSC_FALSE;
  PetscReal       resolveJump = 0;

  PetscCall(PetscInitialize(&argc, &argv, nullptr, diagnostics_help.c_str()));
  PetscCall(PCGDSWRegister());
  PetscCall(ProblemSetFromOptions(p));
  PetscOptionsBegin(PETSC_COMM_WORLD, nullptr, "Diagnostics of the elasticity problem's solve", nullptr);
  PetscCall(PetscOptionsString("-prefix", "the solver's options prefix", nullptr, prefix, prefix, sizeof(prefix), nullptr));
  PetscCall(PetscOptionsBool("-check_phi", "check that Phi reproduces the rigid-body modes", nullptr, checkPhi, &checkPhi, nullptr));
  PetscCall(PetscOptionsBool("-check_coarse", "compare the coarse operator with Phi^T (A Phi), report the coarse solver", nullptr, checkCoarse, &checkCoarse, nullptr));
  PetscCall(PetscOptionsBool("-report_subdomains", "report the dofs of the subdomains", nullptr, reportSubdomains, &reportSubdomains, nullptr));
  PetscCall(PetscOptionsReal("-resolve_jump", "reassemble with this jump and solve again (0: no)", nullptr, resolveJump, &resolveJump, nullptr));
  PetscCall(PetscOptionsBool("-resolve_clamp_both", "reassemble with x = 1 clamped too and solve again", nullptr, resolveClamp, &resolveClamp, nullptr));
  PetscOptionsEnd();
  PetscCall(SystemCreate(p, s));
  PetscCall(SolverCreate(p, s, &ksp, boxes, grown));
  if (prefix[0]) { /* the solver's options again, now under the prefix */
    PetscCall(KSPSetOptionsPrefix(ksp, prefix));
    PetscCall(KSPSetFromOptions(ksp));
  }
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(SolveAndReport(ksp, s, PETSC_FALSE));
  if (checkPhi) PetscCall(CheckPhi(pc, s.rigid));
  if (checkCoarse) PetscCall(CheckCoarse(pc, s.A));
  if (reportSubdomains) PetscCall(ReportSubdomains(pc, s.A));
  if (resolveJump > 0 || resolveClamp) { /* new values, same pattern: the PC refactors and re-extends */
    if (resolveJump > 0) p.jump = resolveJump;
    if (resolveClamp) p.clampBoth = PETSC_TRUE;
    PetscCall(MatZeroEntries(s.A));
    PetscCall(VecZeroEntries(s.b));
    PetscCall(Assemble(p, s.A, s.b));
    PetscCall(Constrain(p, s.A, s.b, s.x, s.rigid));
    PetscCall(SolveAndReport(ksp, s, PETSC_TRUE));
    if (checkCoarse) PetscCall(CheckCoarse(pc, s.A));
  }

  for (IS &is : boxes) PetscCall(ISDestroy(&is));
  for (IS &is : grown) PetscCall(ISDestroy(&is));
  PetscCall(KSPDestroy(&ksp));
  PetscCall(SystemDestroy(s));
  PetscCall(PetscFinalize());
  return 0;
}
