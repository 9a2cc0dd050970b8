// SPDX-License-Identifier: BSD-2-Clause
#include "waveform.h"
#include "base/files.h"
#include "base/options.h"
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace fsi {

/* x of the tridiagonal system (a: below the diagonal, b: on it, c: above it), Thomas's algorithm. */
static std::vector<PetscReal> Tridiagonal(const std::vector<PetscReal> &a, const std::vector<PetscReal> &b, const std::vector<PetscReal> &c, std::vector<PetscReal> r)
{
  const size_t           n = b.size();
  std::vector<PetscReal> cp(n);
  PetscReal              d = b[0];
  cp[0] = c[0] / d, r[0] /= d;
  for (size_t i = 1; i < n; i++) {
    d     = b[i] - a[i] * cp[i - 1];
    cp[i] = c[i] / d, r[i] = (r[i] - a[i] * r[i - 1]) / d;
  }
  for (size_t i = n - 1; i-- > 0;) r[i] -= cp[i] * r[i + 1];
  return r;
}

/* The periodic spline's second derivatives: for each sample i (indices modulo n),
   h_{i-1} m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_i m_{i+1} = 6 (s_i - s_{i-1}), s_i the slope of
   interval i; the corners of the cyclic system by Sherman and Morrison's update. */
static void PeriodicSpline(Waveform &w)
{
  const size_t           n = w.t.size() - 1; /* intervals = unknowns */
  std::vector<PetscReal> h(n), s(n), a(n), b(n), c(n), r(n), u(n, 0.0);
  for (size_t i = 0; i < n; i++) h[i] = w.t[i + 1] - w.t[i], s[i] = (w.v[i + 1] - w.v[i]) / h[i];
  for (size_t i = 0; i < n; i++) {
    const size_t p = (i + n - 1) % n;
    a[i] = h[p], b[i] = 2 * (h[p] + h[i]), c[i] = h[i], r[i] = 6 * (s[i] - s[p]);
  }
  const PetscReal corner = h[n - 1], gamma = -b[0]; /* A[0][n-1] = A[n-1][0] = h_{n-1} */
  b[0] -= gamma, b[n - 1] -= corner * corner / gamma;
  u[0] = gamma, u[n - 1] = corner;
  std::vector<PetscReal> x = Tridiagonal(a, b, c, r), z = Tridiagonal(a, b, c, u);
  const PetscReal        f = (x[0] + corner * x[n - 1] / gamma) / (1 + z[0] + corner * z[n - 1] / gamma);
  w.m.resize(n + 1);
  for (size_t i = 0; i < n; i++) w.m[i] = x[i] - f * z[i];
  w.m[n] = w.m[0];
}

PetscReal Waveform::Value(PetscReal time) const
{
  if (t.empty()) {
    PetscReal value = fourier[0];
    for (size_t k = 1; 2 * k <= fourier.size(); k++) {
      const PetscReal phase = 2 * PETSC_PI * k * time / period;
      value += fourier[2 * k - 1] * PetscCosReal(phase) + (2 * k < fourier.size() ? fourier[2 * k] * PetscSinReal(phase) : 0.0);
    }
    return value;
  }
  PetscReal tau = std::fmod(time - t[0], period);
  if (tau < 0) tau += period;
  tau += t[0];
  const size_t    i = std::min((size_t)(std::upper_bound(t.begin(), t.end(), tau) - t.begin()), t.size() - 1) - 1;
  const PetscReal h = t[i + 1] - t[i], l = t[i + 1] - tau, r = tau - t[i];
  return m[i] * l * l * l / (6 * h) + m[i + 1] * r * r * r / (6 * h) + (v[i] / h - m[i] * h / 6) * l + (v[i + 1] / h - m[i + 1] * h / 6) * r;
}

std::vector<PetscReal> Waveform::Harmonics(PetscInt K) const
{
  std::vector<PetscReal> c(2 * K + 1, 0.0);
  if (t.empty()) {
    for (size_t k = 0; k < fourier.size() && k < c.size(); k++) c[k] = fourier[k];
    return c;
  }
  const PetscInt N = 64 * PetscMax(K, 1);
  for (PetscInt j = 0; j < N; j++) {
    const PetscReal tj = period * j / N, vj = Value(tj) / N;
    c[0] += vj;
    for (PetscInt k = 1; k <= K; k++) {
      const PetscReal phase = 2 * PETSC_PI * k * j / N;
      c[2 * k - 1] += 2 * vj * PetscCosReal(phase), c[2 * k] += 2 * vj * PetscSinReal(phase);
    }
  }
  return c;
}

/* "" if the samples of `file` make a waveform (then in w.t, w.v), else why not. */
static std::string ReadSamples(const char *option, const std::string &file, Waveform &w)
{
  std::ifstream     in;
  const std::string why = OpenInput(option, file, in);
  if (!why.empty()) return why;
  const std::string at = std::string(option) + " " + file + " line ";
  long              number = 0;
  for (std::string line; std::getline(in, line);) {
    number++;
    std::istringstream words(line.substr(0, line.find('#')));
    std::string        t, v, extra;
    if (!(words >> t)) continue; /* blank or a comment */
    char *end1, *end2;
    if (!(words >> v) || (words >> extra)) return at + std::to_string(number) + ": give two numbers, the time and the value (got '" + line + "')";
    const double x = std::strtod(t.c_str(), &end1), y = std::strtod(v.c_str(), &end2);
    if (*end1 || *end2 || end1 == t.c_str() || end2 == v.c_str()) return at + std::to_string(number) + ": '" + line + "' is not two numbers";
    if (!std::isfinite(x) || !std::isfinite(y)) return at + std::to_string(number) + ": '" + line + "': the time and the value must be finite";
    if (!w.t.empty() && x <= w.t.back()) return at + std::to_string(number) + ": the time " + t + " does not follow the previous one: the times must increase";
    w.t.push_back(x), w.v.push_back(y);
  }
  if (w.t.size() < 4) return std::string(option) + " " + file + ": " + std::to_string(w.t.size()) + " samples; give at least 4, one period of the signal (the last repeats the first)";
  const PetscReal scale = std::max(std::fabs(*std::max_element(w.v.begin(), w.v.end())), std::fabs(*std::min_element(w.v.begin(), w.v.end())));
  if (std::fabs(w.v.back() - w.v.front()) > 1e-9 * std::max(scale, (PetscReal)1e-300))
    return std::string(option) + " " + file + ": the last sample's value differs from the first's: give one period, whose last sample (at t0 + T) repeats the first";
  return "";
}

PetscErrorCode WaveformRead(MPI_Comm comm, const char *option, const std::string &file, Waveform &w)
{
  PetscMPIInt rank;
  PetscInt    n;

  PetscFunctionBegin;
  w = Waveform();
  PetscCall(CheckOnRankZero(comm, PETSC_ERR_FILE_UNEXPECTED, [&]() { return ReadSamples(option, file, w); }));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  n = (PetscInt)w.t.size();
  PetscCallMPI(MPI_Bcast(&n, 1, MPIU_INT, 0, comm));
  w.t.resize(n), w.v.resize(n);
  PetscCallMPI(MPI_Bcast(w.t.data(), (PetscMPIInt)n, MPIU_REAL, 0, comm));
  PetscCallMPI(MPI_Bcast(w.v.data(), (PetscMPIInt)n, MPIU_REAL, 0, comm));
  w.period = w.t.back() - w.t.front();
  PeriodicSpline(w);
  PetscFunctionReturn(0);
}

PetscErrorCode WaveformFourier(const char *option, const PetscReal *c, PetscInt n, Waveform &w)
{
  PetscFunctionBegin;
  PetscCheck(n >= 2, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s: give the period and the coefficients, T,a0,a1,b1,a2,b2,... (got %" PetscInt_FMT " values)", option, n);
  PetscCheck(c[0] > 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "%s: the period T (the first value) must be positive (got %s)", option, Number(c[0]).c_str());
  w = Waveform();
  w.period = c[0];
  w.fourier.assign(c + 1, c + n);
  PetscFunctionReturn(0);
}

} // namespace fsi
