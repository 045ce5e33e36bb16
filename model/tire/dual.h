#pragma once
/// @file
/// A forward-mode dual number with N fixed derivative slots: exact partial derivatives of the
/// smooth TMeasy formulas without hand-written chain rules. Allocation-free; internal to
/// model/tire (used by the .cpp files).

#include <cmath>

namespace rig::model::tire::internal {

template <int N>
struct Dual {
  double v = 0;
  double d[N] = {};

  constexpr Dual() = default;
  constexpr Dual(double value) : v(value) {}  // NOLINT: implicit from constants is intended
  static constexpr Dual variable(double value, int slot, double seed = 1.0) {
    Dual r(value);
    r.d[slot] = seed;
    return r;
  }
};

template <int N>
constexpr Dual<N> operator+(const Dual<N>& a, const Dual<N>& b) {
  Dual<N> r(a.v + b.v);
  for (int i = 0; i < N; ++i) r.d[i] = a.d[i] + b.d[i];
  return r;
}
template <int N>
constexpr Dual<N> operator-(const Dual<N>& a, const Dual<N>& b) {
  Dual<N> r(a.v - b.v);
  for (int i = 0; i < N; ++i) r.d[i] = a.d[i] - b.d[i];
  return r;
}
template <int N>
constexpr Dual<N> operator-(const Dual<N>& a) {
  Dual<N> r(-a.v);
  for (int i = 0; i < N; ++i) r.d[i] = -a.d[i];
  return r;
}
template <int N>
constexpr Dual<N> operator*(const Dual<N>& a, const Dual<N>& b) {
  Dual<N> r(a.v * b.v);
  for (int i = 0; i < N; ++i) r.d[i] = a.d[i] * b.v + a.v * b.d[i];
  return r;
}
template <int N>
constexpr Dual<N> operator/(const Dual<N>& a, const Dual<N>& b) {
  const double inv = 1.0 / b.v;
  Dual<N> r(a.v * inv);
  for (int i = 0; i < N; ++i) r.d[i] = (a.d[i] - r.v * b.d[i]) * inv;
  return r;
}
template <int N>
constexpr Dual<N> operator+(const Dual<N>& a, double b) {
  return a + Dual<N>(b);
}
template <int N>
constexpr Dual<N> operator+(double a, const Dual<N>& b) {
  return Dual<N>(a) + b;
}
template <int N>
constexpr Dual<N> operator-(const Dual<N>& a, double b) {
  return a - Dual<N>(b);
}
template <int N>
constexpr Dual<N> operator-(double a, const Dual<N>& b) {
  return Dual<N>(a) - b;
}
template <int N>
constexpr Dual<N> operator*(const Dual<N>& a, double b) {
  Dual<N> r(a.v * b);
  for (int i = 0; i < N; ++i) r.d[i] = a.d[i] * b;
  return r;
}
template <int N>
constexpr Dual<N> operator*(double a, const Dual<N>& b) {
  return b * a;
}
template <int N>
constexpr Dual<N> operator/(const Dual<N>& a, double b) {
  return a * (1.0 / b);
}
template <int N>
constexpr Dual<N> operator/(double a, const Dual<N>& b) {
  return Dual<N>(a) / b;
}

template <int N>
inline Dual<N> sqrt(const Dual<N>& a) {
  const double s = std::sqrt(a.v);
  Dual<N> r(s);
  const double k = s > 0.0 ? 0.5 / s : 0.0;  // sqrt at 0: derivative taken as 0 (guarded use)
  for (int i = 0; i < N; ++i) r.d[i] = a.d[i] * k;
  return r;
}
template <int N>
inline Dual<N> cos(const Dual<N>& a) {
  Dual<N> r(std::cos(a.v));
  const double k = -std::sin(a.v);
  for (int i = 0; i < N; ++i) r.d[i] = a.d[i] * k;
  return r;
}
template <int N>
constexpr Dual<N> abs(const Dual<N>& a) {
  return a.v < 0.0 ? -a : a;
}

inline double value_of(double x) { return x; }
template <int N>
constexpr double value_of(const Dual<N>& x) {
  return x.v;
}

}  // namespace rig::model::tire::internal
