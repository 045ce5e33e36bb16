#pragma once
/// @file
/// The mutable state of a leaf balance (leaf_balance.h): the rocker angle on each side and the
/// group's last balance (its warm start). One slot per balance in VehicleState, copied with it,
/// put at rest by a reset. Plain data.

#include <array>

#include <Eigen/Core>

namespace rig::model::vehicle {

/// Leaf balances per unit (a tandem; kMaxLeafAxles = 3 leaf axles leave room for one).
inline constexpr int kMaxLeafBalances = 1;

struct LeafBalanceState {
  using Vector6d = Eigen::Matrix<double, 6, 1>;
  using Matrix64d = Eigen::Matrix<double, 6, 4>;
  int first_axle = -1;  ///< the tandem's front axle (0 front); -1: unused
  /// The condensed unknowns u = (x_1, pitch_1, x_2, pitch_2, beta_left, beta_right): each
  /// axle's fore-aft travel and wind-up, and the rocker angles [rad, front end up +].
  Vector6d u = Vector6d::Zero();
  /// The last balance's inputs e = (heave_1, roll_1, heave_2, roll_2) and housing loads
  /// (F_x1, M_y1, F_x2, M_y2), and how u moved with them there: the next predictor.
  Eigen::Vector4d at = Eigen::Vector4d::Zero();
  Eigen::Vector4d load = Eigen::Vector4d::Zero();
  Matrix64d du_de = Matrix64d::Zero();
  Matrix64d du_dload = Matrix64d::Zero();
  /// Inputs told by prepare() for the evaluation under way (front axle first).
  Eigen::Vector4d next_at = Eigen::Vector4d::Zero();
  Eigen::Vector4d next_load = Eigen::Vector4d::Zero();
  std::array<double, 2> moment_residual_nm{};  ///< the rockers' moment at the last evaluation
  int evaluations = 0;                         ///< leaf evaluations (per leaf) in the last balance
};

}  // namespace rig::model::vehicle
