#pragma once
/// @file
/// Forward-difference Jacobians of a mechanical block's q in dynamic matrices, for comparing the
/// analytic partials with: the solver's own `finite_difference_force_jacobians` (step
/// sqrt(eps) max(1, |x|), model/solver/finite_difference.h), the one the stepper falls back on.

#include <Eigen/Core>

#include "model/solver/finite_difference.h"
#include "model/solver/mechanical_block.h"

namespace rig::test {

/// dq/dy and dq/dz of `block` at (y, z) by forward differences (allocates: tests only).
template <int N>
void fd_jacobians(const model::solver::MechanicalBlock<N>& block,
                  const typename model::solver::MechanicalBlock<N>::Vector& y,
                  const typename model::solver::MechanicalBlock<N>::Vector& z,
                  Eigen::MatrixXd& dq_dy, Eigen::MatrixXd& dq_dz) {
  using Block = model::solver::MechanicalBlock<N>;
  const Eigen::Index n = y.size();
  typename Block::Matrix dy(n, n), dz(n, n);
  typename Block::Vector work_y = y, work_z = z, q0 = y, q1 = y;
  model::solver::finite_difference_force_jacobians<N>(block, y, z, dy, dz, work_y, work_z, q0, q1);
  dq_dy = dy;
  dq_dz = dz;
}

/// |a - b| / |b| (Frobenius), the agreement the tests print and bound.
inline double relative_error(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).norm() / b.norm();
}

}  // namespace rig::test
