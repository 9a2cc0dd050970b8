// SPDX-License-Identifier: BSD-2-Clause
/* Forward-mode automatic differentiation with N directions, nestable (Dual<9, Dual<9>> gives
   second derivatives): stress and exact tangent of a hyperelastic law from its energy alone. */
#pragma once

#include <cmath>

namespace fsi {

template <int N, class T = double>
struct Dual {
  T v{};
  T d[N]{};
  Dual() = default;
  Dual(double c) : v(c) { }
  Dual(const T &c, int) : v(c) { }
};

#define FSI_DUAL_BINARY(op, val, der)                                                    \
  template <int N, class T>                                                              \
  inline Dual<N, T> operator op(const Dual<N, T> &a, const Dual<N, T> &b)                \
  {                                                                                      \
    Dual<N, T> r;                                                                        \
    r.v = val;                                                                           \
    for (int i = 0; i < N; i++) r.d[i] = der;                                            \
    return r;                                                                            \
  }                                                                                      \
  template <int N, class T>                                                              \
  inline Dual<N, T> operator op(const Dual<N, T> &a, double c) { return a op Dual<N, T>(T(c), 0); } \
  template <int N, class T>                                                              \
  inline Dual<N, T> operator op(double c, const Dual<N, T> &b) { return Dual<N, T>(T(c), 0) op b; }
FSI_DUAL_BINARY(+, a.v + b.v, a.d[i] + b.d[i])
FSI_DUAL_BINARY(-, a.v - b.v, a.d[i] - b.d[i])
FSI_DUAL_BINARY(*, a.v * b.v, a.d[i] * b.v + a.v * b.d[i])
FSI_DUAL_BINARY(/, a.v / b.v, (a.d[i] * b.v - a.v * b.d[i]) / (b.v * b.v))
#undef FSI_DUAL_BINARY

template <int N, class T>
inline Dual<N, T> operator-(const Dual<N, T> &a) { return 0.0 - a; }

/* f(a) with f'(a.v) given: the chain rule, once for every function below */
template <int N, class T>
inline Dual<N, T> Chain(const Dual<N, T> &a, const T &f, const T &df)
{
  Dual<N, T> r;
  r.v = f;
  for (int i = 0; i < N; i++) r.d[i] = df * a.d[i];
  return r;
}
template <int N, class T>
inline Dual<N, T> log(const Dual<N, T> &a) { using std::log; return Chain(a, log(a.v), 1.0 / a.v); }
template <int N, class T>
inline Dual<N, T> pow(const Dual<N, T> &a, double p) { using std::pow; return Chain(a, pow(a.v, p), p * pow(a.v, p - 1)); }
template <int N, class T>
inline Dual<N, T> sqrt(const Dual<N, T> &a) { using std::sqrt; const T s = sqrt(a.v); return Chain(a, s, 0.5 / s); }
template <int N, class T>
inline Dual<N, T> exp(const Dual<N, T> &a) { using std::exp; const T e = exp(a.v); return Chain(a, e, e); }
template <int N, class T>
inline bool operator>(const Dual<N, T> &a, double c) { return a.v > c; }

} // namespace fsi
