#pragma once
/// @file
/// Block-sparse factorization of the modified mass matrix M_VI with the zero blocks of
/// eqs. (30-31): a "body" block B coupled to several "leaf" blocks (front axle, rear axle, more
/// axles of a truck) which are not coupled to each other:
///
///         [ A_BB  A_B1  A_B2 ... ]
///     A = [ A_1B  A_11   0   ... ]        (A_ij = 0 for leaves i != j)
///         [ A_2B   0    A_22 ... ]
///
/// Each leaf block is factorized alone, then the body's Schur complement
/// S = A_BB - sum_i A_Bi A_ii^-1 A_iB. Cost: sum of the small cubes plus n_B^3 instead of
/// (n_B + sum n_i)^3. All storage is sized in the constructor; compute() and solve() never
/// allocate. The vehicle's partition - a 6-DOF body and 2-DOF leaves (two hub travels per
/// axle) - takes a fixed-size path (2 x 2 leaf inverses, 6 x 6 Schur LU): the same algebra
/// without the dynamic-size overhead that dominates at these sizes; with a frame's twist as a
/// body tail of 1, likewise with a 7 x 7 Schur LU (arrowhead_body7.h).

#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

#include "model/solver/arrowhead_body7.h"

namespace rig::model::solver {

/// Partition of the speeds: the body block first, then the leaf blocks in order, then (optional)
/// `body_tail_size` more body speeds stored after the leaves (a vehicle's frame twist, appended
/// so that the hub travels keep their indices): they belong to the body block (they couple to
/// every leaf) and are moved next to it for the factorization.
struct ArrowheadPartition {
  Eigen::Index body_size = 0;
  std::vector<Eigen::Index> leaf_sizes;  ///< one entry per leaf (axle)
  Eigen::Index body_tail_size = 0;
  [[nodiscard]] Eigen::Index total_size() const noexcept;
};

/// LU of an arrowhead block matrix (see file comment). Entries of the zero blocks are ignored,
/// whatever they hold.
class ArrowheadFactorization {
 public:
  using Matrix = Eigen::MatrixXd;

  explicit ArrowheadFactorization(const ArrowheadPartition& partition);
  /// For MechanicalStepper<Eigen::Dynamic, ArrowheadFactorization>: the size is implied by the
  /// partition given at construction, so this constructor is not offered.
  explicit ArrowheadFactorization(Eigen::Index size) = delete;

  /// The partition as factorized: a body tail is counted in body_size (and body_tail_size is 0),
  /// so solve_body takes the body in that order (head, then tail).
  [[nodiscard]] const ArrowheadPartition& partition() const noexcept { return partition_; }
  /// The given partition's body head: the leading rows that are body rows in both orders.
  [[nodiscard]] Eigen::Index body_head_size() const noexcept { return head_; }

  /// Factorizes a (total_size x total_size).
  void compute(const Matrix& a) noexcept;

  /// x = A^-1 b, column by column (b, x: total_size x any columns; they must not alias).
  template <typename Rhs, typename Dst>
  void solve(const Eigen::MatrixBase<Rhs>& b, Eigen::MatrixBase<Dst>& x) const noexcept {
    for (Eigen::Index c = 0; c < b.cols(); ++c) {
      if (tail_ == 0 || body7_leaves2_) {
        rhs_ = b.col(c);
        solve_column();
        x.col(c) = sol_;
        continue;
      }
      given_ = b.col(c);
      to_factorized_order(given_, rhs_);
      solve_column();
      from_factorized_order(sol_, given_);
      x.col(c) = given_;
    }
  }

  /// x_B = body rows of A^-1 [b_B; 0], for a right-hand side that is zero on every leaf row
  /// (e.g. forces acting on the body coordinates only). With the leaves eliminated this is
  /// S^-1 b_B: one body_size solve with the factorized Schur complement per column instead of a
  /// full solve, and no leaf rows are formed. b_B, x_B: body_size x any columns (must not alias);
  /// or fewer rows, at most body_head_size(): the body's further rows (a tail) are then zero and
  /// x_B gets as many rows as b_B.
  template <typename Rhs, typename Dst>
  void solve_body(const Eigen::MatrixBase<Rhs>& b_body,
                  Eigen::MatrixBase<Dst>& x_body) const noexcept {
    const Eigen::Index r = b_body.rows();
    for (Eigen::Index c = 0; c < b_body.cols(); ++c) {
      if (body6_leaves2_) {
        // fixed-size in and out: a solve straight into a dynamic column takes Eigen's generic
        // triangular solver, about twice the instructions
        Eigen::Matrix<double, 6, 1> col = Eigen::Matrix<double, 6, 1>::Zero();
        col.head(r) = b_body.col(c);
        const Eigen::Matrix<double, 6, 1> x = schur_lu6_.solve(col);
        x_body.col(c) = x.head(r);
      } else if (body7_leaves2_) {
        ArrowheadBody7::Vec7 col = ArrowheadBody7::Vec7::Zero();
        col.head(r) = b_body.col(c);
        const ArrowheadBody7::Vec7 x = body7_.solve_body(col);
        x_body.col(c) = x.head(r);
      } else {
        body_rhs_.setZero();
        body_rhs_.head(r) = b_body.col(c);
        sol_.head(partition_.body_size) = schur_lu_.solve(body_rhs_);
        x_body.col(c) = sol_.head(r);
      }
    }
  }

 private:
  ArrowheadFactorization(const ArrowheadPartition& partition, Eigen::Index head, Eigen::Index tail);
  void solve_column() const noexcept;
  void compute_general(const Matrix& a) noexcept;
  /// The body tail (stored last) moved behind the body head, and back.
  void to_factorized_order(const Eigen::VectorXd& given, Eigen::VectorXd& ordered) const noexcept;
  void from_factorized_order(const Eigen::VectorXd& ordered, Eigen::VectorXd& given) const noexcept;
  void compute_body6_leaves2(const Matrix& a) noexcept;
  void solve_column_body6_leaves2() const noexcept;

  ArrowheadPartition partition_;
  std::vector<Eigen::Index> leaf_offsets_;
  std::vector<Eigen::PartialPivLU<Eigen::MatrixXd>> leaf_lu_;
  std::vector<Eigen::MatrixXd> leaf_coupling_;  ///< A_iB
  std::vector<Eigen::MatrixXd> body_coupling_;  ///< A_Bi
  std::vector<Eigen::MatrixXd> leaf_solved_;    ///< A_ii^-1 A_iB
  Eigen::MatrixXd schur_;                       ///< S
  Eigen::PartialPivLU<Eigen::MatrixXd> schur_lu_;
  mutable Eigen::VectorXd rhs_, sol_, body_rhs_, leaf_tmp_;
  Eigen::Index head_ = 0, tail_ = 0;  ///< the given partition's body head and tail
  Matrix ordered_;                    ///< A in the factorized order (tail_ > 0 only)
  mutable Eigen::VectorXd given_;     ///< a column in the given order (tail_ > 0 only)

  // fixed-size path: body 6, every leaf 2
  using Mat6 = Eigen::Matrix<double, 6, 6>;
  using Mat26 = Eigen::Matrix<double, 2, 6>;
  bool body6_leaves2_ = false;
  std::vector<Eigen::Matrix2d> leaf_inverse2_;  ///< A_ii^-1
  std::vector<Mat26> leaf_solved2_;             ///< A_ii^-1 A_iB
  std::vector<Mat26> body_coupling2_t_;         ///< A_Bi^T
  FixedLU<6> schur_lu6_;

  // fixed-size path: body 6 + a tail of 1 (stored last), every leaf 2
  bool body7_leaves2_ = false;
  ArrowheadBody7 body7_;
};

}  // namespace rig::model::solver
