#pragma once
/// @file
/// Contact kinematics of one wheel on the road (model/road), as a function of the framework
/// state: contact point, tire axes, contact point velocity, tire penetration. The wheel centre
/// and its orientation come from the kinematics of eq. (29) (the framework). On today's plane
/// the road is asked directly; on any other road the contact is taken on the wheel's local road
/// plane of the step (local_road_plane.h), found once per step at y(k).

#include "model/road/road.h"
#include "model/vehicle/chassis_kinematics.h"
#include "model/vehicle/local_road_plane.h"

namespace rig::model::vehicle {

struct WheelContact {
  Vec3 lever_m;         ///< contact point relative to the CG, body axes (for J_P = [I, -[r]x, e_z])
  Vec3 ex, ey, normal;  ///< tire longitudinal, lateral and road normal, body axes
  Vec3 spin_axis;       ///< wheel spin axis, body axes
  double vx_mps = 0;    ///< contact point velocity along ex
  double vy_mps = 0;    ///< along ey
  double penetration_m = 0;  ///< r0 - wheel centre height above the road (> 0 in contact)
  double penetration_rate_mps = 0;
};

/// @param centre_m wheel centre relative to the CG (body axes); @param hub_velocity_mps its
/// velocity relative to the body from hub travel (the kinematics' tangent times the travel rate);
/// @param spin_axis the wheel's spin axis Rz(gamma) Rx(alpha) e_y (gamma, alpha of eq. 29; see
/// set_wheel_orientation). The contact point is the point of the road below the centre, along
/// the road's normal there.
inline WheelContact wheel_contact(const road::Road& road, const Mat3& r_body_to_road,
                                  const Vec3& cg_road_m, const Vec3& v_body, const Vec3& w_body,
                                  const Vec3& centre_m, const Vec3& hub_velocity_mps,
                                  const Vec3& spin_axis, double radius_unloaded_m) noexcept {
  WheelContact c;
  const double x = cg_road_m.x() + r_body_to_road.row(0).dot(centre_m);
  const double y = cg_road_m.y() + r_body_to_road.row(1).dot(centre_m);
  const double height = cg_road_m.z() + r_body_to_road.row(2).dot(centre_m) - road.height_m(x, y);
  c.normal = r_body_to_road.transpose() * road.normal(x, y);
  c.lever_m = centre_m - height * c.normal;
  c.spin_axis = spin_axis;
  c.ex = c.spin_axis.cross(c.normal).normalized();
  c.ey = c.normal.cross(c.ex);
  const Vec3 vp = v_body + w_body.cross(c.lever_m) + hub_velocity_mps;
  c.vx_mps = c.ex.dot(vp);
  c.vy_mps = c.ey.dot(vp);
  c.penetration_m = radius_unloaded_m - height;
  c.penetration_rate_mps = -c.normal.dot(vp);
  return c;
}

/// The same on the wheel's local road plane (road frame): the contact point is the foot of the
/// wheel centre on the plane, the penetration r0 minus the centre's distance from it.
inline WheelContact wheel_contact(const LocalRoadPlane& plane, const Mat3& r_body_to_road,
                                  const Vec3& cg_road_m, const Vec3& v_body, const Vec3& w_body,
                                  const Vec3& centre_m, const Vec3& hub_velocity_mps,
                                  const Vec3& spin_axis, double radius_unloaded_m) noexcept {
  WheelContact c;
  const Vec3 centre_road = cg_road_m + r_body_to_road * centre_m;
  const double height = (centre_road - plane.point_m).dot(plane.normal);
  c.normal = r_body_to_road.transpose() * plane.normal;
  c.lever_m = centre_m - height * c.normal;
  c.spin_axis = spin_axis;
  c.ex = c.spin_axis.cross(c.normal).normalized();
  c.ey = c.normal.cross(c.ex);
  const Vec3 vp = v_body + w_body.cross(c.lever_m) + hub_velocity_mps;
  c.vx_mps = c.ex.dot(vp);
  c.vy_mps = c.ey.dot(vp);
  c.penetration_m = radius_unloaded_m - height;
  c.penetration_rate_mps = -c.normal.dot(vp);
  return c;
}

}  // namespace rig::model::vehicle
