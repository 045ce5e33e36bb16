#pragma once
/// @file
/// The force of one mount (free_body_params.h) between the chassis and a free body, both rigid
/// bodies with y = [x, y, z (road frame), yaw, pitch, roll] and z = [v, omega] in their own axes
/// (chassis_kinematics.h), and its stiffness and damping in the mount's axes for the partials.

#include <Eigen/Core>

#include "model/vehicle/chassis_kinematics.h"
#include "model/vehicle/free_body/free_body_params.h"

namespace rig::model::vehicle {

/// Position, orientation and velocities of a rigid body (chassis or free body).
struct RigidPose {
  Mat3 rot = Mat3::Identity();  ///< body to road
  Vec3 position_m = Vec3::Zero();
  Vec3 velocity_mps = Vec3::Zero();  ///< body axes
  Vec3 rate_radps = Vec3::Zero();    ///< body axes
};

/// From coordinates [x, y, z, yaw, pitch, roll] and speeds [v, omega].
template <typename Y, typename Z>
[[nodiscard]] RigidPose rigid_pose(const Y& y, const Z& z) noexcept {
  RigidPose p;
  p.rot = body_to_road(y(3), y(4), y(5));
  p.position_m = Vec3(y(0), y(1), y(2));
  p.velocity_mps = Vec3(z(0), z(1), z(2));
  p.rate_radps = Vec3(z(3), z(4), z(5));
  return p;
}

/// The pose at y + dt K^-1 z (eq. 6: where the step evaluates q), speeds as they are.
template <typename Y, typename Z>
[[nodiscard]] RigidPose predicted_pose(const Y& y, const Z& z, double dt) noexcept {
  RigidPose p = rigid_pose(y, z);
  if (dt == 0.0) return p;
  const Vec3 angles =
      Vec3(y(3), y(4), y(5)) + dt * euler_rates_from_body_rates(y(4), y(5)) * p.rate_radps;
  p.position_m += dt * (p.rot * p.velocity_mps);
  p.rot = body_to_road(angles(0), angles(1), angles(2));
  return p;
}

/// A mount's constants in Eigen form (built once).
struct Mount {
  Vec3 body_point = Vec3::Zero();     ///< body axes
  Vec3 chassis_point = Vec3::Zero();  ///< chassis axes
  Vec3 design_offset = Vec3::Zero();  ///< chassis axes: body point - chassis point at design
  Mat3 axes = Mat3::Identity();       ///< mount axes in chassis axes (columns)
  Vec3 stiffness = Vec3::Zero(), damping = Vec3::Zero();
  Vec3 clearance = Vec3::Zero(), stop_stiffness = Vec3::Zero();
  double margin_m = 0.01;  ///< the buffer travel of the progressive stop
  /// The spring's and the damper's rates in chassis axes (chassis_axes_matrix; constant).
  Mat3 stiffness_matrix = Mat3::Zero(), damping_matrix = Mat3::Zero();
};

[[nodiscard]] Mount make_mount(const MountParams& m, const Vec3& body_position_m,
                               double margin_m) noexcept;

/// What a mount does at one pair of poses.
struct MountForce {
  Vec3 force_n = Vec3::Zero();         ///< on the body, chassis axes (the chassis gets -force)
  Vec3 deflection_m = Vec3::Zero();    ///< mount axes
  Vec3 rate_stiffness = Vec3::Zero();  ///< dF/dd per mount axis, with the stop's rate
  double beyond_stop_m = -1;  ///< the largest |d| - clearance over the axes (> 0: on its stop)
};

[[nodiscard]] MountForce mount_force(const Mount& m, const RigidPose& chassis,
                                     const RigidPose& body) noexcept;

/// mount_force(m, chassis, body).beyond_stop_m from the deflection alone (the same arithmetic,
/// no velocities, forces or rates): the fault check's stop check after every step.
[[nodiscard]] double mount_beyond_stop_m(const Mount& m, const RigidPose& chassis,
                                         const RigidPose& body) noexcept;

/// dF/dd of the mount in chassis axes: A diag(rate) A^T (A: the mount's axes).
[[nodiscard]] inline Mat3 chassis_axes_matrix(const Mount& m, const Vec3& diag) noexcept {
  return m.axes * diag.asDiagonal() * m.axes.transpose();
}

}  // namespace rig::model::vehicle
