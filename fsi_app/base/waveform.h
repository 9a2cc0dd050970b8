// SPDX-License-Identifier: BSD-2-Clause
/* A periodic signal of time — the pressure or flow of a cardiac cycle — given by samples or by
   its Fourier series. Samples (t_k, v_k), k = 0..n, cover one period T = t_n - t_0 and the last
   repeats the first (v_n = v_0); between them the periodic cubic spline (C2 in time, so the time
   schemes keep their order; its error is 5/384 h^4 max|v''''|). A Fourier series is
   v(t) = a_0 + sum_k a_k cos(2 pi k t / T) + b_k sin(2 pi k t / T). Both repeat with period T. */
#pragma once

#include <petscsys.h>
#include <string>
#include <vector>

namespace fsi {

struct Waveform {
  PetscReal              period = 0;
  std::vector<PetscReal> t, v, m; /* samples and the spline's second derivatives (empty: Fourier) */
  std::vector<PetscReal> fourier; /* a_0, a_1, b_1, a_2, b_2, ... */

  PetscReal Value(PetscReal time) const;
  /* a_0, a_1, b_1, ..., a_K, b_K: the series itself, or the samples' spline's coefficients by
     the trapezoidal rule on 64 K points (exact for its trigonometric part up to K; the spline's
     coefficients fall as k^-4, so the aliasing error is of the order of the K-th's) */
  std::vector<PetscReal> Harmonics(PetscInt K) const;
};

/* The samples of `file` (lines "t value", '#' starts a comment), read on rank 0: at least four,
   finite, t strictly increasing, the last value the first's. Errors name `option`, the file and
   the line. */
PetscErrorCode WaveformRead(MPI_Comm comm, const char *option, const std::string &file, Waveform &w);

/* The series T,a_0,a_1,b_1,... of `option` (n values): T > 0, every coefficient finite. */
PetscErrorCode WaveformFourier(const char *option, const PetscReal *c, PetscInt n, Waveform &w);

} // namespace fsi
