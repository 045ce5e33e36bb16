#include "model/vehicle/free_body/free_bodies.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace rig::model::vehicle {
namespace {

Vec3 vec3(const std::array<double, 3>& a) noexcept { return {a[0], a[1], a[2]}; }

RigidPose body_pose(const VehicleState& s, int slot) noexcept {
  const auto k = static_cast<std::size_t>(slot);
  return rigid_pose(s.free_body_y[k], s.free_body_z[k]);
}

/// Coordinates and speeds of a body whose motion relative to `chassis` is `rel`.
void compose(const RigidPose& chassis, double chassis_yaw, const RelativeMotion& rel,
             const Vec3& design, const Mat3& relative_rot, Vec6& y, Vec6& z) noexcept {
  const Vec3 r = design + rel.position_m;
  const Mat3 rot = chassis.rot * relative_rot;
  y.head<3>() = chassis.position_m + chassis.rot * r;
  double yaw = std::atan2(rot(1, 0), rot(0, 0));
  yaw += 2 * std::numbers::pi * std::round((chassis_yaw - yaw) / (2 * std::numbers::pi));
  y(3) = yaw;
  y(4) = -std::asin(std::clamp(rot(2, 0), -1.0, 1.0));
  y(5) = std::atan2(rot(2, 1), rot(2, 2));
  const Vec3 v_road =
      chassis.rot * (chassis.velocity_mps + chassis.rate_radps.cross(r) + rel.velocity_mps);
  z.head<3>() = rot.transpose() * v_road;
  z.tail<3>() = relative_rot.transpose() * (chassis.rate_radps + rel.rate_radps);
}

}  // namespace

FreeBodies::FreeBodies(const VehicleParams& p, const road::Road& road, VehicleState& state,
                       const VehicleWorkspace& work)
    : chassis_(std::make_unique<PredictedChassis>(state, work)) {
  if (p.free_bodies.size() > kMaxFreeBodies)
    throw std::invalid_argument("vehicle: at most " + std::to_string(kMaxFreeBodies) +
                                " free bodies");
  for (const FreeBodyParams& b : p.free_bodies) {
    if (b.mounts.empty() || b.mounts.size() > kMaxMounts || !(b.mass_kg > 0))
      throw std::invalid_argument("vehicle: free body " + b.name + ": needs a mass > 0 and 1.." +
                                  std::to_string(kMaxMounts) + " mounts");
  }
  for (std::size_t i = 0; i < p.free_bodies.size(); ++i) {
    const FreeBodyParams& b = p.free_bodies[i];
    const int slot = static_cast<int>(i);
    if (b.kind == FreeBodyKind::kSeat) {
      seats_.push_back(std::make_unique<Seat>(b, road, state, work, slot, *chassis_));
      bodies_.push_back(nullptr);
      stages_.push_back(std::make_unique<solver::MechanicalStepper<1>>(*seats_.back()));
    } else {
      bodies_.push_back(std::make_unique<FreeBody>(b, road, state, work, slot, *chassis_));
      seats_.push_back(nullptr);
      stages_.push_back(std::make_unique<solver::MechanicalStepper<6>>(*bodies_.back()));
    }
  }
}

void FreeBodies::add_chassis_load(const RigidPose& chassis, Eigen::Ref<Vec6> q) const noexcept {
  for (std::size_t i = 0; i < stages_.size(); ++i)
    q += bodies_[i] ? bodies_[i]->chassis_load(chassis) : seats_[i]->chassis_load(chassis);
}

void FreeBodies::add_chassis_jacobians(const RigidPose& chassis, Mat6& dq_ds,
                                       Mat6& dq_dz) const noexcept {
  for (const auto& b : bodies_) {
    if (b) b->chassis_jacobians(chassis, dq_ds, dq_dz);
  }
}

double free_body_beyond_stop_m(const FreeBodyParams& b, int slot, const VehicleState& s,
                               const Mount* mounts) noexcept {
  const RigidPose chassis = rigid_pose(s.framework_y, s.framework_z);
  const auto k = static_cast<std::size_t>(slot);
  if (b.kind == FreeBodyKind::kSeat) {
    const Vec3 point = chassis.position_m + chassis.rot * vec3(b.position_m);
    const double clearance = b.mounts.empty() ? 0.0 : b.mounts.front().stop_clearance_m[2];
    return std::abs(s.seat_y[k](0) - point.z()) - clearance;
  }
  const RigidPose body = body_pose(s, slot);
  double beyond = -1e9;
  for (std::size_t i = 0; i < b.mounts.size() && i < kMaxMounts; ++i) {
    const double e = mounts ? mount_beyond_stop_m(mounts[i], chassis, body)
                            : mount_beyond_stop_m(
                                  make_mount(b.mounts[i], vec3(b.position_m), b.through_margin_m),
                                  chassis, body);
    beyond = std::max(beyond, e);
  }
  return beyond;
}

RelativeMotion free_body_motion(const FreeBodyParams& b, int slot, const VehicleState& s) noexcept {
  const RigidPose chassis = rigid_pose(s.framework_y, s.framework_z);
  const auto k = static_cast<std::size_t>(slot);
  if (b.kind == FreeBodyKind::kSeat) {
    const Vec3 p = vec3(b.position_m);
    const Vec3 point = chassis.position_m + chassis.rot * p;
    const Vec3 v = chassis.rot * (chassis.velocity_mps + chassis.rate_radps.cross(p));
    RelativeMotion m;
    m.position_m.z() = s.seat_y[k](0) - point.z();
    m.velocity_mps.z() = s.seat_z[k](0) - v.z();
    return m;
  }
  return relative_motion(chassis, body_pose(s, slot), vec3(b.position_m));
}

void place_free_bodies(const VehicleParams& p, VehicleState& s) noexcept {
  const RigidPose chassis = rigid_pose(s.framework_y, s.framework_z);
  for (std::size_t i = 0; i < p.free_bodies.size() && i < kMaxFreeBodies; ++i) {
    const FreeBodyParams& b = p.free_bodies[i];
    const Vec3 design = vec3(b.position_m);
    if (b.kind == FreeBodyKind::kSeat) {
      const Vec3 point = chassis.position_m + chassis.rot * design;
      const Vec3 v = chassis.rot * (chassis.velocity_mps + chassis.rate_radps.cross(design));
      s.seat_y[i](0) = point.z();
      s.seat_z[i](0) = v.z();
      continue;
    }
    compose(chassis, s.framework_y(3), RelativeMotion{}, design, Mat3::Identity(), s.free_body_y[i],
            s.free_body_z[i]);
  }
}

void carry_free_bodies(const VehicleParams& p, const Vec6& old_y, const Vec6& old_z,
                       VehicleState& s) noexcept {
  const RigidPose before = rigid_pose(old_y, old_z);
  const RigidPose after = rigid_pose(s.framework_y, s.framework_z);
  for (std::size_t i = 0; i < p.free_bodies.size() && i < kMaxFreeBodies; ++i) {
    const FreeBodyParams& b = p.free_bodies[i];
    const Vec3 design = vec3(b.position_m);
    if (b.kind == FreeBodyKind::kSeat) {
      const Vec3 p0 = before.position_m + before.rot * design;
      const Vec3 v0 = before.rot * (before.velocity_mps + before.rate_radps.cross(design));
      const Vec3 p1 = after.position_m + after.rot * design;
      const Vec3 v1 = after.rot * (after.velocity_mps + after.rate_radps.cross(design));
      s.seat_y[i](0) += p1.z() - p0.z();
      s.seat_z[i](0) += v1.z() - v0.z();
      continue;
    }
    const RigidPose body = rigid_pose(s.free_body_y[i], s.free_body_z[i]);
    const RelativeMotion rel = relative_motion(before, body, design);
    compose(after, s.framework_y(3), rel, design, before.rot.transpose() * body.rot,
            s.free_body_y[i], s.free_body_z[i]);
  }
}

void fill_free_body_report(const VehicleParams& p, const VehicleState& s,
                           ModelReport& report) noexcept {
  const int n = std::min(static_cast<int>(p.free_bodies.size()), kMaxFreeBodies);
  report.body_count = n;
  for (int i = 0; i < n; ++i) {
    const FreeBodyParams& b = p.free_bodies[static_cast<std::size_t>(i)];
    const RelativeMotion m = free_body_motion(b, i, s);
    FreeBodyReport& r = report.bodies[static_cast<std::size_t>(i)];
    for (int k = 0; k < 3; ++k) {
      const auto j = static_cast<std::size_t>(k);
      r.position_m[j] = m.position_m(k);
      r.orientation_rad[j] = m.angles_rad(k);
      r.velocity_mps[j] = m.velocity_mps(k);
      r.angular_velocity_radps[j] = m.rate_radps(k);
    }
    r.on_stop = free_body_beyond_stop_m(b, i, s) > 0 ? 1 : 0;
  }
}

}  // namespace rig::model::vehicle
