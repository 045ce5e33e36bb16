#pragma once
/// @file
/// The differentials of a drive train as a tree over the driven wheels (README.md): the carrier
/// (w_c, the root's input) feeds the root; each differential j splits its input torque
/// r_j : (1 - r_j) to its sides a and b, and with its relative speed delta_j = w_a - w_b its
/// sides turn at w_a = w_in + (1 - r_j) delta_j, w_b = w_in - r_j delta_j (power conserved:
/// r w_a + (1 - r) w_b = w_in). So the shaft end of driven wheel i turns at
///   w_side_i = w_c + sum_j G_ij delta_j,  G_ij = 1 - r_j (i under side a), -r_j (side b), 0.
/// Built once (allocation here only); constant afterwards.

#include <array>

#include <Eigen/Core>

#include "model/vehicle/vehicle_params.h"
#include "model/vehicle/vehicle_state.h"

namespace rig::model::vehicle::differential {

using model::kMaxDifferentials;
inline constexpr int kMaxLeaves = kMaxWheels;
/// At most this many limited-slip differentials (the friction solve's contacts, dry_friction.h).
inline constexpr int kMaxLimitedSlip = 4;

// sized to the tree (n leaves, m differentials) within fixed maxima: never on the heap
using LeafMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxLeaves, kMaxDifferentials>;
using DiffMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDifferentials, kMaxDifferentials>;
using SideMatrix =
    Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxLeaves, kMaxDifferentials>;

struct DifferentialTree {
  int leaf_count = 0;                   ///< driven wheels
  std::array<int, kMaxLeaves> wheel{};  ///< leaf i's wheel (front to rear, left before right)
  int count = 0;                        ///< differentials: the configured, then implicit open
                                        ///< axle differentials of driven axles not named
  std::array<DifferentialParams, kMaxDifferentials> params{};  ///< per differential
  LeafMatrix g;                                                ///< n x m: w_side = w_c 1 + G delta
  DiffMatrix input_row;  ///< m x m: w_in_j = w_c + input_row.row(j) delta
  /// n x m: leaf i lies under side a (1) / side b (-1) of differential j, or not (0).
  SideMatrix side;
};

/// How many differentials the tree of p has (the configured and the implicit open ones across
/// the other driven axles); 0 without [[drivetrain.differential]] (today's open differentials).
[[nodiscard]] int differential_count(const VehicleParams& p) noexcept;

/// The tree of p.drivetrain.differentials over p's driven axles. Assumes what the loader checks
/// (io/config: every driven axle under exactly one root, sides disjoint, at most
/// kMaxDifferentials and kMaxLimitedSlip).
[[nodiscard]] DifferentialTree build_tree(const VehicleParams& p);

}  // namespace rig::model::vehicle::differential
