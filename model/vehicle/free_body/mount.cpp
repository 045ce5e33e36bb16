#include "model/vehicle/free_body/mount.h"

#include <cmath>

namespace rig::model::vehicle {

Mount make_mount(const MountParams& m, const Vec3& body_position_m, double margin_m) noexcept {
  Mount out;
  out.body_point = Vec3(m.body_point_m[0], m.body_point_m[1], m.body_point_m[2]);
  out.chassis_point = Vec3(m.chassis_point_m[0], m.chassis_point_m[1], m.chassis_point_m[2]);
  out.design_offset = body_position_m + out.body_point - out.chassis_point;
  out.axes = body_to_road(m.orientation_rad[2], m.orientation_rad[1], m.orientation_rad[0]);
  for (int k = 0; k < 3; ++k) {
    const auto i = static_cast<std::size_t>(k);
    out.stiffness(k) = m.stiffness_npm[i];
    out.damping(k) = m.damping_nspm[i];
    out.clearance(k) = m.stop_clearance_m[i];
    out.stop_stiffness(k) = m.stop_stiffness_npm[i];
  }
  out.margin_m = margin_m;
  out.stiffness_matrix = chassis_axes_matrix(out, out.stiffness);
  out.damping_matrix = chassis_axes_matrix(out, out.damping);
  return out;
}

namespace {

/// The deflection in the mount's axes: the body point's displacement from the chassis point,
/// seen from the chassis, less the design offset.
Vec3 deflection_m(const Mount& m, const RigidPose& chassis, const Vec3& pb,
                  const Vec3& pc) noexcept {
  const Vec3 rel = chassis.rot.transpose() * (pb - pc);
  return m.axes.transpose() * (rel - m.design_offset);
}

}  // namespace

double mount_beyond_stop_m(const Mount& m, const RigidPose& chassis,
                           const RigidPose& body) noexcept {
  const Vec3 pb = body.position_m + body.rot * m.body_point;
  const Vec3 pc = chassis.position_m + chassis.rot * m.chassis_point;
  const Vec3 d = deflection_m(m, chassis, pb, pc);
  double beyond = -1;
  for (int k = 0; k < 3; ++k) {
    const double e = std::abs(d(k)) - m.clearance(k);
    if (e > beyond) beyond = e;
  }
  return beyond;
}

MountForce mount_force(const Mount& m, const RigidPose& chassis, const RigidPose& body) noexcept {
  // the two points and their velocities, road frame
  const Vec3 pb = body.position_m + body.rot * m.body_point;
  const Vec3 vb = body.rot * (body.velocity_mps + body.rate_radps.cross(m.body_point));
  const Vec3 pc = chassis.position_m + chassis.rot * m.chassis_point;
  const Vec3 vc = chassis.rot * (chassis.velocity_mps + chassis.rate_radps.cross(m.chassis_point));
  // relative position and its rate seen from the chassis (which turns at omega_c)
  const Vec3 rel = chassis.rot.transpose() * (pb - pc);
  const Vec3 rel_rate = chassis.rot.transpose() * (vb - vc) - chassis.rate_radps.cross(rel);
  const Vec3 d = m.axes.transpose() * (rel - m.design_offset);
  const Vec3 dd = m.axes.transpose() * rel_rate;
  MountForce out;
  out.deflection_m = d;
  Vec3 f;
  for (int k = 0; k < 3; ++k) {
    f(k) = -m.stiffness(k) * d(k) - m.damping(k) * dd(k);
    out.rate_stiffness(k) = m.stiffness(k);
    const double e = std::abs(d(k)) - m.clearance(k);
    if (e > out.beyond_stop_m) out.beyond_stop_m = e;
    if (e > 0) {
      f(k) -= std::copysign(m.stop_stiffness(k) * e * (1 + e / m.margin_m), d(k));
      out.rate_stiffness(k) += m.stop_stiffness(k) * (1 + 2 * e / m.margin_m);
    }
  }
  out.force_n = m.axes * f;
  return out;
}

}  // namespace rig::model::vehicle
