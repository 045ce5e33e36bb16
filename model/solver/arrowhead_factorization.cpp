#include "model/solver/arrowhead_factorization.h"

#include <algorithm>
#include <numeric>

#include "model/solver/inverse_2x2.h"

namespace rig::model::solver {

Eigen::Index ArrowheadPartition::total_size() const noexcept {
  return std::accumulate(leaf_sizes.begin(), leaf_sizes.end(), body_size + body_tail_size);
}

namespace {

/// The partition with its body tail counted in the body (the factorized order).
ArrowheadPartition factorized(ArrowheadPartition p) {
  p.body_size += p.body_tail_size;
  p.body_tail_size = 0;
  return p;
}

}  // namespace

ArrowheadFactorization::ArrowheadFactorization(const ArrowheadPartition& given)
    : ArrowheadFactorization(factorized(given), given.body_size, given.body_tail_size) {}

ArrowheadFactorization::ArrowheadFactorization(const ArrowheadPartition& partition,
                                               Eigen::Index head, Eigen::Index tail)
    : partition_(partition),
      schur_(partition.body_size, partition.body_size),
      schur_lu_(partition.body_size),
      rhs_(partition.total_size()),
      sol_(partition.total_size()),
      body_rhs_(partition.body_size),
      head_(head),
      tail_(tail),
      body7_(head == 6 && tail == 1 ? partition.leaf_sizes.size() : 0) {
  if (tail_ > 0) {
    ordered_.resize(partition.total_size(), partition.total_size());
    given_.resize(partition.total_size());
  }
  const Eigen::Index nb = partition.body_size;
  Eigen::Index offset = nb;
  Eigen::Index max_leaf = 0;
  for (const Eigen::Index n : partition.leaf_sizes) {
    leaf_offsets_.push_back(offset);
    leaf_lu_.emplace_back(n);
    leaf_coupling_.emplace_back(n, nb);
    body_coupling_.emplace_back(nb, n);
    leaf_solved_.emplace_back(n, nb);
    offset += n;
    max_leaf = std::max(max_leaf, n);
  }
  leaf_tmp_.resize(max_leaf);
  body6_leaves2_ = nb == 6 && !partition.leaf_sizes.empty() &&
                   std::all_of(partition.leaf_sizes.begin(), partition.leaf_sizes.end(),
                               [](Eigen::Index n) { return n == 2; });
  body7_leaves2_ = head == 6 && tail == 1 && !partition.leaf_sizes.empty() &&
                   std::all_of(partition.leaf_sizes.begin(), partition.leaf_sizes.end(),
                               [](Eigen::Index n) { return n == 2; });
  if (body6_leaves2_) {
    leaf_inverse2_.resize(partition.leaf_sizes.size());
    leaf_solved2_.resize(partition.leaf_sizes.size());
    body_coupling2_t_.resize(partition.leaf_sizes.size());
  }
}

void ArrowheadFactorization::compute_body6_leaves2(const Matrix& a) noexcept {
  Mat6 schur = a.topLeftCorner<6, 6>();
  for (std::size_t i = 0; i < leaf_inverse2_.size(); ++i) {
    const Eigen::Index o = leaf_offsets_[i];
    const Eigen::Matrix2d inv = inverse_2x2(a.block<2, 2>(o, o));  // a 2-DOF leaf
    leaf_inverse2_[i] = inv;
    leaf_solved2_[i].noalias() = inv * a.block<2, 6>(o, 0);
    body_coupling2_t_[i] = a.block<6, 2>(0, o).transpose();
    // Schur complement S = A_BB - sum_i A_Bi A_ii^-1 A_iB
    schur.noalias() -= body_coupling2_t_[i].transpose() * leaf_solved2_[i];
  }
  schur_lu6_.compute(schur);
}

void ArrowheadFactorization::solve_column_body6_leaves2() const noexcept {
  Eigen::Matrix<double, 6, 1> body = rhs_.head<6>();
  for (std::size_t i = 0; i < leaf_inverse2_.size(); ++i) {
    const Eigen::Vector2d t = leaf_inverse2_[i] * rhs_.segment<2>(leaf_offsets_[i]);
    body.noalias() -= body_coupling2_t_[i].transpose() * t;
  }
  const Eigen::Matrix<double, 6, 1> xb = schur_lu6_.solve(body);
  sol_.head<6>() = xb;
  for (std::size_t i = 0; i < leaf_inverse2_.size(); ++i) {
    const Eigen::Index o = leaf_offsets_[i];
    sol_.segment<2>(o) = leaf_inverse2_[i] * rhs_.segment<2>(o) - leaf_solved2_[i] * xb;
  }
}

void ArrowheadFactorization::to_factorized_order(const Eigen::VectorXd& given,
                                                 Eigen::VectorXd& ordered) const noexcept {
  const Eigen::Index n = given.size(), leaves = n - head_ - tail_;
  ordered.head(head_) = given.head(head_);
  ordered.segment(head_, tail_) = given.tail(tail_);
  ordered.tail(leaves) = given.segment(head_, leaves);
}

void ArrowheadFactorization::from_factorized_order(const Eigen::VectorXd& ordered,
                                                   Eigen::VectorXd& given) const noexcept {
  const Eigen::Index n = given.size(), leaves = n - head_ - tail_;
  given.head(head_) = ordered.head(head_);
  given.tail(tail_) = ordered.segment(head_, tail_);
  given.segment(head_, leaves) = ordered.tail(leaves);
}

void ArrowheadFactorization::compute(const Matrix& a) noexcept {
  if (body6_leaves2_) {
    compute_body6_leaves2(a);
    return;
  }
  if (body7_leaves2_) {
    body7_.compute(a);  // in the given order: no permuted copy
    return;
  }
  if (tail_ == 0) {
    compute_general(a);
    return;
  }
  // P A P^T: rows and columns in the factorized order (body head, body tail, leaves)
  const Eigen::Index n = a.rows(), h = head_, t = tail_, l = n - h - t;
  const Eigen::Index src[3] = {0, n - t, h}, dst[3] = {0, h, h + t}, len[3] = {h, t, l};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c)
      ordered_.block(dst[r], dst[c], len[r], len[c]) = a.block(src[r], src[c], len[r], len[c]);
  }
  compute_general(ordered_);
}

void ArrowheadFactorization::compute_general(const Matrix& a) noexcept {
  const Eigen::Index nb = partition_.body_size;
  schur_ = a.topLeftCorner(nb, nb);
  for (std::size_t i = 0; i < leaf_lu_.size(); ++i) {
    const Eigen::Index o = leaf_offsets_[i];
    const Eigen::Index n = partition_.leaf_sizes[i];
    leaf_lu_[i].compute(a.block(o, o, n, n));
    leaf_coupling_[i] = a.block(o, 0, n, nb);
    body_coupling_[i] = a.block(0, o, nb, n);
    leaf_solved_[i] = leaf_lu_[i].solve(leaf_coupling_[i]);
    // Schur complement of the leaves: S = A_BB - sum_i A_Bi A_ii^-1 A_iB
    schur_.noalias() -= body_coupling_[i] * leaf_solved_[i];
  }
  schur_lu_.compute(schur_);
}

void ArrowheadFactorization::solve_column() const noexcept {
  if (body6_leaves2_) {
    solve_column_body6_leaves2();
    return;
  }
  if (body7_leaves2_) {
    body7_.solve_column(rhs_, sol_);
    return;
  }
  const Eigen::Index nb = partition_.body_size;
  // body: S x_B = b_B - sum_i A_Bi A_ii^-1 b_i
  body_rhs_ = rhs_.head(nb);
  for (std::size_t i = 0; i < leaf_lu_.size(); ++i) {
    const Eigen::Index o = leaf_offsets_[i];
    const Eigen::Index n = partition_.leaf_sizes[i];
    auto tmp = leaf_tmp_.head(n);
    tmp = leaf_lu_[i].solve(rhs_.segment(o, n));
    body_rhs_.noalias() -= body_coupling_[i] * tmp;
  }
  sol_.head(nb) = schur_lu_.solve(body_rhs_);
  // leaves: x_i = A_ii^-1 b_i - (A_ii^-1 A_iB) x_B
  for (std::size_t i = 0; i < leaf_lu_.size(); ++i) {
    const Eigen::Index o = leaf_offsets_[i];
    const Eigen::Index n = partition_.leaf_sizes[i];
    auto x_i = sol_.segment(o, n);
    x_i = leaf_lu_[i].solve(rhs_.segment(o, n));
    x_i.noalias() -= leaf_solved_[i] * sol_.head(nb);
  }
}

}  // namespace rig::model::solver
