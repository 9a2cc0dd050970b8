// SPDX-License-Identifier: BSD-2-Clause
/* MATSOLVERCHOLMODSINGLE ("cholmod_single"): the Cholesky factor of a sequential AIJ matrix,
   computed by CHOLMOD (supernodal, in double precision) and then kept and applied in single
   precision. A triangular solve reads the whole factor for a few flops per entry, so its time is
   the factor's bytes over the memory bandwidth: half the bytes, about half the time, and half the
   memory the factor keeps.
   Every numeric factorisation checks itself: the single-precision solve of a fixed pseudo-random
   right-hand side against the double-precision one. Where they differ by more than
   -mat_cholmod_single_deviation_max (1e-3) relative to the solution (an ill-conditioned matrix),
   the factor stays in double precision. */
#include "../gdswimpl.h"
#if GDSW_HAVE_SINGLE_FACTOR
#include <cholmod.h>
#include <SuiteSparse_config.h>
#include <petsc/private/matimpl.h>
#include <algorithm>
#include <cmath>
#include <vector>

/* A's CSR arrays go to CHOLMOD as they are: its int interface for 32-bit PetscInt, its long one
   (cholmod_l_*, SuiteSparse_long: int64_t) for 64-bit; the factor's arrays are then PetscInt too */
#if defined(PETSC_USE_64BIT_INDICES)
  #define CHOLMOD(name) cholmod_l_##name
  #define CHOLMOD_ITYPE CHOLMOD_LONG
static_assert(sizeof(SuiteSparse_long) == sizeof(PetscInt), "CHOLMOD's long indices are not PetscInt");
#else
  #define CHOLMOD(name) cholmod_##name
  #define CHOLMOD_ITYPE CHOLMOD_INT
#endif

/* single-precision BLAS, which PETSc's double build does not declare; its ints are PetscBLASInt */
extern "C" {
void strsv_(const char *, const char *, const char *, const PetscBLASInt *, const float *, const PetscBLASInt *, float *, const PetscBLASInt *);
void dtrsv_(const char *, const char *, const char *, const PetscBLASInt *, const double *, const PetscBLASInt *, double *, const PetscBLASInt *);
void sgemv_(const char *, const PetscBLASInt *, const PetscBLASInt *, const float *, const float *, const PetscBLASInt *, const float *, const PetscBLASInt *, const float *, float *, const PetscBLASInt *);
void dgemv_(const char *, const PetscBLASInt *, const PetscBLASInt *, const double *, const double *, const PetscBLASInt *, const double *, const PetscBLASInt *, const double *, double *, const PetscBLASInt *);
}

namespace {

struct SingleFactor {
  cholmod_common     c;
  cholmod_factor    *L = nullptr; /* supernodal; only its pattern once the values are in Lf */
  float             *Lf = nullptr;
  size_t             nnz = 0;       /* entries of the supernodes' dense blocks */
  double             fill = 0;      /* nnz over the entries of A's triangle */
  bool               single = false;
  /* 1e-3 leaves a preconditioner as good as with the double factor: the local solve perturbed far
     below what a Krylov method asks of its preconditioned residual */
  double             deviationMax = 1e-3;
  double             deviation = 0; /* of the last numeric factorisation's check */
  std::vector<float> xf, wf;
  std::vector<double> xd, wd;
};

inline void Trsv(const char *trans, PetscBLASInt n, const float *a, PetscBLASInt lda, float *x)
{
  const PetscBLASInt one = 1;
  strsv_("L", trans, "N", &n, a, &lda, x, &one);
}
inline void Trsv(const char *trans, PetscBLASInt n, const double *a, PetscBLASInt lda, double *x)
{
  const PetscBLASInt one = 1;
  dtrsv_("L", trans, "N", &n, a, &lda, x, &one);
}
inline void Gemv(const char *trans, PetscBLASInt m, PetscBLASInt n, float alpha, const float *a, PetscBLASInt lda, const float *x, float beta, float *y)
{
  const PetscBLASInt one = 1;
  sgemv_(trans, &m, &n, &alpha, a, &lda, x, &one, &beta, y, &one);
}
inline void Gemv(const char *trans, PetscBLASInt m, PetscBLASInt n, double alpha, const double *a, PetscBLASInt lda, const double *x, double beta, double *y)
{
  const PetscBLASInt one = 1;
  dgemv_(trans, &m, &n, &alpha, a, &lda, x, &one, &beta, y, &one);
}

/* x := L^{-T} L^{-1} x in the factor's (permuted) order. Supernode k holds columns
   super[k]..super[k+1]-1 as a dense column-major block of nr rows: its lower-triangular diagonal
   block, then the rows s[pi[k]+nc..] below it. w: at least the largest nr - nc. A supernode's
   rows fit PetscBLASInt (checked by the analysis). */
template <typename T>
void SupernodalSolve(const cholmod_factor *L, const T *Lx, T *x, T *w)
{
  const PetscInt *super = (const PetscInt *)L->super, *pi = (const PetscInt *)L->pi, *px = (const PetscInt *)L->px, *s = (const PetscInt *)L->s;
  const PetscInt  nsuper = (PetscInt)L->nsuper;
  for (PetscInt k = 0; k < nsuper; k++) {
    const PetscInt     c0 = super[k];
    const PetscBLASInt nc = (PetscBLASInt)(super[k + 1] - c0), nr = (PetscBLASInt)(pi[k + 1] - pi[k]), nb = nr - nc;
    const T           *X     = Lx + px[k];
    const PetscInt    *below = s + pi[k] + nc;
    Trsv("N", nc, X, nr, x + c0);
    if (!nb) continue;
    Gemv("N", nb, nc, T(1), X + nc, nr, x + c0, T(0), w);
    for (PetscBLASInt i = 0; i < nb; i++) x[below[i]] -= w[i];
  }
  for (PetscInt k = nsuper - 1; k >= 0; k--) {
    const PetscInt     c0 = super[k];
    const PetscBLASInt nc = (PetscBLASInt)(super[k + 1] - c0), nr = (PetscBLASInt)(pi[k + 1] - pi[k]), nb = nr - nc;
    const T           *X     = Lx + px[k];
    const PetscInt    *below = s + pi[k] + nc;
    if (nb) {
      for (PetscBLASInt i = 0; i < nb; i++) w[i] = x[below[i]];
      Gemv("T", nb, nc, T(-1), X + nc, nr, w, T(1), x + c0);
    }
    Trsv("T", nc, X, nr, x + c0);
  }
}

/* y = A^{-1} b through the factor, b and y in the matrix's order */
template <typename T>
void Solve(const cholmod_factor *L, const T *Lx, const PetscScalar *b, PetscScalar *y, std::vector<T> &x, std::vector<T> &w)
{
  const PetscInt *P = (const PetscInt *)L->Perm;
  const PetscInt  n = (PetscInt)L->n;
  for (PetscInt i = 0; i < n; i++) x[i] = (T)b[P[i]];
  SupernodalSolve(L, Lx, x.data(), w.data());
  for (PetscInt i = 0; i < n; i++) y[P[i]] = (PetscScalar)x[i];
}

/* A's CSR rows as CHOLMOD's compressed columns: the transpose, the same matrix; CHOLMOD reads the
   upper triangle of its columns */
PetscErrorCode Wrap(Mat A, cholmod_sparse *S, const PetscScalar **values)
{
  PetscInt        n;
  const PetscInt *ia, *ja;
  PetscBool       done;

  PetscFunctionBegin;
  PetscCall(MatGetRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  PetscCheck(done, PETSC_COMM_SELF, PETSC_ERR_SUP, "cholmod_single: cannot get the rows of the matrix");
  *S        = cholmod_sparse();
  S->nrow   = S->ncol = (size_t)n;
  S->nzmax  = (size_t)ia[n];
  S->p      = (void *)ia;
  S->i      = (void *)ja;
  S->stype  = 1;
  S->itype  = CHOLMOD_ITYPE;
  S->dtype  = CHOLMOD_DOUBLE;
  S->sorted = 1;
  S->packed = 1;
  S->xtype  = CHOLMOD_PATTERN;
  if (values) {
    PetscCall(MatSeqAIJGetArrayRead(A, values));
    S->x     = (void *)*values;
    S->xtype = CHOLMOD_REAL;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Unwrap(Mat A, cholmod_sparse *S, const PetscScalar **values)
{
  PetscInt  n;
  PetscBool done;

  PetscFunctionBegin;
  if (values) PetscCall(MatSeqAIJRestoreArrayRead(A, values));
  PetscCall(MatRestoreRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &n, (const PetscInt **)&S->p, (const PetscInt **)&S->i, &done));
  PetscFunctionReturn(0);
}

PetscErrorCode MatSolve_CholmodSingle(Mat F, Vec b, Vec y)
{
  SingleFactor      *f = (SingleFactor *)F->data;
  const PetscScalar *bb;
  PetscScalar       *yy;

  PetscFunctionBegin;
  PetscCall(VecGetArrayRead(b, &bb));
  PetscCall(VecGetArrayWrite(y, &yy));
  if (f->single) Solve(f->L, f->Lf, bb, yy, f->xf, f->wf);
  else Solve(f->L, (const double *)f->L->x, bb, yy, f->xd, f->wd);
  PetscCall(VecRestoreArrayRead(b, &bb));
  PetscCall(VecRestoreArrayWrite(y, &yy));
  PetscCall(PetscLogFlops(4.0 * (double)f->nnz));
  PetscFunctionReturn(0);
}

/* The relative deviation of the single-precision solve from the double one on a fixed
   pseudo-random right-hand side (the same in every run). */
double Deviation(SingleFactor *f)
{
  const size_t             n = f->L->n;
  std::vector<PetscScalar> b(n), yd(n), ys(n);
  unsigned long long       state = 0x9e3779b97f4a7c15ULL;
  for (size_t i = 0; i < n; i++) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    b[i]  = (double)(state >> 11) / 9007199254740992.0 - 0.5;
  }
  Solve(f->L, (const double *)f->L->x, b.data(), yd.data(), f->xd, f->wd);
  Solve(f->L, f->Lf, b.data(), ys.data(), f->xf, f->wf);
  double d = 0, y = 0;
  for (size_t i = 0; i < n; i++) d += (ys[i] - yd[i]) * (ys[i] - yd[i]), y += yd[i] * yd[i];
  return y > 0 ? std::sqrt(d / y) : 0.0;
}

PetscErrorCode MatCholeskyFactorNumeric_CholmodSingle(Mat F, Mat A, const MatFactorInfo *info)
{
  SingleFactor      *f = (SingleFactor *)F->data;
  cholmod_sparse     S;
  const PetscScalar *values;

  PetscFunctionBegin;
  if (f->Lf) f->Lf = (float *)SuiteSparse_free(f->Lf);
  PetscCall(Wrap(A, &S, &values));
  const double triangle = 0.5 * ((double)S.nzmax + (double)S.nrow);
  const int    ok       = CHOLMOD(factorize)(&S, f->L, &f->c);
  PetscCall(Unwrap(A, &S, &values));
  PetscCheck(ok && f->c.status >= CHOLMOD_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "cholmod_single: CHOLMOD's factorisation failed with status %d", f->c.status);
  PetscCall(PetscLogFlops(f->c.fl));
  F->ops->solve          = MatSolve_CholmodSingle;
  F->ops->solvetranspose = MatSolve_CholmodSingle;
  if (f->c.status == CHOLMOD_NOT_POSDEF) { /* a failure of the PC, which may then try LU */
    F->factorerrortype             = MAT_FACTOR_NUMERIC_ZEROPIVOT;
    F->factorerror_zeropivot_row   = (PetscInt)f->L->minor;
    F->factorerror_zeropivot_value = 0.0;
    PetscCall(PetscInfo(F, "cholmod_single: not positive definite (column %d of the factor)\n", (int)f->L->minor));
    PetscFunctionReturn(0);
  }
  F->factorerrortype = MAT_FACTOR_NOERROR;
  f->fill            = (double)f->nnz / triangle;
  f->Lf = (float *)SuiteSparse_malloc(f->nnz, sizeof(float));
  PetscCheck(f->Lf, PETSC_COMM_SELF, PETSC_ERR_MEM, "cholmod_single: out of memory for a factor of %zu entries", f->nnz);
  const double *Lx = (const double *)f->L->x;
  for (size_t k = 0; k < f->nnz; k++) f->Lf[k] = (float)Lx[k];
  f->deviation = Deviation(f);
  f->single    = f->deviation <= f->deviationMax;
  if (f->single) {
    PetscCall(PetscInfo(F, "cholmod_single: %zu entries; the single-precision solve deviates by %g from the double one\n", f->nnz, f->deviation));
    /* the double values go; the pattern stays for the next factorisation */
    PetscCheck(CHOLMOD(change_factor)(CHOLMOD_PATTERN, 1, 1, 1, 1, f->L, &f->c), PETSC_COMM_SELF, PETSC_ERR_LIB, "cholmod_single: CHOLMOD could not drop the double factor (status %d)", f->c.status);
  } else {
    f->Lf = (float *)SuiteSparse_free(f->Lf);
    PetscCall(PetscInfo(F, "cholmod_single: the single-precision solve deviates by %g from the double one (more than %g): the factor stays in double precision\n", f->deviation, f->deviationMax));
  }
  PetscFunctionReturn(0);
}

/* -mat_cholmod_single_deviation_max: a number >= 0, or a sentence that names the option */
PetscErrorCode CheckDeviationMax(Mat F)
{
  const char    *prefix = ((PetscObject)F)->prefix ? ((PetscObject)F)->prefix : "";
  char           value[256];
  PetscBool      set;
  PetscReal      r = -1;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscCall(PetscOptionsGetString(((PetscObject)F)->options, ((PetscObject)F)->prefix, "-mat_cholmod_single_deviation_max", value, sizeof(value), &set));
  if (!set) PetscFunctionReturn(0);
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  ierr = PetscOptionsStringToReal(value, &r);
  PetscCall(PetscPopErrorHandler());
  PetscCheck(!ierr && r >= 0 && !PetscIsInfOrNanReal(r), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "cholmod_single: -%smat_cholmod_single_deviation_max %s is out of range: give a number >= 0 (0 keeps every factor in double precision)", prefix, value);
  PetscFunctionReturn(0);
}

PetscErrorCode MatCholeskyFactorSymbolic_CholmodSingle(Mat F, Mat A, IS perm, const MatFactorInfo *info)
{
  SingleFactor   *f = (SingleFactor *)F->data;
  cholmod_sparse  S;
  const PetscInt *p = nullptr;

  PetscFunctionBegin;
  PetscCall(CheckDeviationMax(F));
  PetscObjectOptionsBegin((PetscObject)F);
  PetscCall(PetscOptionsReal("-mat_cholmod_single_deviation_max", "Largest deviation of the single-precision solve from the double one, relative to the solution, that keeps the factor in single precision", "MATSOLVERCHOLMODSINGLE", f->deviationMax, &f->deviationMax, nullptr));
  PetscOptionsEnd();
  if (f->L) CHOLMOD(free_factor)(&f->L, &f->c);
  if (f->Lf) f->Lf = (float *)SuiteSparse_free(f->Lf);
  PetscCall(Wrap(A, &S, nullptr));
  if (perm) { /* the given ordering only */
    PetscCall(ISGetIndices(perm, &p));
    f->c.nmethods           = 1;
    f->c.method[0].ordering = CHOLMOD_GIVEN;
  } else f->c.nmethods = 0; /* CHOLMOD's own choice */
  f->L = CHOLMOD(analyze_p)(&S, (PetscInt *)p, nullptr, 0, &f->c);
  if (perm) PetscCall(ISRestoreIndices(perm, &p));
  PetscCall(Unwrap(A, &S, nullptr));
  PetscCheck(f->L, PETSC_COMM_SELF, PETSC_ERR_LIB, "cholmod_single: CHOLMOD's analysis failed with status %d", f->c.status);
  /* the supernodes' sizes fix the factor's entries and the solves' work vectors; BLAS takes their rows */
  const PetscInt *super = (const PetscInt *)f->L->super, *pi = (const PetscInt *)f->L->pi;
  PetscInt        maxBelow = 0, maxRows = 0;
  for (size_t k = 0; k < f->L->nsuper; k++) {
    maxBelow = std::max(maxBelow, pi[k + 1] - pi[k] - (super[k + 1] - super[k]));
    maxRows  = std::max(maxRows, pi[k + 1] - pi[k]);
  }
  PetscBLASInt rows;
  PetscCall(PetscBLASIntCast(maxRows, &rows));
  f->nnz = (size_t)((const PetscInt *)f->L->px)[f->L->nsuper];
  f->xd.resize(f->L->n);
  f->wd.resize(maxBelow + 1);
  f->xf.resize(f->L->n);
  f->wf.resize(maxBelow + 1);
  F->ops->choleskyfactornumeric = MatCholeskyFactorNumeric_CholmodSingle;
  PetscFunctionReturn(0);
}

PetscErrorCode MatView_CholmodSingle(Mat F, PetscViewer viewer)
{
  SingleFactor     *f = (SingleFactor *)F->data;
  PetscBool         ascii;
  PetscViewerFormat format;

  PetscFunctionBegin;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &ascii));
  if (!ascii || !(f->Lf || (f->L && f->L->xtype != CHOLMOD_PATTERN))) PetscFunctionReturn(0); /* not factored */
  PetscCall(PetscViewerGetFormat(viewer, &format));
  if (format != PETSC_VIEWER_ASCII_INFO) PetscFunctionReturn(0);
  char deviation[32];
  snprintf(deviation, sizeof(deviation), "%.2g", f->deviation);
  PetscCall(PetscViewerASCIIPrintf(viewer, "CHOLMOD supernodal factor, %zu entries in %zu supernodes, kept in %s precision (its single-precision solve deviated by %s; limit %g)\n", f->nnz, f->L->nsuper, f->single ? "single" : "double", deviation, f->deviationMax));
  PetscFunctionReturn(0);
}

PetscErrorCode MatGetInfo_CholmodSingle(Mat F, MatInfoType flag, MatInfo *info)
{
  SingleFactor *f = (SingleFactor *)F->data;

  PetscFunctionBegin;
  PetscCall(PetscMemzero(info, sizeof(*info)));
  info->block_size   = 1.0;
  info->nz_used      = (PetscLogDouble)f->nnz;
  info->nz_allocated = (PetscLogDouble)f->nnz;
  info->memory            = (PetscLogDouble)f->nnz * (f->single ? sizeof(float) : sizeof(double));
  info->fill_ratio_needed = f->fill;
  PetscFunctionReturn(0);
}

PetscErrorCode MatFactorGetSolverType_CholmodSingle(Mat F, MatSolverType *type)
{
  PetscFunctionBegin;
  *type = MATSOLVERCHOLMODSINGLE;
  PetscFunctionReturn(0);
}

PetscErrorCode MatDestroy_CholmodSingle(Mat F)
{
  SingleFactor *f = (SingleFactor *)F->data;

  PetscFunctionBegin;
  if (f->Lf) SuiteSparse_free(f->Lf);
  if (f->L) CHOLMOD(free_factor)(&f->L, &f->c);
  CHOLMOD(finish)(&f->c);
  delete f;
  F->data = nullptr;
  PetscCall(PetscObjectComposeFunction((PetscObject)F, "MatFactorGetSolverType_C", nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode MatGetFactor_SeqAIJ_CholmodSingle(Mat A, MatFactorType ftype, Mat *F)
{
  Mat           B;
  PetscInt      m, n;
  SingleFactor *f;

  PetscFunctionBegin;
  PetscCall(MatGetSize(A, &m, &n));
  PetscCall(MatCreate(PETSC_COMM_SELF, &B));
  PetscCall(MatSetSizes(B, m, n, m, n));
  PetscCall(PetscLayoutSetUp(B->rmap));
  PetscCall(PetscLayoutSetUp(B->cmap));
  PetscCall(PetscStrallocpy(MATSOLVERCHOLMODSINGLE, &((PetscObject)B)->type_name));
  f = new SingleFactor;
  CHOLMOD(start)(&f->c);
  f->c.supernodal = CHOLMOD_SUPERNODAL; /* the solve above walks supernodes */
  f->c.print      = 0;                  /* a matrix that is not positive definite is the PC's failure to report */
  B->data                        = f;
  B->ops->choleskyfactorsymbolic = MatCholeskyFactorSymbolic_CholmodSingle;
  B->ops->view                   = MatView_CholmodSingle;
  B->ops->getinfo                = MatGetInfo_CholmodSingle;
  B->ops->destroy                = MatDestroy_CholmodSingle;
  B->factortype                  = MAT_FACTOR_CHOLESKY;
  B->assembled                   = PETSC_TRUE;
  B->preallocated                = PETSC_TRUE;
  B->canuseordering              = PETSC_TRUE;
  PetscCall(PetscStrallocpy(MATORDERINGEXTERNAL, (char **)&B->preferredordering[MAT_FACTOR_CHOLESKY]));
  PetscCall(PetscFree(B->solvertype));
  PetscCall(PetscStrallocpy(MATSOLVERCHOLMODSINGLE, &B->solvertype));
  PetscCall(PetscObjectComposeFunction((PetscObject)B, "MatFactorGetSolverType_C", MatFactorGetSolverType_CholmodSingle));
  *F = B;
  PetscFunctionReturn(0);
}

} // namespace

/*MC
   MATSOLVERCHOLMODSINGLE = "cholmod_single" - Cholesky factorisation of sequential `MATSEQAIJ`
   matrices by CHOLMOD (supernodal, in double precision), kept and applied in single precision;
   registered by the gdsw library (`PCGDSWRegister()`, or -dll_append)

   Use -pc_type cholesky -pc_factor_mat_solver_type cholmod_single; `PCGDSW` uses it for the
   Cholesky factors of its first level by default (`PCGDSWSetLocalPrecision()`).

   Options Database Key:
.  -mat_cholmod_single_deviation_max <1e-3> - the largest deviation of the single-precision solve
   from the double one, relative to the solution, on a fixed pseudo-random right-hand side, that
   keeps a factor in single precision; a factor that deviates more stays in double precision
   (-info says so), and 0 keeps every factor in double precision

   Notes:
   A triangular solve reads the whole factor for about four flops per entry and is limited by
   memory bandwidth: in single precision it reads half the bytes and takes about half the time,
   and the factor keeps half the memory (its double values are freed once rounded). The
   factorisation itself is CHOLMOD's, in double precision, with the ordering the `PC` gives
   (`MatGetOrdering()`, e.g. gdsw_nodes) or, with the ordering external (the default), CHOLMOD's
   own choice. A matrix that is not positive definite gives `MAT_FACTOR_NUMERIC_ZEROPIVOT`, as a
   failed `PCCHOLESKY`. Only real double-precision PETSc builds (32- or 64-bit indices).

   Level: intermediate

.seealso: `PCCHOLESKY`, `PCFactorSetMatSolverType()`, `MATSOLVERCHOLMOD`, `PCGDSWSetLocalPrecision()`
M*/

PetscErrorCode GDSWRegisterSingleFactor(void)
{
  PetscFunctionBegin;
  PetscCall(MatSolverTypeRegister(MATSOLVERCHOLMODSINGLE, MATSEQAIJ, MAT_FACTOR_CHOLESKY, MatGetFactor_SeqAIJ_CholmodSingle));
  PetscFunctionReturn(0);
}

PetscErrorCode GDSWFactorIsSingle(Mat F, PetscBool *single)
{
  PetscBool ours;

  PetscFunctionBegin;
  PetscCall(PetscObjectTypeCompare((PetscObject)F, MATSOLVERCHOLMODSINGLE, &ours));
  *single = (PetscBool)(ours && F->data && ((SingleFactor *)F->data)->single);
  PetscFunctionReturn(0);
}

#else /* the factors stay CHOLMOD's, in double precision */
PetscErrorCode GDSWRegisterSingleFactor(void)
{
  return 0;
}

PetscErrorCode GDSWFactorIsSingle(Mat F, PetscBool *single)
{
  *single = PETSC_FALSE;
  return 0;
}
#endif
