#pragma once
/// @file
/// Forward-difference Jacobians: the fallback for blocks without analytic partial derivatives
/// (prototyping) and the check of analytic ones in tests. Workspaces are passed in, so nothing
/// is allocated.

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Core>

#include "model/solver/force_element.h"
#include "model/solver/mechanical_block.h"

namespace rig::model::solver {

/// Perturbation for forward differences of a coordinate of magnitude |x|.
inline double fd_step(double x) noexcept {
  return std::sqrt(std::numeric_limits<double>::epsilon()) * std::max(1.0, std::abs(x));
}

/// df/ds of a force element by forward differences at s. work_s, f0, f1: workspaces of size n.
template <int N>
void finite_difference_rate_jacobian(const ForceElement<N>& element,
                                     const typename ForceElement<N>::Vector& s,
                                     typename ForceElement<N>::Matrix& df_ds,
                                     typename ForceElement<N>::Vector& work_s,
                                     typename ForceElement<N>::Vector& f0,
                                     typename ForceElement<N>::Vector& f1) noexcept {
  element.rate(s, f0);
  work_s = s;
  for (Eigen::Index j = 0; j < s.size(); ++j) {
    const double delta = fd_step(s(j));
    work_s(j) = s(j) + delta;
    element.rate(work_s, f1);
    df_ds.col(j) = (f1 - f0) / delta;
    work_s(j) = s(j);
  }
}

/// dq/dy and dq/dz of a mechanical block by forward differences at (y, z).
/// work_y, work_z, q0, q1: workspaces of size n.
template <int N>
void finite_difference_force_jacobians(
    const MechanicalBlock<N>& block, const typename MechanicalBlock<N>::Vector& y,
    const typename MechanicalBlock<N>::Vector& z, typename MechanicalBlock<N>::Matrix& dq_dy,
    typename MechanicalBlock<N>::Matrix& dq_dz, typename MechanicalBlock<N>::Vector& work_y,
    typename MechanicalBlock<N>::Vector& work_z, typename MechanicalBlock<N>::Vector& q0,
    typename MechanicalBlock<N>::Vector& q1) noexcept {
  block.applied_forces(y, z, q0);
  work_y = y;
  work_z = z;
  for (Eigen::Index j = 0; j < y.size(); ++j) {
    const double delta = fd_step(y(j));
    work_y(j) = y(j) + delta;
    block.applied_forces(work_y, z, q1);
    dq_dy.col(j) = (q1 - q0) / delta;
    work_y(j) = y(j);
  }
  for (Eigen::Index j = 0; j < z.size(); ++j) {
    const double delta = fd_step(z(j));
    work_z(j) = z(j) + delta;
    block.applied_forces(y, work_z, q1);
    dq_dz.col(j) = (q1 - q0) / delta;
    work_z(j) = z(j);
  }
}

}  // namespace rig::model::solver
