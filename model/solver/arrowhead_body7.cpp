#include "model/solver/arrowhead_body7.h"

#include "model/solver/inverse_2x2.h"

namespace rig::model::solver {

namespace {

constexpr Eigen::Index kHead = 6;  // the chassis' speeds; the leaves start after them

/// Rows o, o + 1 of a over the body's columns (head, then the tail t).
Eigen::Matrix<double, 2, 7> leaf_rows(const Eigen::MatrixXd& a, Eigen::Index o, Eigen::Index t) {
  Eigen::Matrix<double, 2, 7> r;
  r.leftCols<kHead>() = a.block<2, kHead>(o, 0);
  r.col(kHead) = a.block<2, 1>(o, t);
  return r;
}

}  // namespace

ArrowheadBody7::ArrowheadBody7(std::size_t leaves)
    : leaf_inverse_(leaves), leaf_solved_(leaves), body_coupling_t_(leaves) {}

void ArrowheadBody7::compute(const Eigen::MatrixXd& a) noexcept {
  const Eigen::Index t = a.rows() - 1;
  Mat7 schur;
  schur.topLeftCorner<kHead, kHead>() = a.topLeftCorner<kHead, kHead>();
  schur.block<kHead, 1>(0, kHead) = a.block<kHead, 1>(0, t);
  schur.block<1, kHead>(kHead, 0) = a.block<1, kHead>(t, 0);
  schur(kHead, kHead) = a(t, t);
  for (std::size_t i = 0; i < leaf_inverse_.size(); ++i) {
    const Eigen::Index o = kHead + 2 * static_cast<Eigen::Index>(i);
    const Eigen::Matrix2d inv = inverse_2x2(a.block<2, 2>(o, o));  // a 2-DOF leaf
    leaf_inverse_[i] = inv;
    leaf_solved_[i].noalias() = inv * leaf_rows(a, o, t);
    body_coupling_t_[i].leftCols<kHead>() = a.block<kHead, 2>(0, o).transpose();
    body_coupling_t_[i].col(kHead) = a.block<1, 2>(t, o).transpose();
    // Schur complement S = A_BB - sum_i A_Bi A_ii^-1 A_iB
    schur.noalias() -= body_coupling_t_[i].transpose() * leaf_solved_[i];
  }
  schur_lu_.compute(schur);
}

void ArrowheadBody7::solve_column(const Eigen::VectorXd& rhs, Eigen::VectorXd& sol) const noexcept {
  const Eigen::Index t = rhs.size() - 1;
  Vec7 body;
  body.head<kHead>() = rhs.head<kHead>();
  body(kHead) = rhs(t);
  for (std::size_t i = 0; i < leaf_inverse_.size(); ++i) {
    const Eigen::Index o = kHead + 2 * static_cast<Eigen::Index>(i);
    const Eigen::Vector2d x = leaf_inverse_[i] * rhs.segment<2>(o);
    body.noalias() -= body_coupling_t_[i].transpose() * x;
  }
  const Vec7 xb = schur_lu_.solve(body);
  sol.head<kHead>() = xb.head<kHead>();
  sol(t) = xb(kHead);
  for (std::size_t i = 0; i < leaf_inverse_.size(); ++i) {
    const Eigen::Index o = kHead + 2 * static_cast<Eigen::Index>(i);
    sol.segment<2>(o) = leaf_inverse_[i] * rhs.segment<2>(o) - leaf_solved_[i] * xb;
  }
}

}  // namespace rig::model::solver
