#pragma once
/// @file
/// The parameters of one differential of a drive train (`[[drivetrain.differential]]`,
/// README.md): across an axle (between its left and right wheel) or between two groups of axles
/// (a centre or inter-axle differential), its kind and its locking.

#include <cstdint>
#include <vector>

namespace rig::model::vehicle::differential {

enum class DifferentialKind : std::uint8_t {
  kOpen,         ///< the split r : (1 - r) at any speed difference
  kLocked,       ///< both outputs turn as one (a constraint)
  kViscous,      ///< open + a viscous coupling between the outputs: c (w_a - w_b)
  kLimitedSlip,  ///< open + a clutch pack between the outputs (dry friction, stick predicted)
};

struct DifferentialParams {
  DifferentialKind kind = DifferentialKind::kOpen;
  /// Across an axle: its index (0-based, front to rear); side a its left wheel, side b its right.
  /// -1: between two groups of axles, side_a_axles and side_b_axles.
  int axle = -1;
  std::vector<int> side_a_axles;  ///< between: the first side's axles (0-based; e.g. the front)
  std::vector<int> side_b_axles;  ///< between: the second side's axles
  /// The fraction of the input torque to side a (open: at any speeds), in (0, 1).
  double split = 0.5;
  /// Viscous: the coupling's torque per speed difference of the outputs [N m s/rad].
  double viscous_nmspr = 0;
  /// Limited slip: the locking torque, the largest difference of the outputs' torques |T_a - T_b|
  /// (at an even split), T_L = preload_nm + (bias_ratio - 1) / (bias_ratio + 1) |T_in|, with
  /// T_in the input torque of the step's start; bias_ratio = T_high / T_low at the limit without
  /// preload (1: no torque sensing).
  double preload_nm = 0;
  double bias_ratio = 1;
  /// The driver may lock it: while the lock input (differential_lock_between_cmd for a between
  /// differential, differential_lock_axle_cmd across an axle) is 1 it turns as one.
  bool lockable = false;
};

}  // namespace rig::model::vehicle::differential
