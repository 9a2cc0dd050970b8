/* SPDX-License-Identifier: BSD-2-Clause */
/* One SPD matrix (Matrix Market, symmetric) factored by CHOLMOD's supernodal Cholesky in double
   and in single precision: CHOLMOD 5 (SuiteSparse >= 7.4, Debian 13) factors in single
   precision when the matrix is single; an older CHOLMOD (Debian 12's 3.0) runs double only.
   The time of the numerical factorisation (the fastest of 3, and the first, into fresh memory
   as each of gdsw's factors is), of one solve (the mean of 10), and the error of the solution
   of A x = A 1. It answers what a single-precision factorisation would save gdsw's exact local
   solvers (docs/gdsw.md, "Where the time goes").

   cc -O2 -o cholmod_precision cholmod_precision.c -I/usr/include/suitesparse -lcholmod -lsuitesparseconfig -lm
   OMP_NUM_THREADS=1 ./cholmod_precision A.mtx */
#include <cholmod.h>
#include <math.h>
#include <stdio.h>
#include <time.h>

static double Now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static void Run(const char *file, int dtype, const char *name)
{
  cholmod_common c;
  cholmod_start(&c);
  c.supernodal = CHOLMOD_SUPERNODAL;
  FILE *f = fopen(file, "r");
#if CHOLMOD_MAIN_VERSION >= 5
  cholmod_sparse *A = cholmod_read_sparse2(f, dtype, &c);
#else
  cholmod_sparse *A = cholmod_read_sparse(f, &c);
#endif
  fclose(f);
  cholmod_dense  *one = cholmod_ones(A->nrow, 1, CHOLMOD_REAL + dtype, &c), *b = cholmod_zeros(A->nrow, 1, CHOLMOD_REAL + dtype, &c), *x = NULL;
  double          alpha[2] = {1, 0}, beta[2] = {0, 0};
  cholmod_sdmult(A, 0, alpha, beta, one, b, &c); /* b = A 1 */
  const double    t0 = Now();
  cholmod_factor *L  = cholmod_analyze(A, &c);
  const double    t1 = Now();
  double          best = 1e30, first = 0;
  for (int k = 0; k < 3; k++) { /* the first into fresh memory, as each of gdsw's factors is */
    const double s = Now();
    cholmod_factorize(A, L, &c);
    if (!k) first = Now() - s;
    if (Now() - s < best) best = Now() - s;
  }
  const double t2 = Now();
  for (int k = 0; k < 10; k++) {
    cholmod_free_dense(&x, &c);
    x = cholmod_solve(CHOLMOD_A, L, b, &c);
  }
  const double t3 = Now();
  double err = 0;
  for (size_t i = 0; i < A->nrow; i++) {
    const double xi = dtype == CHOLMOD_SINGLE ? ((float *)x->x)[i] : ((double *)x->x)[i];
    if (fabs(xi - 1) > err) err = fabs(xi - 1);
  }
  printf("%s %s: analysis %.3f s, factorisation %.3f s (the first %.3f s), solve %.2f ms, factor entries %.0f, flops %.2e, max |x - 1| %.1e (status %d)\n", file, name, t1 - t0, best, first, (t3 - t2) * 100, c.lnz, c.fl, err, c.status);
  cholmod_free_dense(&x, &c);
  cholmod_free_dense(&b, &c);
  cholmod_free_dense(&one, &c);
  cholmod_free_factor(&L, &c);
  cholmod_free_sparse(&A, &c);
  cholmod_finish(&c);
}

int main(int argc, char **argv)
{
  for (int i = 1; i < argc; i++) {
    Run(argv[i], CHOLMOD_DOUBLE, "double");
#if CHOLMOD_MAIN_VERSION >= 5
    Run(argv[i], CHOLMOD_SINGLE, "single");
#endif
  }
  return 0;
}
