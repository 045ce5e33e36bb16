#pragma once
/// @file
/// Gaussian elimination with partial pivoting for the leaf's fixed 7 x 7 bordered system and a
/// few right-hand sides at once, unrolled by the compiler: Eigen's PartialPivLU goes through its
/// blocked, dynamic-stride kernels even at fixed size, which cost 2-3 times as much here.

#include <cmath>
#include <utility>

#include <Eigen/Core>

namespace rig::model::vehicle::leaf_spring {

/// Solves a x = b in place (b becomes x; a is consumed). False if a pivot is zero or not finite.
template <int N, int M>
bool solve_in_place(Eigen::Matrix<double, N, N>& a, Eigen::Matrix<double, N, M>& b) noexcept {
  for (int k = 0; k < N; ++k) {
    int p = k;
    for (int i = k + 1; i < N; ++i) {
      if (std::abs(a(i, k)) > std::abs(a(p, k))) p = i;
    }
    if (!(std::abs(a(p, k)) > 0.0) || !std::isfinite(a(p, k))) return false;
    if (p != k) {
      a.row(p).swap(a.row(k));
      b.row(p).swap(b.row(k));
    }
    const double inv = 1.0 / a(k, k);
    for (int i = k + 1; i < N; ++i) {
      const double f = a(i, k) * inv;
      if (f == 0.0) continue;
      for (int j = k + 1; j < N; ++j) a(i, j) -= f * a(k, j);
      b.row(i) -= f * b.row(k);
    }
  }
  for (int k = N - 1; k >= 0; --k) {
    for (int j = k + 1; j < N; ++j) b.row(k) -= a(k, j) * b.row(j);
    b.row(k) /= a(k, k);
  }
  return true;
}

}  // namespace rig::model::vehicle::leaf_spring
