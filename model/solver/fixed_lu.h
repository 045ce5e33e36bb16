#pragma once
/// @file
/// Partial-pivoting LU of a small fixed-size matrix that gives Eigen::PartialPivLU's factors and
/// solutions bit for bit, with a factorization the compiler unrolls: Eigen's goes through a
/// dynamic-stride kernel even at fixed size (a 6 x 6 cost ~1.5 k instructions, four of them a
/// step on the 40 t combination). The elimination is Eigen's own (PartialPivLU.h,
/// unblocked_lu): the first largest |pivot| of the column, the column below divided by the
/// pivot, the rank-1 update of the rest, the last row apart; the solves are Eigen's triangular
/// solves on the same types. solver_test FixedLU.* compares both on random and singular matrices.

#include <array>
#include <cmath>

#include <Eigen/Core>
#include <Eigen/LU>

namespace rig::model::solver {

template <int N>
class FixedLU {
  static_assert(N > 0, "FixedLU is for fixed sizes; Eigen::PartialPivLU for dynamic ones");

 public:
  using Matrix = Eigen::Matrix<double, N, N>;

  FixedLU() noexcept : lu_(Matrix::Identity()) {
    for (int k = 0; k < N; ++k) transpositions_[static_cast<std::size_t>(k)] = k;
  }
  explicit FixedLU(const Matrix& a) noexcept { compute(a); }
  /// As Eigen::PartialPivLU(size), for code written for both (size == N).
  explicit FixedLU(Eigen::Index /*size*/) noexcept : FixedLU() {}

  FixedLU& compute(const Matrix& a) noexcept {
    lu_ = a;
    for (int k = 0; k < N - 1; ++k) {
      int p = k;
      double biggest = std::abs(lu_(k, k));
      for (int i = k + 1; i < N; ++i) {
        const double score = std::abs(lu_(i, k));
        if (score > biggest) {
          biggest = score;
          p = i;
        }
      }
      transpositions_[static_cast<std::size_t>(k)] = p;
      if (biggest != 0.0) {  // a zero column: no division, the update as Eigen's
        if (p != k) lu_.row(k).swap(lu_.row(p));
        const double pivot = lu_(k, k);
        for (int i = k + 1; i < N; ++i) lu_(i, k) /= pivot;
      }
      for (int j = k + 1; j < N; ++j)
        for (int i = k + 1; i < N; ++i) lu_(i, j) -= lu_(i, k) * lu_(k, j);
    }
    transpositions_[static_cast<std::size_t>(N - 1)] = N - 1;
    return *this;
  }

  /// x = A^-1 b (b: N rows, any columns).
  template <typename Rhs>
  [[nodiscard]] typename Rhs::PlainObject solve(const Eigen::MatrixBase<Rhs>& b) const noexcept {
    typename Rhs::PlainObject x = b;
    solve_in_place(x);
    return x;
  }
  template <typename Dst>
  void solve_in_place(Eigen::MatrixBase<Dst>& x) const noexcept {
    if constexpr (N > 1) {
      for (int k = 0; k < N - 1; ++k) {  // P b: the row exchanges in their order
        const int p = transpositions_[static_cast<std::size_t>(k)];
        if (p != k) x.row(k).swap(x.row(p));
      }
    }
    lu_.template triangularView<Eigen::UnitLower>().solveInPlace(x);
    lu_.template triangularView<Eigen::Upper>().solveInPlace(x);
  }
  [[nodiscard]] Matrix inverse() const noexcept { return solve(Matrix::Identity()); }

  [[nodiscard]] const Matrix& matrix_lu() const noexcept { return lu_; }

 private:
  Matrix lu_;
  std::array<int, static_cast<std::size_t>(N)> transpositions_{};
};

/// The partial-pivoting LU of an N x N matrix: FixedLU for a fixed N, Eigen's for a dynamic one.
template <int N>
struct PartialPivLuOf {
  using type = FixedLU<N>;
};
template <>
struct PartialPivLuOf<Eigen::Dynamic> {
  using type = Eigen::PartialPivLU<Eigen::MatrixXd>;
};

}  // namespace rig::model::solver
