#pragma once
/// @file
/// Gauss-Legendre quadrature with 6 points (exact for polynomials up to degree 11) and 3 points
/// (up to degree 5); Abramowitz and Stegun, Table 25.4: the reference line's clothoid and poly3
/// arc-length integrals (6 points over a knot interval once, 3 points over half of one per
/// query).

#include <array>
#include <cstddef>
#include <type_traits>

namespace rig::model::road {

inline constexpr std::array<double, 3> kGaussNodes6{0.23861918608319693, 0.6612093864662645,
                                                    0.932469514203152};
inline constexpr std::array<double, 3> kGaussWeights6{0.46791393457269137, 0.36076157304813894,
                                                      0.17132449237916975};

/// The integral of f over [a, b] by 6-point Gauss-Legendre; f(x) returns a value that adds and
/// scales (double, or a small struct with + and *).
template <class F>
auto gauss_legendre6(double a, double b, const F& f) noexcept {
  using Value = std::decay_t<decltype(f(a))>;  // a value, never an expression template
  const double mid = 0.5 * (a + b);
  const double half = 0.5 * (b - a);
  Value sum = f(mid) * 0.0;
  for (std::size_t i = 0; i < kGaussNodes6.size(); ++i) {
    const double dx = half * kGaussNodes6[i];
    sum = sum + (f(mid - dx) + f(mid + dx)) * kGaussWeights6[i];
  }
  return Value(sum * half);
}

/// The integral of f over [a, b] by 3-point Gauss-Legendre (nodes 0, +-sqrt(3/5), weights 8/9,
/// 5/9).
template <class F>
auto gauss_legendre3(double a, double b, const F& f) noexcept {
  using Value = std::decay_t<decltype(f(a))>;
  const double mid = 0.5 * (a + b);
  const double half = 0.5 * (b - a);
  const double dx = half * 0.7745966692414834;
  return Value((f(mid) * (8.0 / 9.0) + (f(mid - dx) + f(mid + dx)) * (5.0 / 9.0)) * half);
}

}  // namespace rig::model::road
