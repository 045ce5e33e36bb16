#pragma once
/// @file
/// Joints between two units of a vehicle combination as position constraints 0 = g(y_a, y_b)
/// (eq. 39) over the chassis coordinates y_B = [x, y, z, yaw, pitch, roll] of the leading unit a
/// and the trailing unit b (the hub-travel columns of dg/dy are zero).
///
/// - Ball hitch (tow ball, drawbar eye, dolly): the hitch points coincide, 3 rows
///     g = r_a + R_a p_a - r_b - R_b p_b                     (road frame).
/// - Fifth wheel: the ball rows plus one roll constraint,
///     g_4 = (R_a e_y) . (R_b e_z),
///   i.e. a Cardan joint: the semitrailer may yaw about its kingpin axis (its own z) and pitch
///   about the plate's pivot axis (the tractor's y), but it cannot roll relative to the tractor.
///   Why a constraint and not its limit, a stiff roll support: a stiff spring between two units
///   makes the pair stiff, and stability then needs their coupled implicit matrix (eqs. 32-38) -
///   exactly what the DAE approach avoids. As a constraint it costs one more multiplier (a 4x4
///   Newton matrix instead of 3x3) and nothing else. The lash and roll compliance of a real
///   fifth wheel (a few degrees before the plate takes roll moment) are not modelled.
/// - Tow bar (car + tow bar + car, method.md sec. 5): a rigid rod of length L pinned at a point
///   of the leading unit and a point of the towed unit, ONE distance constraint
///     g = |r_b + R_b p_b - r_a - R_a p_a| - L,
///   dg/dy = -u^T dg_ball/dy with u = (r_b + R_b p_b - r_a - R_a p_a) / |...| (the unit vector
///   from the leading to the towed end) and dg_ball/dy the ball rows above. The multiplier is
///   the rod's axial force with the sign of compression: the force on the leading unit is
///   -lambda u, so the rod force (tension positive) is -lambda. The rod leaves the towed unit's
///   yaw (and its pitch and roll) free relative to the bar: it is guided by its own tires (and
///   its steering, if steered).

#include <Eigen/Core>

#include "model/vehicle/chassis_kinematics.h"

namespace rig::model::combination {

using vehicle::Mat3;
using vehicle::Vec3;

enum class JointKind { kBall, kFifthWheel, kTowBar };

struct JointParams {
  JointKind kind = JointKind::kBall;
  /// The joint point in the leading unit's body frame, from its sprung-mass CG [m].
  Vec3 leading_point_m = Vec3::Zero();
  /// The same point in the trailing unit's body frame [m].
  Vec3 trailing_point_m = Vec3::Zero();
  /// Tow bar only: the rod length L between the two points [m].
  double length_m = 0;
  /// The force-coupled baseline only (eqs. 32-38): the joint as a stiff spring-damper.
  double stiffness_npm = 5e7;
  double damping_nspm = 1.5e4;
  double roll_stiffness_nmpr = 5e7;  ///< fifth wheel roll row (g_4 ~ relative roll angle)
  double roll_damping_nmspr = 1.5e4;
};

/// g and dg/dy of one joint; rows beyond size() are unused.
struct JointEvaluation {
  static constexpr int kMaxRows = 4;
  Eigen::Matrix<double, kMaxRows, 1> g = Eigen::Matrix<double, kMaxRows, 1>::Zero();
  Eigen::Matrix<double, kMaxRows, 6> dg_dya = Eigen::Matrix<double, kMaxRows, 6>::Zero();
  Eigen::Matrix<double, kMaxRows, 6> dg_dyb = Eigen::Matrix<double, kMaxRows, 6>::Zero();
};

class Joint {
 public:
  explicit Joint(const JointParams& params) : p_(params) {}

  /// Number of constraint rows (3 ball, 4 fifth wheel, 1 tow bar).
  [[nodiscard]] int size() const noexcept {
    return p_.kind == JointKind::kBall ? 3 : p_.kind == JointKind::kFifthWheel ? 4 : 1;
  }
  [[nodiscard]] const JointParams& params() const noexcept { return p_; }

  /// g(y_a, y_b) and its partial derivatives at the chassis coordinates of both units. No
  /// allocation.
  void evaluate(const Eigen::Ref<const Eigen::VectorXd>& y_a,
                const Eigen::Ref<const Eigen::VectorXd>& y_b, JointEvaluation& out) const noexcept;

  /// The joint force on the leading unit, road frame [N], from the joint's multipliers: the
  /// generalized constraint force on unit a is (dg/dy_a K_a^-1)^T lambda = [R_a^T lambda;
  /// p_a x R_a^T lambda], i.e. lambda_(0..2) is the force at the hitch point on unit a.
  [[nodiscard]] static Vec3 force_on_leading_n(const Eigen::Ref<const Eigen::VectorXd>& lambda) {
    return lambda.head<3>();
  }

  /// Tow bar: the rod force, tension positive [N], from the joint's multiplier (see above).
  [[nodiscard]] static double rod_force_n(double lambda) noexcept { return -lambda; }

 private:
  JointParams p_;
};

}  // namespace rig::model::combination
