#pragma once
/// @file
/// A free body of 6 DOF (a cab, an engine) on its mounts: a subsystem block (eq. 2) with the
/// chassis' coordinates y = [x, y, z (CG, road frame), yaw, pitch, roll] and speeds
/// z = [v, omega] (own axes; K as the chassis', chassis_kinematics.h), so that the only coupling
/// to the framework is the mounts' forces - no inertial coupling, and the framework's mass
/// matrix and arrowhead partition stay as they are. The sequential step (eq. 8) advances it
/// before the framework at the chassis state y_V(k); the framework then takes the mounts'
/// reactions from its newest state (chassis_load). Analytic partials of the mount springs,
/// dampers and stops on both sides.

#include <Eigen/Core>

#include "model/vehicle/free_body/mounted_body.h"

namespace rig::model::vehicle {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

class FreeBody final : public MountedBody<6> {
 public:
  /// Its coordinates are state.free_body_y[slot], free_body_z[slot]; the chassis' are
  /// state.framework_y, framework_z; the engine torque is work.engine_torque_nm.
  FreeBody(const FreeBodyParams& p, const road::Road& road, VehicleState& state,
           const VehicleWorkspace& work, int slot, const PredictedChassis& chassis);

  [[nodiscard]] Eigen::Index size() const noexcept override { return 6; }
  [[nodiscard]] Vector& coordinates() noexcept override;
  [[nodiscard]] Vector& speeds() noexcept override;
  void kinematics_inverse(const Vector& y, Matrix& k_inv) const noexcept override;
  void mass_matrix(const Vector& y, Matrix& m) const noexcept override;
  /// Gravity, w x m v, w x I w, the mounts, the engine torque's reaction (-T about the crank).
  void applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept override;
  /// The mounts' springs, stops and dampers: -J^T A^T K A J with J = [I, -[p]x] at each body
  /// point, A = R_c^T R_b; dq/dy = dq/ds K (s: displacements in body axes). Geometric terms of
  /// the mounts' preload and gravity stay explicit (method.md sec. 6).
  bool force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                       Matrix& dq_dz) const noexcept override;

  /// The reaction of the body on the chassis at pose `chassis` (the body's newest state):
  /// generalized force on the chassis' 6 speeds (force and moment about the CG, chassis axes).
  [[nodiscard]] Vec6 chassis_load(const RigidPose& chassis) const noexcept;
  /// Its partials in the chassis' speed space: d q_c / d s_c (multiply by K for dq/dy) and
  /// d q_c / d z_c.
  void chassis_jacobians(const RigidPose& chassis, Mat6& dq_ds, Mat6& dq_dz) const noexcept;
  /// The largest |d| - clearance over its mounts and axes (> 0: on its stops).
  [[nodiscard]] double beyond_stop_m(const RigidPose& chassis) const noexcept;

  [[nodiscard]] int mount_count() const noexcept { return mount_count_; }
  [[nodiscard]] const Mount& mount(int i) const noexcept {
    return mounts_[static_cast<std::size_t>(i)];
  }
  /// Mount i's force on the body (chassis axes) at the current states.
  [[nodiscard]] MountForce mount_force_now(int i) const noexcept;
  /// The drive torque reacting on the body (engine only; 0 for a cab) [N m].
  [[nodiscard]] double reaction_torque_nm() const noexcept;

 private:
  /// The mounts at the block's poses (the chassis predicted, the body at (y, z)), evaluated
  /// once per (y, z) and chassis state: applied_forces after force_jacobians reuses them.
  struct BodySide {
    RigidPose chassis, body;
    std::array<MountForce, kMaxMounts> forces{};
  };
  [[nodiscard]] const BodySide& body_side(const Vector& y, const Vector& z) const noexcept;
  /// The mounts at the chassis pose the framework asks with and the body's newest state, once
  /// per pair: chassis_load and chassis_jacobians share them.
  struct ChassisSide {
    RigidPose body;
    std::array<MountForce, kMaxMounts> forces{};
  };
  [[nodiscard]] const ChassisSide& chassis_side(const RigidPose& chassis) const noexcept;

  int mount_count_ = 0;
  std::array<Mount, kMaxMounts> mounts_{};
  Vec3 inertia_ = Vec3::Zero();
  Vec3 crank_axis_ = Vec3::UnitX();
  mutable InputKey<25> body_key_;  // per-step caches (input_key.h)
  mutable BodySide body_side_;
  mutable InputKey<30> chassis_side_key_;
  mutable ChassisSide chassis_side_;
};

/// The body's pose relative to the chassis: position of its CG from the design position and
/// roll, pitch, yaw of R_c^T R_b (chassis axes), and their rates.
struct RelativeMotion {
  Vec3 position_m = Vec3::Zero();
  Vec3 angles_rad = Vec3::Zero();  ///< roll, pitch, yaw
  Vec3 velocity_mps = Vec3::Zero();
  Vec3 rate_radps = Vec3::Zero();  ///< relative angular velocity, chassis axes
};
[[nodiscard]] RelativeMotion relative_motion(const RigidPose& chassis, const RigidPose& body,
                                             const Vec3& design_position_m) noexcept;

}  // namespace rig::model::vehicle
