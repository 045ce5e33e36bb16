#include "model/solver/arrowhead_factorization.h"

#include <algorithm>
#include <numeric>

namespace rig::model::solver {

Eigen::Index ArrowheadPartition::total_size() const noexcept {
  return std::accumulate(leaf_sizes.begin(), leaf_sizes.end(), body_size);
}

ArrowheadFactorization::ArrowheadFactorization(const ArrowheadPartition& partition)
    : partition_(partition),
      schur_(partition.body_size, partition.body_size),
      schur_lu_(partition.body_size),
      rhs_(partition.total_size()),
      sol_(partition.total_size()),
      body_rhs_(partition.body_size) {
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
}

void ArrowheadFactorization::compute(const Matrix& a) noexcept {
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
