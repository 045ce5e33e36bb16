#pragma once
/// @file
/// The arrowhead factorization's fixed-size path for a vehicle with frame torsion: a body of 7
/// speeds (the chassis' 6 first, the frame's twist stored last, after the leaves) and 2-DOF
/// leaves (two hub travels or an axle's heave and roll) in between. It reads the blocks of eqs.
/// (30-31) straight from the given order, so that no permuted copy of M_VI and no reordered
/// right-hand side is formed: the same algebra as the 6-DOF body path (explicit 2 x 2 leaf
/// inverses, a fixed 7 x 7 Schur LU), without the general path's dynamic-size overhead.

#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

#include "model/solver/fixed_lu.h"

namespace rig::model::solver {

class ArrowheadBody7 {
 public:
  using Mat7 = Eigen::Matrix<double, 7, 7>;
  using Vec7 = Eigen::Matrix<double, 7, 1>;

  /// Storage for `leaves` leaf blocks, sized once.
  explicit ArrowheadBody7(std::size_t leaves);

  /// Factorizes a (given order: 6 body speeds, the leaves' 2 x leaves, 1 body tail).
  void compute(const Eigen::MatrixXd& a) noexcept;
  /// sol = A^-1 rhs (given order; rhs and sol must not alias).
  void solve_column(const Eigen::VectorXd& rhs, Eigen::VectorXd& sol) const noexcept;
  /// S^-1 b: the body rows (head, then tail) of A^-1 [b_B; 0].
  [[nodiscard]] Vec7 solve_body(const Vec7& b) const noexcept { return schur_lu_.solve(b); }

 private:
  using Mat27 = Eigen::Matrix<double, 2, 7>;
  std::vector<Eigen::Matrix2d> leaf_inverse_;  ///< A_ii^-1
  std::vector<Mat27> leaf_solved_;             ///< A_ii^-1 A_iB
  std::vector<Mat27> body_coupling_t_;         ///< A_Bi^T
  FixedLU<7> schur_lu_;
};

}  // namespace rig::model::solver
