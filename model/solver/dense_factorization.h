#pragma once
/// @file
/// Dense LU factorization of the modified mass matrix M_VI (eq. 8) for small blocks of known
/// size. With fixed N everything lives in the object; with Eigen::Dynamic the storage is sized
/// once in the constructor, so compute() and solve() never allocate.

#include <Eigen/Core>
#include <Eigen/LU>

#include "model/solver/fixed_lu.h"

namespace rig::model::solver {

/// Partial-pivoting LU of an N x N matrix.
template <int N>
class DenseFactorization {
 public:
  using Matrix = Eigen::Matrix<double, N, N>;

  /// @param size rows of the matrix (must equal N when N is fixed).
  explicit DenseFactorization(Eigen::Index size)
      : lu_(Matrix::Identity(size, size)),
        column_in_(Vector::Zero(size)),
        column_out_(Vector::Zero(size)) {}

  /// Factorizes a (copies it into the factorization's own storage).
  void compute(const Matrix& a) noexcept { lu_.compute(a); }

  /// x = A^-1 b, column by column; b and x may have any number of columns.
  template <typename Rhs, typename Dst>
  void solve(const Eigen::MatrixBase<Rhs>& b, Eigen::MatrixBase<Dst>& x) const noexcept {
    // Column by column through sized vectors: no temporaries for any column count.
    for (Eigen::Index c = 0; c < b.cols(); ++c) {
      column_in_ = b.col(c);
      column_out_ = lu_.solve(column_in_);
      x.col(c) = column_out_;
    }
  }

 private:
  using Vector = Eigen::Matrix<double, N, 1>;
  typename PartialPivLuOf<N>::type lu_;
  mutable Vector column_in_, column_out_;
};

}  // namespace rig::model::solver
