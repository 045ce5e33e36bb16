#pragma once
/// @file
/// The explicit inverse of a 2 x 2 block (adjugate over determinant): the arrowhead's 2-DOF
/// leaves (a hub's or an axle's mass + stiffness + damping, far from singular) need no pivoting.

#include <Eigen/Core>

namespace rig::model::solver {

[[nodiscard]] inline Eigen::Matrix2d inverse_2x2(const Eigen::Matrix2d& l) noexcept {
  const double det = l(0, 0) * l(1, 1) - l(0, 1) * l(1, 0);
  Eigen::Matrix2d inv;
  inv << l(1, 1), -l(0, 1), -l(1, 0), l(0, 0);
  inv /= det;
  return inv;
}

}  // namespace rig::model::solver
