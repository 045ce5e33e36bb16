#pragma once
/// @file
/// The mutable state of a rigid axle on five-link leaf springs (leaf_axle.h), one slot per
/// leaf-sprung axle in VehicleState: copied with it, so a fault's rollback and a save/restore
/// take the leaves' warm starts along. Plain data.

#include <array>

#include <Eigen/Core>

#include "model/vehicle/leaf_spring/leaf_spring.h"

namespace rig::model::vehicle {

/// Leaf-sprung axles per unit (a tractor's front axle and a tandem).
inline constexpr int kMaxLeafAxles = 3;

struct LeafAxleState {
  int axle = -1;  ///< the axle (0 front) this slot belongs to; -1: unused
  std::array<leaf_spring::LeafState, 2> leaf{};  ///< left, right: each leaf's last equilibrium
  /// The condensed coordinates (seat pose of both leaves, from the free leaf): the axle's
  /// fore-aft travel and wind-up (pitch, ISO 8855) where the leaves balance the housing's load.
  double x_m = 0;
  double pitch_rad = 0;
  double rest_x_m = 0;  ///< x_m at rest (the design position, no housing load)
  double rest_pitch_rad = 0;
  /// The last balanced evaluation (at heave, roll = `at`): the leaves' generalized forces on
  /// (heave, roll), their condensed stiffness, each leaf's vertical force (compression +).
  Eigen::Vector2d at = Eigen::Vector2d::Zero();
  Eigen::Vector2d q = Eigen::Vector2d::Zero();
  Eigen::Matrix2d dq_dy = Eigen::Matrix2d::Zero();
  std::array<double, 2> spring_n{};
  /// d(x, pitch)/d(housing load) and d(x, pitch)/d(heave, roll) there: the next step's
  /// predictor, and the housing load then.
  Eigen::Matrix2d d_balance_d_load = Eigen::Matrix2d::Zero();
  Eigen::Matrix2d d_balance_d_y = Eigen::Matrix2d::Zero();
  Eigen::Vector2d load = Eigen::Vector2d::Zero();
  std::array<int, 2> iterations{};  ///< each leaf's Newton iterations in that evaluation
  int balance_evaluations = 0;      ///< leaf evaluations (per side) to balance the housing
};

}  // namespace rig::model::vehicle
