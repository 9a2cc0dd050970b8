// SPDX-License-Identifier: BSD-2-Clause
/* One SPD matrix (a PETSc binary file) factored by MUMPS in double and in single precision
   (its C API, METIS ordering, one thread) and by CHOLMOD in double through PETSc: the time of
   the analysis, of the numerical factorisation and of one solve (the mean of 10), and the error
   of the solution of A x = A 1. It answers whether a single-precision factorisation would make
   gdsw's exact local solvers cheaper (docs/gdsw.md, "Where the time goes").

   mpicxx -O2 -o factor_precision factor_precision.cxx $(pkg-config --cflags --libs PETSc) -lsmumps -ldmumps -lmumps_common
   OMP_NUM_THREADS=1 ./factor_precision -f A.bin */
#include <petscmat.h>
#include <dmumps_c.h>
#include <smumps_c.h>
#include <chrono>
#include <cmath>
#include <vector>

static double Now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

/* The upper triangle (1-based COO, as MUMPS takes a symmetric matrix) in the precision T. */
template <class T>
struct Upper {
  std::vector<MUMPS_INT> i, j;
  std::vector<T>         a;
};

template <class Struc, class T>
static void Mumps(const char *name, void (*call)(Struc *), Upper<T> &A, int n, const std::vector<T> &b)
{
  Struc id{};
  id.comm_fortran = -987654, id.par = 1, id.sym = 1, id.job = -1; /* sym 1: SPD, LDL^T without pivoting */
  call(&id);
  id.icntl[0] = id.icntl[1] = id.icntl[2] = -1, id.icntl[3] = 0, id.icntl[6] = 5; /* quiet; METIS */
  id.n = n, id.nnz = (MUMPS_INT8)A.a.size(), id.irn = A.i.data(), id.jcn = A.j.data(), id.a = A.a.data();
  const double t0 = Now();
  id.job = 1, call(&id);
  const double t1 = Now();
  id.job = 2, call(&id);
  const double t2 = Now();
  std::vector<T> x;
  for (int k = 0; k < 10; k++) x = b, id.rhs = x.data(), id.nrhs = 1, id.lrhs = n, id.job = 3, call(&id);
  const double t3 = Now();
  double err = 0;
  for (int r = 0; r < n; r++) err = std::max(err, std::abs((double)x[r] - 1.0));
  std::printf("%s: analysis %.3f s, factorisation %.3f s, solve %.2f ms, factor entries %lld, max |x - 1| %.1e (info %d)\n", name, t1 - t0, t2 - t1, (t3 - t2) * 100, (long long)id.infog[8], err, id.infog[0]);
  id.job = -2, call(&id);
}

int main(int argc, char **argv)
{
  char          file[PETSC_MAX_PATH_LEN] = "";
  PetscViewer   viewer;
  Mat           A, F;
  Vec           one, b, x;
  IS            rows, cols;
  MatFactorInfo info;
  PetscInt      n;
  Upper<double> Ad;
  Upper<float>  As;

  PetscCall(PetscInitialize(&argc, &argv, nullptr, nullptr));
  PetscCall(PetscOptionsGetString(nullptr, nullptr, "-f", file, sizeof(file), nullptr));
  PetscCall(PetscViewerBinaryOpen(PETSC_COMM_SELF, file, FILE_MODE_READ, &viewer));
  PetscCall(MatCreate(PETSC_COMM_SELF, &A));
  PetscCall(MatSetType(A, MATSEQAIJ));
  PetscCall(MatLoad(A, viewer));
  PetscCall(PetscViewerDestroy(&viewer));
  PetscCall(MatGetSize(A, &n, nullptr));
  for (PetscInt r = 0; r < n; r++) {
    PetscInt           nc;
    const PetscInt    *c;
    const PetscScalar *v;
    PetscCall(MatGetRow(A, r, &nc, &c, &v));
    for (PetscInt k = 0; k < nc; k++)
      if (c[k] >= r) Ad.i.push_back(r + 1), Ad.j.push_back(c[k] + 1), Ad.a.push_back(v[k]), As.a.push_back((float)v[k]);
    PetscCall(MatRestoreRow(A, r, &nc, &c, &v));
  }
  As.i = Ad.i, As.j = Ad.j;
  PetscCall(MatCreateVecs(A, &one, &b));
  PetscCall(VecSet(one, 1.0));
  PetscCall(MatMult(A, one, b));
  const PetscScalar *bb;
  PetscCall(VecGetArrayRead(b, &bb));
  const std::vector<double> bd(bb, bb + n);
  const std::vector<float>  bs(bb, bb + n);
  PetscCall(VecRestoreArrayRead(b, &bb));
  std::printf("%s: %" PetscInt_FMT " rows, %zu entries in the upper triangle\n", file, n, Ad.a.size());
  Mumps<DMUMPS_STRUC_C, double>("MUMPS double", dmumps_c, Ad, (int)n, bd);
  Mumps<SMUMPS_STRUC_C, float>("MUMPS single", smumps_c, As, (int)n, bs);

  PetscCall(MatSetOption(A, MAT_SPD, PETSC_TRUE));
  PetscCall(MatGetFactor(A, MATSOLVERCHOLMOD, MAT_FACTOR_CHOLESKY, &F));
  PetscCall(MatGetOrdering(A, MATORDERINGNATURAL, &rows, &cols)); /* CHOLMOD orders itself */
  PetscCall(MatFactorInfoInitialize(&info));
  PetscCall(VecDuplicate(b, &x));
  const double t0 = Now();
  PetscCall(MatCholeskyFactorSymbolic(F, A, rows, &info));
  const double t1 = Now();
  PetscCall(MatCholeskyFactorNumeric(F, A, &info));
  const double t2 = Now();
  for (int k = 0; k < 10; k++) PetscCall(MatSolve(F, b, x));
  const double t3 = Now();
  std::printf("CHOLMOD double: analysis %.3f s, factorisation %.3f s, solve %.2f ms\n", t1 - t0, t2 - t1, (t3 - t2) * 100);
  PetscCall(MatDestroy(&F));
  PetscCall(ISDestroy(&rows));
  PetscCall(ISDestroy(&cols));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&one));
  PetscCall(VecDestroy(&b));
  PetscCall(MatDestroy(&A));
  PetscCall(PetscFinalize());
  return 0;
}
